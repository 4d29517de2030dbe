// Seed 002's quality Q and image-driven steering (noise/steerable_noise.hpp): the elongation of the noise
// (sqrt of E (d n / d across)^2 / E (d n / d along)^2) grows with Q in 2D and 3D; analytic gradients against
// central differences with Q > 0 and with an image (the dG/dy of the B-spline); a uniform image steers as its
// constant direction does; an image whose left half points along x and right half along y steers each half its
// way; the weight sum stays positive; the refusals (Q outside 0..N, an image outside 2D or beside a direction).
#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "dfvn/field/dfvn_field.hpp"
#include "dfvn/noise/steerable_noise.hpp"

namespace dfvn {
namespace {

template <int N>
SteerSpec along_x(int quality) {
  SteerSpec spec;
  spec.direction.assign(N, 0.0);
  spec.direction[0] = 1.0;
  spec.quality = quality;
  return spec;
}

// sqrt(E g_across^2 / E g_along^2) of n_1 over random points (along = x, across = the other axes, per axis).
template <int N>
double elongation(const SteerableNoise<N>& noise, int points) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-30.0, 30.0);
  double along = 0.0, across = 0.0;
  for (int p = 0; p < points; ++p) {
    Vec<N> y;
    for (int j = 0; j < N; ++j) y[j] = u(rng);
    const Vec<N> g = noise.evaluate(y).gradient[0];
    along += g[0] * g[0];
    for (int j = 1; j < N; ++j) across += g[j] * g[j] / (N - 1);
  }
  return std::sqrt(across / along);
}

TEST(SteerQuality, ElongationGrowsWithQuality) {
  double previous = 0.0;
  for (int q = 0; q <= 2; ++q) {
    const SteerableNoise<2> noise(3, 0.0, along_x<2>(q));
    const double e = elongation(noise, 20000);
    EXPECT_GT(e, previous * 1.1) << "Q = " << q;
    previous = e;
  }
  previous = 0.0;
  for (int q = 0; q <= 2; ++q) {
    const SteerableNoise<3> noise(3, 0.0, along_x<3>(q));
    const double e = elongation(noise, 4000);
    EXPECT_GT(e, previous * 1.05) << "3D Q = " << q;
    previous = e;
  }
}

template <int N>
void expect_gradients(const SteerableNoise<N>& noise, double scale, double tolerance) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-scale, scale);
  constexpr double h = 1e-6;
  for (int p = 0; p < 200; ++p) {
    Vec<N> y;
    for (int j = 0; j < N; ++j) y[j] = u(rng);
    const auto s = noise.evaluate(y);
    for (int j = 0; j < N; ++j) {
      Vec<N> step = Vec<N>::Zero();
      step[j] = h;
      for (int i = 0; i < N - 1; ++i)
        EXPECT_NEAR(s.gradient[i][j], (noise.evaluate(y + step).value[i] - noise.evaluate(y - step).value[i]) / (2 * h), tolerance)
            << "function " << i << " axis " << j << " at " << y.transpose();
    }
    for (int i = 0; i < N - 1; ++i) EXPECT_GT(noise.weight_sum(i, y), 0.0);
  }
}

// A 16 x 16 direction grid: `left` on the columns x < 1/2, `right` on the others.
std::shared_ptr<const DirectionGrid> split_grid(const Vec<2>& left, const Vec<2>& right) {
  auto grid = std::make_shared<DirectionGrid>();
  grid->rows = grid->columns = 16;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j) {
      const Vec<2> u = (j < 8 ? left : right).normalized();
      grid->tensors.push_back({u[0] * u[0], u[0] * u[1], u[1] * u[1]});
    }
  return grid;
}

TEST(SteerQuality, AnalyticGradients) {
  expect_gradients(SteerableNoise<2>(2, 0.4, along_x<2>(2)), 20.0, 1e-6);
  expect_gradients(SteerableNoise<3>(2, 0.0, along_x<3>(1)), 20.0, 1e-6);
  SteerSpec image;
  image.image = split_grid(Vec<2>(1, 1), Vec<2>(1, -0.3));
  image.image_frequency = 1.0;
  image.quality = 1;
  const SteerableNoise<2> steered(2, 0.0, image);
  expect_gradients(steered, 8.0, 1e-6);  // the image spans y in [0, s): around it, on it and beyond
}

TEST(SteerQuality, ImageSteersItsWay) {
  // A uniform image along x: the field of the constant direction (1, 0), to rounding.
  FieldOptions constant{NoiseBasis::steerable, 3.0};
  constant.transform.steer = along_x<2>(0);
  FieldOptions uniform = constant;
  uniform.transform.steer = SteerSpec{};
  uniform.transform.steer.image = split_grid(Vec<2>(1, 0), Vec<2>(1, 0));
  const DfvnField<2> a(4, constant), b(4, uniform);
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int p = 0; p < 200; ++p) {
    const Vec<2> x(u(rng), u(rng));
    EXPECT_LT((a.velocity(x) - b.velocity(x)).norm(), 1e-12 * (1.0 + a.velocity(x).norm()));
  }
  // Left half along x, right half along y: c = (df/dy, -df/dx) runs along each half's direction, so E c_x^2 / E c_y^2
  // is large on the left and small on the right.
  FieldOptions split = uniform;
  split.transform.steer.image = split_grid(Vec<2>(1, 0), Vec<2>(0, 1));
  const DfvnField<2> field(4, split);
  double left_x = 0.0, left_y = 0.0, right_x = 0.0, right_y = 0.0;
  for (int p = 0; p < 20000; ++p) {
    const Vec<2> x(u(rng), u(rng));
    const Vec<2> c = field.velocity(x);
    if (x[0] < 0.35) left_x += c[0] * c[0], left_y += c[1] * c[1];
    if (x[0] > 0.65) right_x += c[0] * c[0], right_y += c[1] * c[1];
  }
  EXPECT_GT(left_x / left_y, 2.0);
  EXPECT_LT(right_x / right_y, 0.5);
}

TEST(SteerQuality, Refusals) {
  SteerSpec spec = along_x<2>(3);
  EXPECT_THROW(check_steer_spec(spec, 2), std::invalid_argument);  // Q > N
  spec.quality = -1;
  EXPECT_THROW(check_steer_spec(spec, 2), std::invalid_argument);
  SteerSpec image;
  image.image = split_grid(Vec<2>(1, 0), Vec<2>(0, 1));
  EXPECT_THROW(check_steer_spec(image, 3), std::invalid_argument);  // 2D only
  image.direction = {1.0, 0.0};
  EXPECT_THROW(check_steer_spec(image, 2), std::invalid_argument);  // two direction fields
}

}  // namespace
}  // namespace dfvn

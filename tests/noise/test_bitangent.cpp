// Bitangent noise (seeds/004) and the simplex-separate basis: the document's 3D and 4D forms as written,
// the simplex-separate DFVN field as the 3D form scaled, the fused simplex basis's first function as S,
// the divergence targets on 10^5 uniform random points for the 3D field of every basis (bitangent noise's
// cross of two gradients) and for the 4D form at fixed time, and the envelope each construction shares.
#include "dfvn/noise/simplex_separate.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "dfvn/field/dfvn_field.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

constexpr std::uint64_t kSeed = 31;
constexpr int kPoints = 100000;

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}

// The functions of simplex-separate are S at the offsets: n_i(x) = n_0(x + o_i), with 3D's and 4D's o_1
// the document's vectors, and n_0 the first function of the fused simplex basis (the same S).
TEST(SimplexSeparate, FunctionsAreOneSimplexNoiseAtTheDocumentsOffsets) {
  EXPECT_EQ(simplex_separate_offset<3>(1), Vec<3>(31.416, 47.853, 12.679));
  EXPECT_EQ(simplex_separate_offset<4>(1), Vec<4>(31.416, 47.853, 12.679, 113.408));
  EXPECT_EQ(simplex_separate_offset<8>(0), Vec<8>::Zero());
  const SimplexSeparateNoiseFunctions<5> separate(kSeed);
  const SimplexNoise<5> fused(kSeed);
  for (std::uint64_t i = 0; i < 200; ++i) {
    const Vec<5> x = testing::random_point<5>(kSeed, i);
    const auto s = separate.evaluate(x);
    EXPECT_EQ(s.value[0], fused.evaluate_all(x).value[0]);
    EXPECT_EQ(s.gradient[0], fused.evaluate_all(x).gradient[0]);
    for (int m = 1; m < 4; ++m) {
      const auto shifted = separate.evaluate(Vec<5>(x + simplex_separate_offset<5>(m)));
      EXPECT_EQ(s.value[m], shifted.value[0]);
      EXPECT_EQ(s.gradient[m], shifted.gradient[0]);
    }
  }
}

// The simplex-separate DFVN field in 3D is the document's BitangentNoise3D_ref at s x, times A^2.
TEST(Bitangent, SeparateFieldIsTheDocumentsThreeDimensionalForm) {
  const DfvnField<3> field(kSeed, FieldOptions{NoiseBasis::simplex_separate, 1.7});
  const SimplexNoise<3> noise(kSeed);
  const double a2 = field.amplitude() * field.amplitude();
  for (std::uint64_t i = 0; i < 1000; ++i) {
    const Vec<3> x = testing::random_point<3>(kSeed + 1, i);
    const Vec<3> expected = a2 * bitangent_noise_3d(noise, Vec<3>(field.scale() * x));
    const Vec<3> c = field.velocity(x);
    EXPECT_LE((c - expected).norm(), 1e-12 * (1.0 + expected.norm())) << "x = " << x.transpose();
  }
}

// The fused simplex DFVN field in 3D is the document's optimised BitangentNoise3D at s x, times A^2.
TEST(Bitangent, FusedFieldIsTheDocumentsOptimisedForm) {
  const DfvnField<3> field(kSeed, FieldOptions{NoiseBasis::simplex, 0.6});
  const SimplexNoise<3> noise(kSeed);
  const double a2 = field.amplitude() * field.amplitude();
  for (std::uint64_t i = 0; i < 1000; ++i) {
    const Vec<3> x = testing::random_point<3>(kSeed + 5, i);
    const Vec<3> expected = a2 * bitangent_noise_3d_fused(noise, Vec<3>(field.scale() * x));
    EXPECT_LE((field.velocity(x) - expected).norm(), 1e-12 * (1.0 + expected.norm())) << "x = " << x.transpose();
  }
}

// |div c| / |Dc| by central differences of `velocity` (h = 1e-5 cycles of the noise) on 10^5 uniform
// random points of [0, 1000 cycles]^3: median and p95.
struct Divergence {
  double median, p95;
  std::size_t moving;
};
Divergence divergence_on_random_points(const std::function<Vec<3>(const Vec<3>&)>& velocity, double cycle, std::uint64_t seed) {
  const double h = 1e-5 * cycle;
  std::vector<double> ratios;
  ratios.reserve(kPoints);
  for (int i = 0; i < kPoints; ++i) {
    const Vec<3> x = testing::random_point<3>(seed, static_cast<std::uint64_t>(i), 0.0, 1000.0 * cycle);
    double divergence = 0.0, jacobian2 = 0.0;
    for (int j = 0; j < 3; ++j) {
      Vec<3> xp = x, xm = x;
      xp[j] += h;
      xm[j] -= h;
      const Vec<3> column = (velocity(xp) - velocity(xm)) / (2.0 * h);
      divergence += column[j];
      jacobian2 += column.squaredNorm();
    }
    if (jacobian2 > 0.0) ratios.push_back(std::abs(divergence) / std::sqrt(jacobian2));
  }
  return {quantile(ratios, 0.5), quantile(ratios, 0.95), ratios.size()};
}

// Bitangent noise with every basis: the 3D DFVN field (cross of two gradients; simplex is the
// document's optimised one-traversal form, simplex-separate its reference form), and the document's
// 4D form at a fixed time w (divergence in x, y, z only).
TEST(Bitangent, DivergenceTargetsOnUniformRandomPoints) {
  for (NoiseBasis basis : kAllNoiseBases) {
    const DfvnField<3> field(kSeed, FieldOptions{basis, 1.0});
    const Divergence d = divergence_on_random_points([&](const Vec<3>& x) { return field.velocity(x); }, 1.0, kSeed + 2);
    std::printf("bitangent 3D %s: |div c|/|Dc| median %.3g p95 %.3g on %zu points\n", to_string(basis).data(), d.median,
                d.p95, d.moving);
    EXPECT_GE(d.moving, static_cast<std::size_t>(kPoints * 0.99)) << to_string(basis);
    EXPECT_LE(d.median, 1e-8) << to_string(basis);
    EXPECT_LE(d.p95, 1e-6) << to_string(basis);
  }
  const SimplexNoise<4> noise(kSeed);
  const double cycle = 2.0 * 3.14159265358979323846 / simplex_wavenumber(4);
  for (const bool fused : {false, true})
  for (double w : {0.0, 12.5}) {
    const Divergence d = divergence_on_random_points(
        [&](const Vec<3>& x) {
          const Vec<4> p(x[0], x[1], x[2], w);
          return fused ? bitangent_noise_4d_fused(noise, p) : bitangent_noise_4d(noise, p);
        },
        cycle, kSeed + 3);
    std::printf("bitangent 4D (%s) at w = %g: |div c|/|Dc| median %.3g p95 %.3g on %zu points\n", fused ? "fused" : "reference", w,
                d.median, d.p95, d.moving);
    EXPECT_GE(d.moving, static_cast<std::size_t>(kPoints * 0.9));
    EXPECT_LE(d.median, 1e-8);
    EXPECT_LE(d.p95, 1e-6);
  }
}

// The 4D form moves with w and is not the 3D form: its gradients are the xyz parts of 4D gradients.
TEST(Bitangent, FourDimensionalFormChangesWithTime) {
  const SimplexNoise<4> noise(kSeed);
  const Vec<4> p(0.3, 1.1, -2.4, 0.0), q(0.3, 1.1, -2.4, 0.05);
  const Vec<3> a = bitangent_noise_4d(noise, p), b = bitangent_noise_4d(noise, q);
  EXPECT_GT(a.norm(), 0.0);
  EXPECT_GT((a - b).norm(), 0.0);
  EXPECT_LT((a - b).norm(), a.norm());  // continuous: a small step in w, a small change
}

// What separates the two causes of the fused basis's collapse: in the fused traversal every function
// shares one radial envelope, so the sizes of their gradients are correlated (3D: r ~ 0.5); the
// separate traversals see the envelope at points o_1 apart, and the correlation is the envelope's
// autocorrelation at that lag, much smaller (README "Two causes of simplex's collapse").
TEST(Bitangent, SeparateTraversalsDoNotShareTheEnvelope) {
  auto gradient_size_correlation = [](NoiseBasis basis) {
    const auto noise = make_noise_functions<3>(basis, kSeed);
    const int n = 40000;
    std::vector<double> a(n), b(n);
    for (int i = 0; i < n; ++i) {
      const auto s = noise->evaluate(testing::random_point<3>(kSeed + 4, static_cast<std::uint64_t>(i), 0.0, 500.0));
      a[i] = s.gradient[0].squaredNorm();
      b[i] = s.gradient[1].squaredNorm();
    }
    double ma = 0.0, mb = 0.0;
    for (int i = 0; i < n; ++i) ma += a[i] / n, mb += b[i] / n;
    double cov = 0.0, va = 0.0, vb = 0.0;
    for (int i = 0; i < n; ++i) cov += (a[i] - ma) * (b[i] - mb), va += (a[i] - ma) * (a[i] - ma), vb += (b[i] - mb) * (b[i] - mb);
    return cov / std::sqrt(va * vb);
  };
  const double fused = gradient_size_correlation(NoiseBasis::simplex);
  const double separate = gradient_size_correlation(NoiseBasis::simplex_separate);
  std::printf("|grad n_1|^2 vs |grad n_2|^2 correlation in 3D: fused %.3f, separate %.3f\n", fused, separate);
  EXPECT_GT(fused, 0.3);
  EXPECT_LT(std::abs(separate), 0.1);
}

}  // namespace
}  // namespace dfvn

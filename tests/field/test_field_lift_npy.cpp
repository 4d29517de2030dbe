// --lift npy:FILE (field/field_transform.hpp): a height field from a 2D .npy array over the unit square,
// interpolated by a tensor cubic B-spline. Checked here:
// - the spline passes through every element (1e-12) at x = j / (columns - 1), y = i / (rows - 1);
// - its gradient against central differences, inside the square and beyond it (h is defined everywhere);
// - C2: the second derivative's central differences agree on both sides of a knot line;
// - the derivation: the xy-projection of grad F x grad(z - h) equals the lifted field's c (1e-12);
// - the 2D divergence on 10^5 random points of the unit square: median <= 1e-8, p95 <= 1e-6 relative,
//   every basis (as the plane and bump lifts of test_field_lift);
// - bad files (NaN, wrong ndim, wrong dtype, too small, truncated, missing) are refused with one line.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "dfvn/field/diagnose.hpp"
#include "dfvn/field/dfvn_field.hpp"
#include "lift_projection.hpp"
#include "test_support.hpp"

namespace dfvn {
namespace {

// The bytes of an .npy file (format 1.0) with this dtype, shape text and raw data.
std::string npy_bytes(const std::string& descr, const std::string& shape, const std::string& data) {
  std::string header = fmt::format("{{'descr': '{}', 'fortran_order': False, 'shape': ({}), }}", descr, shape);
  header.append((64 - (10 + header.size() + 1) % 64) % 64, ' ');
  header += '\n';
  std::string out("\x93NUMPY\x01\x00", 8);
  out += static_cast<char>(header.size() & 0xFF);
  out += static_cast<char>(header.size() >> 8);
  return out + header + data;
}

std::string doubles(const std::vector<double>& values) {
  std::string out(values.size() * 8, '\0');
  std::memcpy(out.data(), values.data(), out.size());
  return out;
}

class NpyLift : public ::testing::Test {
 protected:
  static constexpr int kRows = 7, kColumns = 9;
  std::filesystem::path dir = std::filesystem::temp_directory_path() / fmt::format("dfvn_npy_lift_{}", ::getpid());
  std::vector<double> values;
  std::string path;

  void SetUp() override {
    std::filesystem::create_directories(dir);
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> uniform(-0.3, 0.3);
    for (int k = 0; k < kRows * kColumns; ++k) values.push_back(uniform(random));
    path = write("heights.npy", npy_bytes("<f8", fmt::format("{}, {}", kRows, kColumns), doubles(values)));
  }
  void TearDown() override { std::filesystem::remove_all(dir); }

  std::string write(const std::string& name, const std::string& bytes) const {
    const std::string file = (dir / name).string();
    std::ofstream(file, std::ios::binary) << bytes;
    return file;
  }
};

TEST_F(NpyLift, SplinePassesThroughEveryElement) {
  const LiftSpec spec = parse_lift("npy:" + path);
  const auto h = make_height_field(spec);
  double worst = 0.0;
  for (int i = 0; i < kRows; ++i)
    for (int j = 0; j < kColumns; ++j) {
      Vec<2> g;
      const double value = h->height(Vec<2>(static_cast<double>(j) / (kColumns - 1), static_cast<double>(i) / (kRows - 1)), g);
      worst = std::max(worst, std::abs(value - values[static_cast<std::size_t>(i) * kColumns + j]));
    }
  std::printf("largest |h(grid point) - element| %.3g\n", worst);
  EXPECT_LE(worst, 1e-12);
}

TEST_F(NpyLift, GradientMatchesCentralDifferencesAndIsC2) {
  const auto h = make_height_field(parse_lift("npy:" + path));
  double worst = 0.0;
  for (std::uint64_t k = 0; k < 5000; ++k) {
    const Vec<2> x = testing::random_point<2>(3, k, -0.7, 1.7);  // inside the square and beyond it
    Vec<2> g, unused;
    h->height(x, g);
    const double e = 1e-6;
    const Vec<2> fd((h->height(x + Vec<2>(e, 0), unused) - h->height(x - Vec<2>(e, 0), unused)) / (2 * e),
                    (h->height(x + Vec<2>(0, e), unused) - h->height(x - Vec<2>(0, e), unused)) / (2 * e));
    worst = std::max(worst, (fd - g).norm());
  }
  std::printf("largest |grad h - central difference| %.3g\n", worst);
  EXPECT_LE(worst, 1e-7);
  // Across the knot line x = 3 / 8: h_xx from the gradient's differences just left and just right of it.
  double jump = 0.0, scale = 0.0;
  for (double y : {0.1, 0.37, 0.8}) {
    const double knot = 3.0 / (kColumns - 1), d = 1e-5, e = 1e-7;
    Vec<2> a, b;
    auto hxx = [&](double x) {
      h->height(Vec<2>(x + e, y), a);
      h->height(Vec<2>(x - e, y), b);
      return (a[0] - b[0]) / (2 * e);
    };
    jump = std::max(jump, std::abs(hxx(knot - d) - hxx(knot + d)));
    scale = std::max(scale, std::abs(hxx(knot - d)));
  }
  std::printf("h_xx across a knot: jump %.3g against |h_xx| %.3g\n", jump, scale);
  EXPECT_LE(jump, 1e-3 * std::max(1.0, scale));
}

TEST_F(NpyLift, ProjectedThreeDimensionalFieldIsTheLiftedOne) {
  for (const NoiseBasis basis : kAllNoiseBases) {
    FieldOptions options{basis, 3.0};
    options.transform.lift = parse_lift("npy:" + path);
    const double worst = testing::largest_lift_projection_error(basis, options, -0.2, 1.2);
    EXPECT_LE(worst, 1e-12) << to_string(basis);
  }
}

TEST_F(NpyLift, TwoDimensionalDivergenceOnRandomPoints) {
  for (const NoiseBasis basis : kAllNoiseBases) {
    DiagnosisOptions options;
    options.dimension = 2;
    options.points = 100000;
    options.periods = 3.0;  // at 3 cycles per unit length: the points fill the unit square, the array's
    options.field = FieldOptions{basis, 3.0};
    options.field.transform.lift = parse_lift("npy:" + path);
    const FieldDiagnosis d = diagnose_field(options);
    std::printf("%s npy: RMS %.4f, div median %.2g, p95 %.2g, max %.2g\n", std::string(to_string(basis)).c_str(), d.rms_speed,
                d.divergence_median, d.divergence_p95, d.divergence_max);
    EXPECT_LE(d.divergence_median, 1e-8) << to_string(basis);
    EXPECT_LE(d.divergence_p95, 1e-6) << to_string(basis);
  }
}

TEST_F(NpyLift, BadFilesAreRefusedWithOneLine) {
  std::vector<double> with_nan = values;
  with_nan[10] = std::nan("");
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"nan.npy", npy_bytes("<f8", "7, 9", doubles(with_nan))},
      {"ndim1.npy", npy_bytes("<f8", "63,", doubles(values))},
      {"ndim3.npy", npy_bytes("<f8", "7, 3, 3", doubles(values))},
      {"int.npy", npy_bytes("<i8", "7, 9", doubles(values))},
      {"one_row.npy", npy_bytes("<f8", "1, 63", doubles(values))},
      {"short.npy", npy_bytes("<f8", "7, 9", doubles(values).substr(8))},
      {"text.npy", "0.1,0.2\n0.3,0.4\n"},
  };
  for (const auto& [name, bytes] : bad) {
    const std::string file = write(name, bytes);
    try {
      parse_lift("npy:" + file);
      ADD_FAILURE() << name << " was accepted";
    } catch (const std::invalid_argument& e) {
      const std::string message = e.what();
      std::printf("%s: %s\n", name.c_str(), message.c_str());
      EXPECT_EQ(message.find('\n'), std::string::npos) << name;
      EXPECT_NE(message.find("--lift npy:"), std::string::npos) << name;
    }
  }
  EXPECT_THROW(parse_lift("npy:" + (dir / "missing.npy").string()), std::invalid_argument);
  EXPECT_THROW(parse_lift("npy:"), std::invalid_argument);
}

}  // namespace
}  // namespace dfvn

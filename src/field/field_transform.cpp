#include "dfvn/field/field_transform.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/direction.hpp"
#include "dfvn/core/message_text.hpp"
#include "dfvn/io/csv.hpp"
#include "dfvn/io/png.hpp"
#include "dfvn/io/point_reader.hpp"

namespace dfvn {

namespace {

// Comma-separated finite reals, the whole text; throws naming `what`.
std::vector<double> parse_reals(std::string_view text, std::string_view what) {
  std::vector<double> values;
  std::size_t at = 0;
  while (true) {
    const std::size_t comma = text.find(',', at);
    const std::string_view item = text.substr(at, comma == std::string_view::npos ? std::string_view::npos : comma - at);
    double value = 0.0;
    const char* begin = item.data();
    if (!item.empty() && item.front() == '+') ++begin;
    const auto [ptr, error] = std::from_chars(begin, item.data() + item.size(), value);
    if (item.empty() || error != std::errc{} || ptr != item.data() + item.size() || !std::isfinite(value))
      throw std::invalid_argument(
          fmt::format("{}: {} is not a finite real number", what, quote_for_message(std::string(item))));
    values.push_back(value);
    if (comma == std::string_view::npos) return values;
    at = comma + 1;
  }
}

class PlaneHeight final : public HeightField {
 public:
  PlaneHeight(double sx, double sy) : slope_(sx, sy) {}
  double height(const Vec<2>& x, Vec<2>& gradient) const override {
    gradient = slope_;
    return slope_.dot(x);
  }

 private:
  Vec<2> slope_;
};

class BumpHeight final : public HeightField {
 public:
  // On the plane SX x + SY y (0 without it: the bump alone, bit for bit as before the plane existed).
  BumpHeight(double h, double r, double cx, double cy, double sx = 0.0, double sy = 0.0)
      : height_(h), radius_(r), centre_(cx, cy), slope_(sx, sy) {}
  double height(const Vec<2>& x, Vec<2>& gradient) const override {
    const Vec<2> d = (x - centre_) / radius_;
    const double r2 = d.squaredNorm();
    const bool plane = slope_[0] != 0.0 || slope_[1] != 0.0;
    if (!(r2 < 1.0)) {
      gradient = slope_;
      return plane ? slope_.dot(x) : 0.0;
    }
    const double q = 1.0 - r2;  // h = H q^3, grad h = H 3 q^2 (-2 d / R)
    gradient = (-6.0 * height_ * q * q / radius_) * d;
    if (!plane) return height_ * q * q * q;
    gradient += slope_;
    return height_ * q * q * q + slope_.dot(x);
  }

 private:
  double height_;
  double radius_;
  Vec<2> centre_;
  Vec<2> slope_;
};

// The interpolating tensor cubic B-spline of a height grid (LiftSpec::Kind::npy, field_transform.hpp):
// control points c with (c[k-1] + 4 c[k] + c[k+1]) / 6 = v[k] along each axis, c[-1] = c[0] and c[n] =
// c[n-1] (the border's control point repeated, which is also how the spline continues beyond the grid).
// The uniform cubic B-spline is C2 whatever its control points, so h is C2 everywhere; it passes through
// every grid value and is constant (c at the nearest corner or edge) from two grid spacings beyond.
class SplineHeight final : public HeightField {
 public:
  explicit SplineHeight(const HeightGrid& grid) : rows_(grid.rows), columns_(grid.columns), control_(grid.values) {
    std::vector<double> line;
    for (int i = 0; i < rows_; ++i) {  // along x, in each row
      line.assign(control_.begin() + static_cast<std::ptrdiff_t>(i) * columns_,
                  control_.begin() + static_cast<std::ptrdiff_t>(i + 1) * columns_);
      prefilter(line);
      std::copy(line.begin(), line.end(), control_.begin() + static_cast<std::ptrdiff_t>(i) * columns_);
    }
    line.resize(rows_);
    for (int j = 0; j < columns_; ++j) {  // along y, in each column
      for (int i = 0; i < rows_; ++i) line[i] = control_[static_cast<std::size_t>(i) * columns_ + j];
      prefilter(line);
      for (int i = 0; i < rows_; ++i) control_[static_cast<std::size_t>(i) * columns_ + j] = line[i];
    }
  }

  double height(const Vec<2>& x, Vec<2>& gradient) const override {
    // Grid coordinates: column j at x = j / (columns - 1), row i at y = i / (rows - 1). Beyond two
    // spacings outside, every control point read is the border's: clamping there changes nothing.
    const double gx = std::clamp(x[0] * (columns_ - 1), -2.0, columns_ + 1.0);
    const double gy = std::clamp(x[1] * (rows_ - 1), -2.0, rows_ + 1.0);
    const double fx = std::floor(gx), fy = std::floor(gy);
    double wx[4], dx[4], wy[4], dy[4];
    weights(gx - fx, wx, dx);
    weights(gy - fy, wy, dy);
    const int j0 = static_cast<int>(fx) - 1, i0 = static_cast<int>(fy) - 1;
    double h = 0.0, hx = 0.0, hy = 0.0;
    for (int a = 0; a < 4; ++a) {
      const int i = std::clamp(i0 + a, 0, rows_ - 1);
      double row = 0.0, row_dx = 0.0;
      for (int b = 0; b < 4; ++b) {
        const double c = control_[static_cast<std::size_t>(i) * columns_ + std::clamp(j0 + b, 0, columns_ - 1)];
        row += wx[b] * c;
        row_dx += dx[b] * c;
      }
      h += wy[a] * row;
      hx += wy[a] * row_dx;
      hy += dy[a] * row;
    }
    gradient = Vec<2>(hx * (columns_ - 1), hy * (rows_ - 1));
    return h;
  }

  // A bound on |dh/dx| and |dh/dy|: along an axis the spline's derivative is a convex combination of its
  // control points' differences times the cells per unit length. Infinite when a control point is not
  // finite (heights near the largest double).
  double max_slope() const {
    double steepest = 0.0;
    for (int i = 0; i < rows_; ++i)
      for (int j = 0; j < columns_; ++j) {
        const double c = control_[static_cast<std::size_t>(i) * columns_ + j];
        if (!std::isfinite(c)) return std::numeric_limits<double>::infinity();
        if (j + 1 < columns_)
          steepest = std::max(steepest, std::abs(control_[static_cast<std::size_t>(i) * columns_ + j + 1] - c) * (columns_ - 1));
        if (i + 1 < rows_)
          steepest = std::max(steepest, std::abs(control_[static_cast<std::size_t>(i + 1) * columns_ + j] - c) * (rows_ - 1));
      }
    return steepest;
  }

 private:
  // The uniform cubic B-spline's four weights at u in [0, 1) and their derivatives.
  static void weights(double u, double w[4], double d[4]) {
    const double v = 1.0 - u, u2 = u * u, u3 = u2 * u;
    w[0] = v * v * v / 6.0;
    w[1] = (3.0 * u3 - 6.0 * u2 + 4.0) / 6.0;
    w[2] = (-3.0 * u3 + 3.0 * u2 + 3.0 * u + 1.0) / 6.0;
    w[3] = u3 / 6.0;
    d[0] = -0.5 * v * v;
    d[1] = 1.5 * u2 - 2.0 * u;
    d[2] = -1.5 * u2 + u + 0.5;
    d[3] = 0.5 * u2;
  }
  // Solves (c[k-1] + 4 c[k] + c[k+1]) / 6 = v[k] with c[-1] = c[0], c[n] = c[n-1] in place (Thomas's
  // algorithm; the matrix is strictly diagonally dominant, so no pivoting is needed).
  static void prefilter(std::vector<double>& v) {
    const std::size_t n = v.size();
    std::vector<double> upper(n);
    auto diagonal = [n](std::size_t k) { return (k == 0 || k + 1 == n) ? 5.0 / 6.0 : 4.0 / 6.0; };
    constexpr double off = 1.0 / 6.0;
    double pivot = diagonal(0);
    upper[0] = off / pivot;
    v[0] /= pivot;
    for (std::size_t k = 1; k < n; ++k) {
      pivot = diagonal(k) - off * upper[k - 1];
      upper[k] = off / pivot;
      v[k] = (v[k] - off * v[k - 1]) / pivot;
    }
    for (std::size_t k = n - 1; k-- > 0;) v[k] -= upper[k] * v[k + 1];
  }

  int rows_, columns_;
  std::vector<double> control_;
};

// The steepest |dh/dx_j| of a lift's height (a bound for npy: its spline's control points' largest
// difference along an axis times the cells per unit length, since the spline's derivative is a convex
// combination of those differences).
double lift_max_slope(const LiftSpec& lift) {
  switch (lift.kind) {
    case LiftSpec::Kind::plane: return std::max(std::abs(lift.parameters[0]), std::abs(lift.parameters[1]));
    case LiftSpec::Kind::bump:  // the hill's steepest slope, plus the plane's it may sit on (an upper bound then)
      return 96.0 / (25.0 * std::sqrt(5.0)) * (std::abs(lift.parameters[0]) / lift.parameters[1]) +
             (lift.parameters.size() == 6 ? std::max(std::abs(lift.parameters[4]), std::abs(lift.parameters[5])) : 0.0);
    case LiftSpec::Kind::npy: return lift.grid ? lift.grid->max_slope : 0.0;
    case LiftSpec::Kind::none: break;
  }
  return 0.0;
}

}  // namespace

void NoiseTransform::validate() const {
  if (!stretch_direction.empty()) {
    for (double v : stretch_direction)
      if (!std::isfinite(v)) throw std::invalid_argument("--stretch: the direction must be finite");
    if (!is_direction(stretch_direction)) throw std::invalid_argument("--stretch: the direction must not be zero");
    if (!(stretch_factor >= kMinStretch && stretch_factor <= kMaxStretch))
      throw std::invalid_argument(
          fmt::format("--stretch: the factor S must be in [1e-6, 1e6] (S > 0), got {}", stretch_factor));
  }
  if (time && !std::isfinite(*time)) throw std::invalid_argument(fmt::format("--time must be a finite number, got {}", *time));
  if (lift.active()) {
    if (time)
      throw std::invalid_argument("--lift and --time both read the noise's third dimension: give one of them");
    for (double p : lift.parameters)
      if (!std::isfinite(p)) throw std::invalid_argument("--lift: every parameter must be finite");
    if (!(std::abs(lift.ramp) <= kMaxLiftRamp))
      throw std::invalid_argument(fmt::format("--lift-ramp must be in [-2^50, 2^50] = [{:g}, {:g}], got {:g}",
                                              -kMaxLiftRamp, kMaxLiftRamp, lift.ramp));
    if (lift.kind == LiftSpec::Kind::plane && lift.parameters.size() != 2)
      throw std::invalid_argument("--lift plane:SX,SY takes two slopes");
    if (lift.kind == LiftSpec::Kind::bump && lift.parameters.size() != 4 && lift.parameters.size() != 6)
      throw std::invalid_argument(
          "--lift bump:H,R[,CX,CY[,SX,SY]] takes a height, a radius and optionally a centre and the slopes of a plane under it");
    if (lift.kind == LiftSpec::Kind::npy && (!lift.grid || lift.grid->rows < 2 || lift.grid->columns < 2))
      throw std::invalid_argument("--lift npy:FILE: the height grid needs at least 2 rows and 2 columns");
    if (lift.kind == LiftSpec::Kind::bump && !(lift.parameters[1] > 0.0))
      throw std::invalid_argument(fmt::format("--lift bump: the radius R must be positive, got {:g}", lift.parameters[1]));
    const double slope = lift_max_slope(lift);
    if (!(slope <= kMaxLiftSlope))
      throw std::invalid_argument(fmt::format(
          "--lift {}: the height's steepest slope is {}, above 2^50 = {:g} (the noise would vanish below its rounding)",
          lift.kind == LiftSpec::Kind::plane ? "plane:SX,SY" : lift.kind == LiftSpec::Kind::bump ? "bump:H,R (96 / (25 sqrt 5) |H| / R)" : "npy",
          std::isfinite(slope) ? fmt::format("{:g}", slope) : "beyond the largest double", kMaxLiftSlope));
  }
}

void check_transform_available(const NoiseTransform& transform, int dimension, bool periodic) {
  transform.validate();
  if (transform.time && dimension + 1 > kMaxDimension)
    throw std::invalid_argument(fmt::format(
        "--time reads the basis one dimension up, and the bases go to {}: --time needs --dim {} or less",
        kMaxDimension, kMaxDimension - 1));
  if (transform.lift.active() && dimension != 2)
    throw std::invalid_argument(
        fmt::format("--lift lifts a 2D field onto a surface in 3D: it needs --dim 2, not {}", dimension));
  if (transform.lift.active() && periodic) throw std::invalid_argument("--lift has no periodic form: the torus takes no --lift");
  if (!transform.stretch_direction.empty()) {
    if (periodic)
      throw std::invalid_argument(
          "--stretch breaks the torus's period (f(A x) has period 1 only for an integer A): the torus takes no --stretch");
    if (static_cast<int>(transform.stretch_direction.size()) != dimension)
      throw std::invalid_argument(fmt::format("--stretch: the direction has {} components, the field {} dimensions",
                                              transform.stretch_direction.size(), dimension));
  }
}

void parse_stretch(std::string_view text, NoiseTransform& transform) {
  const std::size_t colon = text.rfind(':');
  if (colon == std::string_view::npos)
    throw std::invalid_argument(fmt::format("--stretch takes U:S (a direction and a factor, e.g. 1,0:2), got {}",
                                            quote_for_message(std::string(text))));
  transform.stretch_direction = parse_reals(text.substr(0, colon), "--stretch direction");
  const std::vector<double> factor = parse_reals(text.substr(colon + 1), "--stretch factor");
  if (factor.size() != 1) throw std::invalid_argument("--stretch: one factor S after the ':'");
  transform.stretch_factor = factor[0];
  NoiseTransform check = transform;
  check.time.reset();
  check.lift = {};
  check.validate();
}

std::shared_ptr<const DirectionGrid> read_steer_image(const std::string& path) {
  const std::string quoted = quote_for_message(path);
  auto grid = std::make_shared<DirectionGrid>();
  grid->source = path;
  std::vector<std::array<double, 2>> directions;  // row-major, row 0 at y = 0
  auto ends_with = [&](std::string_view suffix) {
    return path.size() >= suffix.size() && path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  try {
    if (ends_with(".npy")) {
      // Shape (rows, columns, 2): the point reader's (M, points, N) with N = 2.
      const std::vector<PointTable> sets = read_point_sets(path, InputFormat::npy);
      if (sets.front().dimension != 2 || sets.size() < 2)
        throw InputError("expected a float array of shape (rows, columns, 2), rows and columns >= 2");
      grid->rows = static_cast<int>(sets.size());
      grid->columns = static_cast<int>(sets.front().rows());
      for (const PointTable& row : sets)
        for (std::size_t j = 0; j < row.rows(); ++j) directions.push_back({row.coordinates[2 * j], row.coordinates[2 * j + 1]});
    } else if (ends_with(".png")) {
      // A flow map: R and G hold the direction's x and y, 0..255 -> -1..1; image up is +y.
      const RgbImage image = read_png_rgb(path);
      grid->rows = image.height;
      grid->columns = image.width;
      for (int i = 0; i < image.height; ++i) {
        const std::uint8_t* row = image.pixels.data() + static_cast<std::size_t>(image.height - 1 - i) * image.width * 3;
        for (int j = 0; j < image.width; ++j)
          directions.push_back({2.0 * row[3 * j] / 255.0 - 1.0, 2.0 * row[3 * j + 1] / 255.0 - 1.0});
      }
    } else {
      throw InputError("expected a .png flow map or a .npy array of shape (rows, columns, 2)");
    }
  } catch (const InputError& e) {
    throw std::invalid_argument(fmt::format("--steer-image {}: {}", quoted, e.what()));
  }
  if (grid->rows < 2 || grid->columns < 2)
    throw std::invalid_argument(fmt::format("--steer-image {}: at least 2 x 2 pixels, got {} x {}", quoted, grid->rows,
                                            grid->columns));
  for (const auto& [ux, uy] : directions) {
    const double norm = std::hypot(ux, uy);
    // No direction (u = 0, or a pixel of the PNG's mid grey 127/128): the isotropic tensor I / 2.
    if (!(norm > 1e-2)) grid->tensors.push_back({0.5, 0.0, 0.5});
    else grid->tensors.push_back({ux * ux / (norm * norm), ux * uy / (norm * norm), uy * uy / (norm * norm)});
  }
  return grid;
}

LiftSpec parse_lift(std::string_view text) {
  const std::size_t colon = text.find(':');
  const std::string_view name = text.substr(0, colon);
  LiftSpec spec;
  if (name == "npy" && colon != std::string_view::npos) {
    spec.kind = LiftSpec::Kind::npy;
    spec.path = std::string(text.substr(colon + 1));
    if (spec.path.empty()) throw std::invalid_argument("--lift npy:FILE: the file name is missing");
    try {
      NpyMatrix matrix = read_npy_matrix(spec.path);
      HeightGrid grid{matrix.rows, matrix.columns, std::move(matrix.values)};
      if (grid.rows >= 2 && grid.columns >= 2) grid.max_slope = SplineHeight(grid).max_slope();
      spec.grid = std::make_shared<const HeightGrid>(std::move(grid));
    } catch (const InputError& e) {
      throw std::invalid_argument(fmt::format("--lift npy:{}: {}", quote_for_message(spec.path), e.what()));
    }
    NoiseTransform check;
    check.lift = spec;
    check.validate();
    return spec;
  }
  if (name == "plane")
    spec.kind = LiftSpec::Kind::plane;
  else if (name == "bump")
    spec.kind = LiftSpec::Kind::bump;
  else
    throw std::invalid_argument(fmt::format("--lift takes plane:SX,SY, bump:H,R[,CX,CY[,SX,SY]] or npy:FILE, got {}",
                                            quote_for_message(std::string(text))));
  if (colon == std::string_view::npos) throw std::invalid_argument(fmt::format("--lift {}: its parameters are missing", name));
  spec.parameters = parse_reals(text.substr(colon + 1), fmt::format("--lift {}", name));
  if (spec.kind == LiftSpec::Kind::bump && spec.parameters.size() == 2) spec.parameters.insert(spec.parameters.end(), {0.0, 0.0});
  NoiseTransform check;
  check.lift = spec;
  check.validate();
  return spec;
}

std::shared_ptr<const HeightField> make_height_field(const LiftSpec& spec) {
  switch (spec.kind) {
    case LiftSpec::Kind::plane: return std::make_shared<const PlaneHeight>(spec.parameters[0], spec.parameters[1]);
    case LiftSpec::Kind::bump:
      return std::make_shared<const BumpHeight>(spec.parameters[0], spec.parameters[1], spec.parameters[2], spec.parameters[3],
                                                spec.parameters.size() == 6 ? spec.parameters[4] : 0.0,
                                                spec.parameters.size() == 6 ? spec.parameters[5] : 0.0);
    case LiftSpec::Kind::npy: return std::make_shared<const SplineHeight>(*spec.grid);
    case LiftSpec::Kind::none: break;
  }
  throw std::invalid_argument("no height field");
}

template <int N>
std::shared_ptr<const NoiseFunctions<N>> make_transformed_noise(NoiseBasis basis, std::uint64_t seed, double phase,
                                                                bool periodic, double frequency,
                                                                const NoiseTransform& transform, double time,
                                                                double lift_ramp_in_basis_units) {
  check_transform_available(transform, N, periodic);
  std::shared_ptr<const NoiseFunctions<N>> noise;
  if (transform.time || transform.lift.active()) {
    if constexpr (N + 1 > kMaxDimension) {
      throw std::logic_error("unreachable: checked above");
    } else {
      const std::shared_ptr<const NoiseFunctions<N + 1>> inner =
          periodic ? make_periodic_noise_functions<N + 1>(basis, seed, frequency, phase)
                   : make_noise_functions<N + 1>(basis, seed, phase);
      // Time and heights in the field's length units, read by the basis at s t and s h: the scale the
      // field gives the slice (on the torus the periodic basis is read at x itself, s = 1).
      const double scale =
          periodic ? 1.0 : 2.0 * std::numbers::pi * frequency / SlicedNoise<N>::slice_wavenumber(*inner);
      if constexpr (N == 2) {
        if (transform.lift.active())
          noise = std::make_shared<const LiftedNoise>(inner, make_height_field(transform.lift), scale,
                                                      lift_ramp_in_basis_units);
      }
      if (!noise) noise = std::make_shared<const SlicedNoise<N>>(inner, scale * time);
    }
  } else {
    noise = periodic ? make_periodic_noise_functions<N>(basis, seed, frequency, phase) : make_noise_functions<N>(basis, seed, phase);
  }
  if (!transform.stretch_direction.empty()) {
    Vec<N> u;
    for (int j = 0; j < N; ++j) u[j] = transform.stretch_direction[j];
    noise = std::make_shared<const StretchedNoise<N>>(noise, unit_direction<N>(u), transform.stretch_factor);
  }
  return noise;
}

#define DFVN_INSTANTIATE(N)                                                                                       \
  template std::shared_ptr<const NoiseFunctions<N>> make_transformed_noise<N>(                                  \
      NoiseBasis, std::uint64_t, double, bool, double, const NoiseTransform&, double, double);
DFVN_INSTANTIATE(2)
DFVN_INSTANTIATE(3)
DFVN_INSTANTIATE(4)
DFVN_INSTANTIATE(5)
DFVN_INSTANTIATE(6)
DFVN_INSTANTIATE(7)
DFVN_INSTANTIATE(8)
#undef DFVN_INSTANTIATE

}  // namespace dfvn

#include "dfvn/field/field_transform.hpp"

#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/message_text.hpp"

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
          fmt::format("{}: '{}' is not a finite real number", what, quote_for_message(std::string(item))));
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
  BumpHeight(double h, double r, double cx, double cy) : height_(h), radius_(r), centre_(cx, cy) {}
  double height(const Vec<2>& x, Vec<2>& gradient) const override {
    const Vec<2> d = (x - centre_) / radius_;
    const double r2 = d.squaredNorm();
    if (!(r2 < 1.0)) {
      gradient.setZero();
      return 0.0;
    }
    const double q = 1.0 - r2;  // h = H q^3, grad h = H 3 q^2 (-2 d / R)
    gradient = (-6.0 * height_ * q * q / radius_) * d;
    return height_ * q * q * q;
  }

 private:
  double height_;
  double radius_;
  Vec<2> centre_;
};

}  // namespace

void NoiseTransform::validate() const {
  if (!stretch_direction.empty()) {
    double norm2 = 0.0;
    for (double v : stretch_direction) {
      if (!std::isfinite(v)) throw std::invalid_argument("--stretch: the direction must be finite");
      norm2 += v * v;
    }
    if (!(norm2 > 0.0) || !std::isfinite(norm2))
      throw std::invalid_argument("--stretch: the direction must not be zero");
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
    if (!std::isfinite(lift.ramp)) throw std::invalid_argument("--lift-ramp must be finite");
    if (lift.kind == LiftSpec::Kind::plane && lift.parameters.size() != 2)
      throw std::invalid_argument("--lift plane:SX,SY takes two slopes");
    if (lift.kind == LiftSpec::Kind::bump && lift.parameters.size() != 4)
      throw std::invalid_argument("--lift bump:H,R[,CX,CY] takes a height, a radius and optionally a centre");
    if (lift.kind == LiftSpec::Kind::bump && !(lift.parameters[1] > 0.0))
      throw std::invalid_argument(fmt::format("--lift bump: the radius R must be positive, got {}", lift.parameters[1]));
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
    throw std::invalid_argument(fmt::format("--stretch takes U:S (a direction and a factor, e.g. 1,0:2), got '{}'",
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

LiftSpec parse_lift(std::string_view text) {
  const std::size_t colon = text.find(':');
  const std::string_view name = text.substr(0, colon);
  LiftSpec spec;
  if (name == "plane")
    spec.kind = LiftSpec::Kind::plane;
  else if (name == "bump")
    spec.kind = LiftSpec::Kind::bump;
  else
    throw std::invalid_argument(fmt::format("--lift takes plane:SX,SY or bump:H,R[,CX,CY], got '{}'",
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
      return std::make_shared<const BumpHeight>(spec.parameters[0], spec.parameters[1], spec.parameters[2], spec.parameters[3]);
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
    noise = std::make_shared<const StretchedNoise<N>>(noise, u / u.norm(), transform.stretch_factor);
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

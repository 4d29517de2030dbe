// Where the field reads its noise (FieldOptions::transform): a stretch, a time slice and a lift, the
// three wrappers of noise/noise_transforms.hpp, parsed from the command line's specs and built for a
// field. All three leave the field exactly divergence-free (the f_i stay C2); the field renormalises
// RMS |c| to 1 for each (field/dfvn_field.hpp says how).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dfvn/core/dimension.hpp"
#include "dfvn/noise/noise_functions.hpp"
#include "dfvn/noise/noise_transforms.hpp"
#include "dfvn/noise/rotating_gradients.hpp"
#include "dfvn/noise/steerable_noise.hpp"

namespace dfvn {

// A factor S outside [kMinStretch, kMaxStretch] is refused: A = I + (S - 1) u u^T is then nearly singular
// or stretches the noise argument by more than 10^6 (noise/noise_domain.hpp bounds it).
inline constexpr double kMinStretch = 1e-6;
inline constexpr double kMaxStretch = 1e6;

// The lift's height fields, in the field's length units (all C2):
// - plane:SX,SY   h(x) = SX x_1 + SY x_2 (a constant slope; a lift onto it is the stretch
//                 A = I + (sqrt(1 + |grad h|^2) - 1) n n^T along n = grad h / |grad h|, up to a rotation
//                 of the noise: F is read at (x, grad h . x));
// - bump:H,R[,CX,CY[,SX,SY]]  h(x) = H (1 - r^2)^3 for r = |x - (CX, CY)| / R < 1, else 0 (value, slope and
//                 curvature 0 at r = 1, so C2; a polynomial in r^2, so smooth at the centre); R > 0; its
//                 steepest slope is 96 / (25 sqrt 5) |H| / R (at r = 1 / sqrt 5); with SX, SY the bump sits on
//                 the plane SX x + SY y (the paper's Figure 9: a slope with a hill in its middle).
// - npy:FILE      a 2D float64/float32 array (rows, columns) from a .npy file, each side 2..65536, every
//                 element finite, heights in length units. Element (i, j) is the height at x = j / (columns - 1),
//                 y = i / (rows - 1): the columns run along x and the rows along y over the unit square [0, 1]^2,
//                 corners included (numpy's h[i, j] = f(x_j, y_i), as np.meshgrid's default 'xy' gives). h is the
//                 interpolating tensor cubic B-spline of the array: it passes through every element and is C2
//                 everywhere (the B-spline is C2 whatever its control points, which are prefiltered so that it
//                 interpolates); beyond the square its control points continue as the border's, so h levels
//                 off to a constant from two grid spacings outside, still C2.
struct HeightGrid {
  int rows = 0;
  int columns = 0;
  std::vector<double> values;  // rows x columns, element (i, j) at i * columns + j
  double max_slope = 0.0;      // a bound on |dh/dx| and |dh/dy| of its spline (parse_lift computes it)
};

// The steepest slope |dh/dx_j| of a lift's height and |--lift-ramp| are at most 2^50. In the basis's
// units grad f = grad_xy F + (dF/dz + ramp) grad h: beyond 2^50 (times the noise's own O(1) gradient) the
// noise's part is within a few units in the last place of the slope's term, so the field would be the
// slope's alone; within it every value the field computes is finite (the heights are bounded by the noise
// domain, |F h| < 2^50, and ramp x slope by 2^100).
inline constexpr double kMaxLiftSlope = 0x1p50;
inline constexpr double kMaxLiftRamp = 0x1p50;

struct LiftSpec {
  enum class Kind { none, plane, bump, npy } kind = Kind::none;
  std::vector<double> parameters;  // plane: SX, SY; bump: H, R, CX, CY; npy: none
  std::string path;                // npy: the file it was read from
  std::shared_ptr<const HeightGrid> grid;  // npy: the array, read once by parse_lift
  // The vertical ramp of the paper's Figure 9: F(x, z) + ramp z, ramp in RMS-speed units (the speed
  // that a unit slope adds, along the contour lines of h). 0: Figure 10's lift, no ramp.
  double ramp = 0.0;
  bool active() const { return kind != Kind::none; }
};

struct NoiseTransform {
  // --stretch U:S: f_i(A x) with A = I + (S - 1) u u^T, u = U / |U|; empty direction: no stretch.
  std::vector<double> stretch_direction;
  double stretch_factor = 1.0;
  // --time T: the N-1 functions of the (N+1)-dimensional basis at (x, T), T in the same length units as x.
  std::optional<double> time;
  // --lift (2D only): f(x) = F(x, h(x)) for the first function F of the 3D basis.
  LiftSpec lift;
  // --steer-dir / --steer-field / --steer-k: the direction field of --noise steerable (noise/steerable_noise.hpp).
  // Not a transform of the basis but its parameters, carried here so that every path that takes a field's
  // transform (field, sample, animate, Python) takes them; not counted by active() (the basis reads them).
  SteerSpec steer;
  // --rotation: how --noise simplex's gradients turn with the phase in 3D (noise/rotating_gradients.hpp); carried
  // here for the same reason as `steer`, not counted by active().
  GradientRotation rotation = kDefaultGradientRotation;

  bool active() const { return !stretch_direction.empty() || time.has_value() || lift.active(); }
  // Throws std::invalid_argument with one line for a zero or non-finite direction, S outside
  // [kMinStretch, kMaxStretch], a non-finite time, a lift with bad parameters, a lift beside a time
  // (both use the third noise dimension).
  void validate() const;
};

// Throws std::invalid_argument where `transform` is not available in `dimension` (--time with N = 8,
// --lift outside 2D, a stretch direction of another length) or on the torus (`periodic`: a stretch or a
// lift breaks the period), with one line saying why. make_transformed_noise checks the same.
void check_transform_available(const NoiseTransform& transform, int dimension, bool periodic);

// "U:S" (U comma-separated, any length, e.g. "1,0:2"), into `transform`; throws std::invalid_argument.
void parse_stretch(std::string_view text, NoiseTransform& transform);
// "plane:SX,SY", "bump:H,R[,CX,CY]" or "npy:FILE" (the file is read here); throws std::invalid_argument
// with one line (for a file: its name and what is wrong with it, io/point_reader.hpp read_npy_matrix).
LiftSpec parse_lift(std::string_view text);
std::shared_ptr<const HeightField> make_height_field(const LiftSpec& spec);
// --steer-image FILE: a 2D direction field over the unit square (noise/steerable_noise.hpp, DirectionGrid), from a
// .png flow map (colour: u = (2 R / 255 - 1, 2 G / 255 - 1), x right and y up, row 0 the top at y = 1) or a .npy
// float array of shape (rows, columns, 2) holding u at x = j / (columns - 1), y = i / (rows - 1) (numpy's
// u[i, j]); a direction shorter than 1e-2 counts as none. Throws std::invalid_argument with one line naming the
// file and what is wrong with it.
std::shared_ptr<const DirectionGrid> read_steer_image(const std::string& path);

// The N-1 functions the field reads for `transform`, at time `time` (the transform's own time is
// ignored: the field asks for time 0 too, to measure an amplitude that does not depend on the time).
// `periodic`: the basis's periodic form at `frequency` (the torus); else the free basis, and `frequency`
// sets the scale s = 2 pi F / k_eff that converts the time and the heights into the basis's units.
// Throws std::invalid_argument where the transform is not available (its message says why).
template <int N>
std::shared_ptr<const NoiseFunctions<N>> make_transformed_noise(NoiseBasis basis, std::uint64_t seed, double phase,
                                                                bool periodic, double frequency,
                                                                const NoiseTransform& transform, double time,
                                                                double lift_ramp_in_basis_units = 0.0);

}  // namespace dfvn

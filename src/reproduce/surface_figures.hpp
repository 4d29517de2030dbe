// `dfvn-sample reproduce figure6`, `figure7`, `figure9` and `figure10`: the paper's Sections 5.3-5.5
// (issue 27 item 4). Each run writes PNGs (io/png.hpp, no gnuplot needed), a CSV of its numbers and a
// Markdown reading computed from those numbers.
//   figure6: a texture on the unit sphere warped along the surface field (f_1 = (G/2) |x|^2, the field
//            tangent to every sphere, field/constraint.hpp on_sphere), RK4 at 32 and 128 steps with and
//            without projection (Gauss-Newton reprojection) against 2048 RK4 steps.
//   figure7: a ring pattern in the unit square warped along 2D DFVN bounded by the disc (the inscribed
//            ball, Eq. 13): how many samples leave the disc, and the radial profile outside it; its 3D half (a
//            textured ball, central slices) and the paper's own construction beside Eq. 13 in 2D and 3D.
//   figure9 / figure10: particle traces over the plane h = SX x + SY y (--lift plane), with (figure9, on a slope
//            with a hill in the middle, the paper's central vortex) and without (figure10) the vertical ramp
//            (--lift-ramp), as in the paper; the displacement covariance's principal direction against the slope
//            direction, and the turns about the hill.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "dfvn/core/image.hpp"
#include "dfvn/core/progress.hpp"
#include "dfvn/noise/noise_functions.hpp"

namespace dfvn {

using FigureLog = std::function<void(const std::string&)>;

// ---- Figure 6: a texture warped on the unit sphere (Section 5.3) ----

struct Figure6Config {
  int width = 512;            // the equirectangular map's width in pixels; its height is width / 2
  double time = 0.5;          // integration time (RMS |c| = 1: about 0.5 unit lengths travelled)
  double frequency = 1.5;     // cycles per unit length
  NoiseBasis noise = kDefaultNoiseBasis;
  std::uint64_t seed = 1;
  int threads = 0;
  std::string out_dir = "out/figure6";
  static constexpr int kReferenceSteps = 2048;            // RK4, no projection (as Table 2's reference)
  static constexpr int kSteps[2] = {32, 128};              // the compared settings, each with and without projection
  // The row of increasing t (as the paper's figure): the warp at these fractions of `time`, each with
  // kTimeRowSteps RK4 steps and projection.
  static constexpr double kTimeFractions[3] = {0.25, 0.5, 1.0};
  static constexpr int kTimeRowSteps = 128;

  int height() const { return width / 2; }
  void validate() const;  // throws std::invalid_argument naming the option
};

struct Figure6Row {
  std::string label;     // "reference", "rk4-32", "rk4-32-projected", ...
  int steps = 0;
  bool projected = false;
  double rmse = 0.0;               // against the reference, 8-bit units from float values (warp/image_warp.hpp rmse)
  double max_radius_drift = 0.0;   // max over pixels of ||x(t)| - 1|
  double mean_radius_drift = 0.0;  // its mean
  std::int64_t field_evaluations = 0;
  double seconds = 0.0;
};

struct Figure6Result {
  Figure6Config config;
  std::vector<Figure6Row> rows;        // the reference first, then 32, 32 projected, 128, 128 projected
  std::vector<FloatImage> images;      // per row
  FloatImage source;
  std::vector<double> row_times;       // kTimeFractions x time
  std::vector<FloatImage> time_images; // the warp at each of row_times (projected)
  std::string machine;
};

// The texture: wavy stripes, a smooth function of the 3D point (so it is defined off the sphere too).
double figure6_texture(double x, double y, double z);
Figure6Result run_figure6(const Figure6Config& config, const StageProgress& progress = {});
std::vector<double> figure6_stage_weights(const Figure6Config& config);
// DIR/figure6.csv, DIR/figure6.md, DIR/source.png, DIR/<label>.png per row, DIR/time-<t>.png per time of
// the row, DIR/error-<label>.png per compared setting (|warp - reference| on one log scale for all: the
// largest error of any setting white, kFigure6ErrorDecades decades below it black) and, with gnuplot,
// DIR/figure6.png: the titled montage (scripts/figure6.gp). Returns the Markdown; `log` says how to get the
// montage without gnuplot.
std::string write_figure6(const Figure6Result& result, const FigureLog& log = {});
// The largest pixel error |warp - reference| of any compared setting, in 8-bit grey levels.
double figure6_largest_error(const Figure6Result& result);
inline constexpr int kFigure6ErrorDecades = 5;
std::vector<std::string> figure6_output_files(const Figure6Config& config);
std::string figure6_markdown(const Figure6Result& result);

// ---- Figure 7: DFVN confined to a disc (Section 5.4) ----

struct Figure7Config {
  int width = 256;               // the unit square's image, width x width pixels
  double time = 0.5;
  int steps = 64;                // RK4 steps, each followed by Gauss-Newton reprojection
  double frequency = 3.0;        // cycles per unit length
  double transition_width = 0.1; // Eq. 13's w, in length units (the disc's radius is 1/2)
  int rings = 8;                 // the pattern: 0.5 + 0.5 cos(2 pi rings r / R), R = 1/2 the disc's radius
  int bins = 32;                 // radial profile bins over r in [0, sqrt(2) / 2]
  int width3d = 96;              // the 3D half: each central slice of the unit cube, width3d x width3d pixels
  NoiseBasis noise = kDefaultNoiseBasis;
  std::uint64_t seed = 1;
  int threads = 0;
  std::string out_dir = "out/figure7";

  void validate() const;
};

// One construction of Figure 7's confinement in one dimension (reproduce/figure7_3d.cpp): eq13 (the library's:
// Eq. 13 replaces a function, Gauss-Newton reprojection) or paper (the paper's: the second vector interpolated
// from e_z, in 3D from a second noise gradient, to the normal; RK4 alone).
struct Figure7ConstructionRow {
  int dimension = 2;
  std::string construction;
  std::int64_t inside = 0, left = 0;     // traces starting in the closed disc (ball), and those ending outside it
  double max_end_radius_inside = 0.0;    // the largest end radius of an inside start
  double max_radius_drift_outside = 0.0; // the largest | |x(t) - c| - |x(0) - c| | of an outside start
  double zone_divergence_median = 0.0;   // |div c| / RMS |c| in the transition zone (central differences)
  double zone_divergence_p95 = 0.0;
  std::int64_t field_evaluations = 0;
  double seconds = 0.0;
};

struct Figure7Result {
  Figure7Config config;
  FloatImage source, warped;
  std::int64_t inside = 0, outside = 0;  // pixels whose centre starts inside / outside the closed disc
  std::int64_t left = 0;                 // inside at the start, outside the closed disc at the end
  double max_change_outside = 0.0;       // max |warped - source| over the pixels outside, value units
  double max_radius_drift_outside = 0.0; // max ||x(t) - c| - |x(0) - c|| over the pixels outside
  double mean_change_inside = 0.0;       // mean |warped - source| inside (how much the warp moved)
  double max_radius_inside_end = 0.0;    // the largest |x(t) - c| of a trace that started inside
  // Radial profile: per bin, pixels and the mean value of the source and of the warped image.
  std::vector<std::int64_t> bin_pixels;
  std::vector<double> bin_source, bin_warped;
  std::int64_t field_evaluations = 0;
  double seconds = 0.0;
  std::string machine;
  // Both constructions in 2D (eq13 first: the numbers above) and 3D, the 2D paper construction's warp, and the 3D
  // half's central slices: source z, y, x = 1/2, then eq13's three, then paper's three.
  std::vector<Figure7ConstructionRow> constructions;
  FloatImage warped_paper;
  std::vector<FloatImage> slices_3d;
  double share_left() const { return inside > 0 ? static_cast<double>(left) / static_cast<double>(inside) : 0.0; }
};

Figure7Result run_figure7(const Figure7Config& config, const FractionProgress& progress = {});
// The constructions' comparison and the 3D half, into `result` (run_figure7 calls it after the 2D Eq. 13 run).
void run_figure7_constructions(const Figure7Config& config, Figure7Result& result, const FractionProgress& progress = {});
// DIR/figure7.csv (one row), DIR/figure7_profile.csv, DIR/figure7.md, DIR/source.png, DIR/warped.png, and the
// constructions and the 3D half: DIR/figure7_constructions_3d.csv (a row per dimension and construction),
// DIR/warped_paper.png (2D, the paper's construction) and DIR/slices_3d.png (rows: source, eq13, paper; columns:
// the central slices z, y, x = 1/2 of the unit cube, the ball's sphere their largest circle).
std::string write_figure7(const Figure7Result& result, const FigureLog& log = {});
std::vector<std::string> figure7_output_files();
std::string figure7_markdown(const Figure7Result& result);

// ---- Figures 9 and 10: anisotropy by lifting onto a slope (Section 5.5) ----

struct Figure9Config {
  bool ramp_figure = true;       // true: figure9 (the vertical ramp, as in the paper's Figure 9); false: figure10 (no ramp)
  double slope_x = 1.0, slope_y = 0.5;  // h = SX x + SY y, in length units
  double ramp = 1.0;             // figure9's --lift-ramp BETA (RMS-speed units per unit slope); unused by figure10
  // figure9's hill (--bump H,R): h = SX x + SY y + H (1 - r^2 / R^2)^3 about the square's centre (r < R), the paper's
  // surface with "a vortex in the center": where the hill is steeper than the plane its contour lines close, and
  // the ramp's motion along them circles the hill. H = 0: the plane alone (figure10's surface).
  double bump_height = 0.0, bump_radius = 0.25;
  int grid = 48;                 // K x K particles at the cell centres of the unit square
  double time = 0.25;            // about one noise cycle travelled at frequency 4
  int steps = 64;                // RK4 steps per trace, each followed by Gauss-Newton reprojection
  int segments = 32;             // the traces are drawn (and written) at this many points after the start
  double frequency = 4.0;        // 16 cycles over the unit square: displacements of distant particles are independent
  int image = 512;               // the PNG's side in pixels
  NoiseBasis noise = kDefaultNoiseBasis;
  std::uint64_t seed = 1;
  int threads = 0;
  std::string out_dir = "out/figure9";

  std::string name() const { return ramp_figure ? "figure9" : "figure10"; }
  double used_ramp() const { return ramp_figure ? ramp : 0.0; }
  void validate() const;
};

struct Figure9Result {
  Figure9Config config;
  std::vector<double> traces;  // particle-major: (segments + 1) points of 2 coordinates per particle
  double mean_dx = 0.0, mean_dy = 0.0;               // the mean displacement
  double cov_xx = 0.0, cov_xy = 0.0, cov_yy = 0.0;   // the displacements' covariance (about their mean)
  double eigen_major = 0.0, eigen_minor = 0.0;       // its eigenvalues
  double principal_angle = 0.0;   // the principal direction's angle from the x axis, degrees in (-90, 90]
  double principal_to_slope = 0.0;  // the angle between the principal direction and the slope direction, [0, 90]
  double mean_to_slope = 0.0;       // the angle between the mean displacement and the slope direction, [0, 180]
  double rms_displacement = 0.0;
  // The mean number of turns (signed, counter-clockwise positive) that the particles starting within R / 2 of the
  // hill's centre make about it (0 without a hill): the central vortex.
  double centre_turns = 0.0;
  std::int64_t centre_particles = 0;
  std::int64_t field_evaluations = 0;
  double seconds = 0.0;
  std::string machine;
  int particles() const { return config.grid * config.grid; }
};

Figure9Result run_figure9(const Figure9Config& config, const FractionProgress& progress = {});
// DIR/<name>.csv (one row), DIR/<name>_traces.csv, DIR/<name>.md, DIR/<name>.png.
std::string write_figure9(const Figure9Result& result, const FigureLog& log = {});
std::vector<std::string> figure9_output_files(const Figure9Config& config);
std::string figure9_markdown(const Figure9Result& result);

}  // namespace dfvn

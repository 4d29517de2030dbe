// `dfvn-sample reproduce figure8`: the paper's Figure 8 (Section 5.4), curl noise jittering animated
// over hundreds of frames in the unit square and cube: drop mode (Bærentzen et al. 2023: the free field,
// particles outside the domain are not shown, so they pop in and out) against the boundary-conformant
// field (Eq. 13: every particle stays inside). animate/animation.hpp does the work.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "dfvn/animate/animation.hpp"
#include "dfvn/core/progress.hpp"

namespace dfvn {

struct Figure8Config {
  int frames = 300;
  double phase_step = 0.05;  // DA, radians per frame
  int grid_2d = 16;          // 2D: the cubic 16^2 lattice
  int grid_3d = 8;           // 3D: the BCC lattice on the 8^3 cubic one (8^3 + 7^3 = 855 sites), the paper's octahedral start set
  StartLattice lattice_3d = StartLattice::bcc;
  int drop_margin = 4;  // drop mode: spacings beyond the domain (4: the 3D inside count keeps no trend over 300 frames, data/figure8_record.md)
  std::uint64_t seed = 1;
  int threads = 0;
  std::string out_dir = "out/figure8";
  // Tracks drawn per 2D run: the particles nearest the boundary in frame 0.
  static constexpr int kTracks = 4;

  void validate() const;  // throws std::invalid_argument naming the option
  // The four runs: 2D drop, 2D conformant, 3D drop, 3D conformant.
  std::vector<AnimationOptions> runs() const;
};

struct Figure8Run {
  AnimationResult animation;
  std::vector<std::uint64_t> tracks;  // particles drawn (2D only)
};

struct Figure8Result {
  Figure8Config config;
  std::vector<Figure8Run> runs;  // in Figure8Config::runs() order
  std::vector<double> seconds;   // wall time per run
  std::string machine;
};

// `progress`: one stage per run, each reporting the fraction of its frames.
Figure8Result run_figure8(const Figure8Config& config, const StageProgress& progress = {});
std::vector<double> figure8_stage_weights(const Figure8Config& config);

// The particles of a 2D run nearest the boundary in frame 0 (inside), nearest first; ties by index.
std::vector<std::uint64_t> boundary_tracks(const AnimationResult& animation, int count);

// DIR/figure8_frames.csv (dimension, mode, lattice, then animate's frames.csv columns), DIR/figure8_tracks.csv
// (dimension, mode, particle, frame, x0, x1: the 2D tracks, NaN rows where a particle is outside),
// DIR/figure8.md and, with gnuplot, DIR/figure8.png. Returns the Markdown.
std::string write_figure8(const Figure8Result& result, const std::function<void(const std::string&)>& log);
std::vector<std::string> figure8_output_files();
std::string figure8_markdown(const Figure8Result& result);

}  // namespace dfvn

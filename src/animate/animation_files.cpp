#include "dfvn/animate/animation_files.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "dfvn/io/atomic_file.hpp"
#include "dfvn/io/csv.hpp"
#include "dfvn/io/point_file.hpp"
#include "dfvn/plot/gnuplot.hpp"

namespace dfvn {

std::string frame_csv_row(const FrameStats& s) {
  return fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{}", s.frame, format_real(s.phase), s.inside, s.entered,
                     s.left, format_real(s.largest_jump), format_real(s.rms_move), s.retraced, s.kept_at_start,
                     s.projected, format_real(s.nn_min), format_real(s.nn_q01), format_real(s.nn_median),
                     format_real(s.nn_median_scaled));
}

std::vector<int> strip_frames(int frames) {
  std::vector<int> shown;
  const int panels = std::min(frames, 4);
  for (int p = 0; p < panels; ++p) {
    const int k = panels == 1 ? 0 : static_cast<int>(std::lround(static_cast<double>(p) * (frames - 1) / (panels - 1)));
    if (shown.empty() || shown.back() != k) shown.push_back(k);
  }
  return shown;
}

std::vector<std::string> animation_output_files(const AnimationOptions& options) {
  std::vector<std::string> files = {"frames.npy", "frames.csv"};
  if (options.dimension <= 3) {
    files.push_back("trails.csv");
    if (!find_gnuplot().empty()) files.push_back("animation.png");
  }
  return files;
}

namespace {

std::string trails_csv(const AnimationResult& result, const std::vector<int>& shown) {
  const int n = result.options.dimension;
  std::string text = "panel,frame,particle," + numbered_header("x", n) + "," + numbered_header("to_x", n) + "\n";
  for (std::size_t p = 0; p < shown.size(); ++p) {
    for (int k = std::max(1, shown[p] - kTrailFrames + 1); k <= shown[p]; ++k) {
      const double* from = result.frame(k - 1);
      const double* to = result.frame(k);
      for (std::uint64_t i = 0; i < result.particles; ++i) {
        if (std::isnan(from[i * n]) || std::isnan(to[i * n])) continue;
        text += fmt::format("{},{},{}", p + 1, k, i);
        for (int j = 0; j < n; ++j) text += "," + format_real(from[i * n + j]);
        for (int j = 0; j < n; ++j) text += "," + format_real(to[i * n + j]);
        text += "\n";
      }
    }
    if (shown[p] == 0) {  // frame 0 has no trail: its points as segments of length 0
      const double* at = result.frame(0);
      for (std::uint64_t i = 0; i < result.particles; ++i) {
        if (std::isnan(at[i * n])) continue;
        text += fmt::format("{},0,{}", p + 1, i);
        for (int r = 0; r < 2; ++r)
          for (int j = 0; j < n; ++j) text += "," + format_real(at[i * n + j]);
        text += "\n";
      }
    }
  }
  return text;
}

}  // namespace

void write_animation(const std::string& dir, const AnimationResult& result,
                     const std::function<void(const std::string&)>& log) {
  const std::filesystem::path folder(dir);
  const AnimationOptions& o = result.options;
  {
    AtomicOutput npy((folder / "frames.npy").string());
    write_npy_header(npy.stream(), fmt::format("{}, {}, {}", o.frames, result.particles, o.dimension));
    npy.stream().write(reinterpret_cast<const char*>(result.positions.data()),
                       static_cast<std::streamsize>(result.positions.size() * sizeof(double)));
    npy.commit();
  }
  std::string csv = std::string(kFrameColumns) + "\n";
  for (const FrameStats& s : result.frames) csv += frame_csv_row(s) + "\n";
  write_file_atomically((folder / "frames.csv").string(), csv);
  if (o.dimension > 3) return;
  const std::vector<int> shown = strip_frames(o.frames);
  write_file_atomically((folder / "trails.csv").string(), trails_csv(result, shown));
  std::string frames;
  for (int k : shown) frames += fmt::format("{}{}", frames.empty() ? "" : " ", k);
  // The domain by its name in this dimension: the unit square and disc in 2D, the cube and ball from 3D on.
  const bool cube = o.cnj.domain == DomainKind::cube;
  const std::string domain = o.dimension == 2 ? (cube ? "unit square" : "disc") : (cube ? "unit cube" : "ball");
  const std::string title = fmt::format("{}D CNJ animated, {} in the {}, {} lattice, phase step {} rad/frame, {} frames",
                                        o.dimension, to_string(o.cnj.domain_mode), domain, to_string(o.lattice),
                                        format_real(o.phase_step, 4), o.frames);
  draw_figure(PlotProgram::animation, (folder / "animation.png").string(),
              {(folder / "trails.csv").string(), std::to_string(o.dimension), frames,
               std::string(to_string(o.cnj.domain)), title},
              log);
}

std::string animation_summary(const AnimationResult& result) {
  std::uint64_t lo = result.particles, hi = 0, entered = 0, left = 0, kept = 0, retraced = 0, projected = 0;
  for (const FrameStats& s : result.frames) {
    lo = std::min(lo, s.inside);
    hi = std::max(hi, s.inside);
    entered += s.entered;
    left += s.left;
    kept += s.kept_at_start;
    retraced += s.retraced;
    projected += s.projected;
  }
  const AnimationOptions& o = result.options;
  const bool advect = o.mode == AnimationMode::advect;
  const PackingSummary p = summarise_packing(result);
  const MoveSummary& m = result.moves;
  std::string text = fmt::format(
      "{}D, {} frames, {} particles ({} lattice, {} mode in the {}), {} mode: {}; phase {}{} + k * {} rad\n",
      o.dimension, o.frames, result.particles, to_string(o.lattice), to_string(o.cnj.domain_mode), to_string(o.cnj.domain),
      to_string(o.mode),
      advect ? fmt::format("frame 0 is CNJ, frame k is frame k-1 traced for a frame time of {} ({} RK4 step(s))",
                           format_real(result.frame_time), result.frame_steps)
             : fmt::format("frame k is CNJ of the start sites at phase alpha_k (trace time {}, RK4 steps of at most "
                           "1/{} of it and {} long)",
                           format_real(result.trace_time), result.frame_steps,
                           format_real(animation_trace_options(o).max_step_length, 4)),
      format_real(o.start_phase),
      reduced_phase(o.start_phase) == o.start_phase ? std::string()
                                                    : " (" + format_real(reduced_phase(o.start_phase)) + " modulo 2 pi)",
      format_real(o.phase_step));
  text += fmt::format("inside per frame: {}..{}; entered {}, left {} ({} popping events per 100 frames)", lo, hi, entered,
                      left, format_real(result.popping_per_100_frames(), 4));
  text += advect ? fmt::format("; retraced {}, kept at start {}\n", retraced, kept)
                 : fmt::format("; projected into the domain {}\n", projected);
  text += fmt::format(
      "packing: median nearest-neighbour distance {} mean spacings in frame 0, frames / frame 0: {}..{} (mean {}); "
      "1% quantile {} in frame 0, frames / frame 0: {}..{}\n",
      format_real(p.median_0, 4), format_real(p.median_min, 4), format_real(p.median_max, 4),
      format_real(p.median_mean, 4), format_real(p.q01_0, 4), format_real(p.q01_min, 4), format_real(p.q01_max, 4));
  if (m.moves == 0) return text + "per-frame moves: none (one frame)\n";
  text += fmt::format("per-frame moves (frame 0's mean spacings): median {}, 99th percentile {} ({}x), largest {} ({}x)\n",
                      format_real(m.median, 4), format_real(m.p99, 4), format_real(m.p99 / m.median, 4),
                      format_real(m.largest, 4), format_real(m.largest / m.median, 4));
  return text;
}

}  // namespace dfvn

#include "dfvn/reproduce/figure8.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/animate/animation_files.hpp"
#include "dfvn/core/machine.hpp"
#include "dfvn/core/stopwatch.hpp"
#include "dfvn/io/atomic_file.hpp"
#include "dfvn/io/csv.hpp"
#include "dfvn/plot/gnuplot.hpp"

namespace dfvn {

std::vector<AnimationOptions> Figure8Config::runs() const {
  std::vector<AnimationOptions> out;
  for (int dimension : {2, 3}) {
    for (DomainMode mode : {DomainMode::drop, DomainMode::conformant}) {
      AnimationOptions o;
      o.dimension = dimension;
      o.grid = dimension == 2 ? grid_2d : grid_3d;
      o.lattice = dimension == 2 ? StartLattice::cubic : lattice_3d;
      o.frames = frames;
      o.phase_step = phase_step;
      o.cnj.domain_mode = mode;
      o.drop_margin = drop_margin;
      out.push_back(o);
    }
  }
  return out;
}

void Figure8Config::validate() const {
  for (const AnimationOptions& o : runs()) o.validate();
  if (frames < 2) throw std::invalid_argument(fmt::format("figure8 needs at least 2 frames, got {}", frames));
}

std::vector<double> figure8_stage_weights(const Figure8Config& config) {
  std::vector<double> weights;
  for (const AnimationOptions& o : config.runs())
    weights.push_back(static_cast<double>(animation_start_sites(o).size() / o.dimension) * o.frames * o.dimension);
  return weights;
}

std::vector<std::uint64_t> boundary_tracks(const AnimationResult& animation, int count) {
  const int n = animation.options.dimension;
  const double* x = animation.frame(0);
  std::vector<std::pair<double, std::uint64_t>> by_distance;
  for (std::uint64_t i = 0; i < animation.particles; ++i) {
    if (std::isnan(x[i * n])) continue;
    double d = 1.0;
    for (int j = 0; j < n; ++j) d = std::min({d, x[i * n + j], 1.0 - x[i * n + j]});
    by_distance.emplace_back(d, i);
  }
  std::sort(by_distance.begin(), by_distance.end());
  std::vector<std::uint64_t> out;
  for (std::size_t k = 0; k < by_distance.size() && static_cast<int>(k) < count; ++k) out.push_back(by_distance[k].second);
  return out;
}

Figure8Result run_figure8(const Figure8Config& config, const StageProgress& progress) {
  config.validate();
  Figure8Result result;
  result.config = config;
  result.machine = machine_description();
  for (const AnimationOptions& o : config.runs()) {
    const std::string stage = fmt::format("{}D {}", o.dimension, to_string(o.cnj.domain_mode));
    Stopwatch watch;
    Figure8Run run;
    run.animation = animate(o, config.seed, config.threads, [&](double f) {
      if (progress) progress(stage, f);
    });
    result.seconds.push_back(watch.seconds());
    if (o.dimension == 2) run.tracks = boundary_tracks(run.animation, Figure8Config::kTracks);
    result.runs.push_back(std::move(run));
  }
  return result;
}

std::vector<std::string> figure8_output_files() {
  std::vector<std::string> files = {"figure8_frames.csv", "figure8_tracks.csv", "figure8.md"};
  if (!find_gnuplot().empty()) files.push_back("figure8.png");
  return files;
}

namespace {

struct RunSummary {
  std::uint64_t lo = 0, hi = 0, entered = 0, left = 0, retraced = 0, kept = 0, projected = 0, popping_frames = 0;
  double popping = 0.0, largest_jump = 0.0, mean_rms_move = 0.0;
  std::uint64_t in_layer = 0;  // frames whose largest jump started within the transition width of the boundary
};

// Of frames 1..F-1, those whose largest jump started within the bound's transition width of the cube's
// boundary (the particle's frame k-1 position).
std::uint64_t jumps_in_transition_layer(const AnimationResult& a) {
  const int n = a.options.dimension;
  const double width = std::min(a.options.cnj.boundary_width * a.spacing, 0.25);
  std::uint64_t count = 0;
  for (int k = 1; k < a.options.frames; ++k) {
    const double *before = a.frame(k - 1), *now = a.frame(k);
    double largest = -1.0, distance = 1.0;
    for (std::uint64_t i = 0; i < a.particles; ++i) {
      if (std::isnan(before[i * n]) || std::isnan(now[i * n])) continue;
      double d2 = 0.0, to_boundary = 1.0;
      for (int j = 0; j < n; ++j) {
        d2 += (now[i * n + j] - before[i * n + j]) * (now[i * n + j] - before[i * n + j]);
        to_boundary = std::min({to_boundary, before[i * n + j], 1.0 - before[i * n + j]});
      }
      if (d2 > largest) largest = d2, distance = to_boundary;
    }
    count += largest >= 0.0 && distance <= width;
  }
  return count;
}

RunSummary summarise(const AnimationResult& a) {
  RunSummary s;
  s.in_layer = jumps_in_transition_layer(a);
  s.lo = a.particles;
  double rms_sum = 0.0;
  for (const FrameStats& f : a.frames) {
    s.lo = std::min(s.lo, f.inside);
    s.hi = std::max(s.hi, f.inside);
    s.entered += f.entered;
    s.left += f.left;
    s.retraced += f.retraced;
    s.kept += f.kept_at_start;
    s.projected += f.projected;
    if (f.frame > 0) {
      s.popping_frames += f.entered + f.left > 0;
      s.largest_jump = std::max(s.largest_jump, f.largest_jump);
      rms_sum += f.rms_move;
    }
  }
  s.mean_rms_move = a.frames.size() > 1 ? rms_sum / static_cast<double>(a.frames.size() - 1) : 0.0;
  s.popping = a.popping_per_100_frames();
  return s;
}

}  // namespace

std::string figure8_markdown(const Figure8Result& result) {
  const Figure8Config& c = result.config;
  std::string md = "# Figure 8: curl noise jittering animated, drop mode against the conformant field\n\n";
  md += fmt::format(
      "Made by `dfvn-sample reproduce figure8 --frames {} --phase-step {} --grid-2d {} --grid-3d {} --lattice-3d {} "
      "--drop-margin {} --seed {}`: {} frames (animate's cnj mode: frame k is CNJ's jitter of the start set at phase "
      "alpha_k, traced with a trace map continuous in alpha; {} frame steps of {} rad each, so the "
      "phase turns by {} rad), in the unit square and the unit cube with {} noise at {} cycles per spacing and a CNJ "
      "step scale of {}. Drop mode (the 2023 method) traces a start set reaching {} spacings beyond the domain along the "
      "free field and shows the particles inside; conformant traces the sites inside along the field bounded by "
      "Eq. (13).\n\n",
      c.frames, format_real(c.phase_step, 6), c.grid_2d, c.grid_3d, to_string(c.lattice_3d), c.drop_margin, c.seed, c.frames,
      c.frames - 1, format_real(c.phase_step, 6), format_real(c.phase_step * (c.frames - 1), 6),
      to_string(AnimationOptions::default_cnj().noise), format_real(AnimationOptions::default_cnj().frequency, 3),
      format_real(AnimationOptions::default_cnj().step_scale, 3), c.drop_margin);
  md += "| dim | mode | start lattice | particles | inside per frame (min..max) | entered | left | popping events per 100 "
        "frames | largest jump (spacings) | mean RMS move (spacings) | retraced | kept at start | seconds |\n";
  md += "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  std::string packing =
      "\nThe packing of every frame (frames.csv's nearest-neighbour columns, in each frame's mean spacings) and the "
      "per-frame moves over all frames and particles shown (in frame 0's mean spacings):\n\n"
      "| dim | mode | median NN, frame 0 | median / frame 0's (min..max, mean) | 1% quantile, frame 0 | 1% quantile / "
      "frame 0's (min..max) | median move | 99th percentile move (x median) | largest move (x median) |\n"
      "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  std::vector<RunSummary> summaries;
  for (std::size_t r = 0; r < result.runs.size(); ++r) {
    const AnimationResult& a = result.runs[r].animation;
    const RunSummary s = summarise(a);
    summaries.push_back(s);
    md += fmt::format("| {}D | {} | {} {}^{} | {} | {}..{} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
                      a.options.dimension, to_string(a.options.cnj.domain_mode), to_string(a.options.lattice),
                      a.options.grid, a.options.dimension, a.particles, s.lo, s.hi, s.entered, s.left,
                      format_real(s.popping, 4), format_real(s.largest_jump / a.spacing, 3),
                      format_real(s.mean_rms_move / a.spacing, 3), s.retraced, s.kept,
                      format_real(result.seconds[r], 3));
    const PackingSummary p = summarise_packing(a);
    const MoveSummary& m = a.moves;
    packing += fmt::format("| {}D | {} | {} | {}..{} ({}) | {} | {}..{} | {} | {} ({}x) | {} ({}x) |\n", a.options.dimension,
                           to_string(a.options.cnj.domain_mode), format_real(p.median_0, 3), format_real(p.median_min, 3),
                           format_real(p.median_max, 3), format_real(p.median_mean, 3), format_real(p.q01_0, 3),
                           format_real(p.q01_min, 3), format_real(p.q01_max, 3), format_real(m.median, 3),
                           format_real(m.p99, 3), format_real(m.p99 / m.median, 3), format_real(m.largest, 3),
                           format_real(m.largest / m.median, 3));
  }
  md += packing;
  md += "\n## Reading\n\n";
  for (std::size_t r = 0; r + 1 < result.runs.size(); r += 2) {
    const AnimationResult& drop = result.runs[r].animation;
    const AnimationResult& conf = result.runs[r + 1].animation;
    const RunSummary& d = summaries[r];
    const RunSummary& k = summaries[r + 1];
    const double mean_count = 0.5 * static_cast<double>(d.hi + d.lo);
    md += fmt::format(
        "- **{}D.** Drop mode shows between {} and {} particles per frame (a range of {}, {}% of its middle) and has "
        "{} popping events per 100 frames ({} entered, {} left over {} frame steps; at least one particle popped in {} "
        "of them). The conformant field keeps all {} particles inside in every frame: {} entered, {} left, 0 popping "
        "events ({} trace end(s) outside moved into the domain{}). The median nearest-neighbour "
        "distance of a frame is {}..{} times frame 0's (conformant; drop {}..{}). The two start sets differ: drop "
        "mode's lattice runs on through the boundary, conformant's holds the sites inside only. Largest per-frame "
        "jump: conformant {} spacings, drop {} (a frame lasts {} spacings of RMS motion); in {} of conformant's {} "
        "frame steps (drop: {}) the largest jump started within the transition width ({} spacings) of the boundary, "
        "where Eq. (13)'s blend turns the noise into the boundary function.\n",
        drop.options.dimension, d.lo, d.hi, d.hi - d.lo,
        format_real(100.0 * static_cast<double>(d.hi - d.lo) / mean_count, 3), format_real(d.popping, 4), d.entered,
        d.left, drop.frames.size() - 1, d.popping_frames, conf.particles, k.entered, k.left, k.projected,
        k.retraced > 0 ? fmt::format("; {} retraced with more steps, {} kept at their start", k.retraced, k.kept)
                       : std::string(),
        format_real(summarise_packing(conf).median_min, 3), format_real(summarise_packing(conf).median_max, 3),
        format_real(summarise_packing(drop).median_min, 3), format_real(summarise_packing(drop).median_max, 3),
        format_real(k.largest_jump / conf.spacing, 3), format_real(d.largest_jump / drop.spacing, 3),
        format_real(conf.frame_time / conf.spacing, 3), k.in_layer, conf.frames.size() - 1, d.in_layer,
        format_real(conf.options.cnj.boundary_width, 3));
  }
  md += fmt::format(
      "\nThe counts are in `figure8_frames.csv` (one row per dimension, mode and frame), the tracks of the {} 2D "
      "particles nearest the boundary in frame 0 in `figure8_tracks.csv` (NaN where a particle is outside), the "
      "figure in `figure8.png`. Seconds measured on {}.\n",
      Figure8Config::kTracks, result.machine);
  return md;
}

std::string write_figure8(const Figure8Result& result, const std::function<void(const std::string&)>& log) {
  const std::filesystem::path dir(result.config.out_dir);
  std::string frames = std::string("dimension,mode,lattice,") + kFrameColumns + "\n";
  std::string tracks = "dimension,mode,particle,frame,x0,x1\n";
  for (const Figure8Run& run : result.runs) {
    const AnimationResult& a = run.animation;
    const std::string prefix = fmt::format("{},{},{},", a.options.dimension, to_string(a.options.cnj.domain_mode),
                                           to_string(a.options.lattice));
    for (const FrameStats& s : a.frames) frames += prefix + frame_csv_row(s) + "\n";
    for (std::uint64_t particle : run.tracks)
      for (int k = 0; k < a.options.frames; ++k) {
        const double* x = a.frame(k) + particle * 2;
        tracks += fmt::format("2,{},{},{},{},{}\n", to_string(a.options.cnj.domain_mode), particle, k, format_real(x[0]),
                              format_real(x[1]));
      }
  }
  const std::string md = figure8_markdown(result);
  write_file_atomically((dir / "figure8_frames.csv").string(), frames);
  write_file_atomically((dir / "figure8_tracks.csv").string(), tracks);
  write_file_atomically((dir / "figure8.md").string(), md);
  std::string ids[2];
  for (const Figure8Run& run : result.runs)
    if (run.animation.options.dimension == 2)
      for (std::uint64_t particle : run.tracks) {
        std::string& list = ids[run.animation.options.cnj.domain_mode == DomainMode::drop ? 0 : 1];
        list += fmt::format("{}{}", list.empty() ? "" : " ", particle);
      }
  draw_figure(PlotProgram::figure8, (dir / "figure8.png").string(),
              {(dir / "figure8_frames.csv").string(), (dir / "figure8_tracks.csv").string(), ids[0], ids[1]}, log);
  return md;
}

}  // namespace dfvn

// The files of `dfvn-sample animate` (animate/animation.hpp): frames.npy, frames.csv and, in 2D and 3D,
// trails.csv with its figure animation.png (scripts/animation.gp).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "dfvn/animate/animation.hpp"

namespace dfvn {

// frames.csv's header: FrameStats' fields in order.
inline constexpr const char* kFrameColumns =
    "frame,phase,inside,entered,left,largest_jump,rms_move,retraced,kept_at_start,projected,nn_min,nn_q01,nn_median,"
    "nn_median_scaled";
// One frames.csv row (no newline), reals through format_real.
std::string frame_csv_row(const FrameStats& stats);

// The frames shown in animation.png: up to 4, spread evenly over 0..F-1 (the first and the last
// included), and the trail length in frames behind each.
std::vector<int> strip_frames(int frames);
inline constexpr int kTrailFrames = 24;

// The files write_animation writes for these options (trails.csv and animation.png in 2D and 3D only;
// animation.png only with gnuplot), for the check of the outputs before the run.
std::vector<std::string> animation_output_files(const AnimationOptions& options);

// Writes DIR/frames.npy (float64, shape (F, particles, N), NaN rows for particles outside the domain),
// DIR/frames.csv (one row per frame, kFrameColumns), and in 2D and 3D DIR/trails.csv and, when gnuplot is
// installed, DIR/animation.png (otherwise `log` says how to get it). Each file whole or not at all.
// Throws std::runtime_error when a file cannot be written, PlotError when gnuplot fails.
void write_animation(const std::string& dir, const AnimationResult& result,
                     const std::function<void(const std::string&)>& log);

// A short plain-text summary of the run (printed by the command).
std::string animation_summary(const AnimationResult& result);

}  // namespace dfvn

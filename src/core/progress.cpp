#include "dfvn/core/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "dfvn/core/message_text.hpp"

namespace dfvn {

ProgressMode parse_progress_mode(std::string_view name) {
  if (name == "auto") return ProgressMode::automatic;
  if (name == "always") return ProgressMode::always;
  if (name == "never") return ProgressMode::never;
  throw std::invalid_argument("unknown progress mode " + quote_for_message(name) + " (allowed: auto, always, never)");
}

std::string_view to_string(ProgressMode mode) {
  switch (mode) {
    case ProgressMode::automatic: return "auto";
    case ProgressMode::always: return "always";
    case ProgressMode::never: return "never";
  }
  return "auto";
}

std::string format_duration(double seconds) {
  if (!(seconds >= 0.0)) seconds = 0.0;
  if (seconds < 59.95) return fmt::format("{:.1f} s", seconds);
  const auto whole = static_cast<long long>(std::llround(seconds));
  if (whole < 3600) return fmt::format("{}:{:02}", whole / 60, whole % 60);
  return fmt::format("{}:{:02}:{:02}", whole / 3600, whole / 60 % 60, whole % 60);
}

std::optional<double> estimate_remaining_seconds(double elapsed, double work_done, double work_total) {
  if (!(work_done > 0.0) || !(work_done < work_total) || !(elapsed >= 0.0)) return std::nullopt;
  // The rate is only worth extrapolating once some of the work has been seen.
  if (work_done < 0.01 * work_total && elapsed < 0.5) return std::nullopt;
  const double remaining = elapsed / work_done * (work_total - work_done);
  if (!std::isfinite(remaining) || remaining < 0.05) return std::nullopt;  // would read "0.0 s"
  return remaining;
}

std::string format_progress_line(int stage_index, int stage_count, std::string_view stage, double fraction,
                                 double stage_seconds, double total_seconds, std::optional<double> eta_seconds) {
  fraction = std::clamp(fraction, 0.0, 1.0);
  std::string line = stage_count > 0 ? fmt::format("[{}/{}] ", stage_index, stage_count) : fmt::format("[{}] ", stage_index);
  fmt::format_to(std::back_inserter(line), "{} {:.1f}% (stage {}; elapsed {}", stage, 100.0 * fraction,
                 format_duration(stage_seconds), format_duration(total_seconds));
  if (eta_seconds) fmt::format_to(std::back_inserter(line), ", ETA {}", format_duration(*eta_seconds));
  line += ')';
  return line;
}

ProgressReporter::ProgressReporter(ProgressMode mode, std::FILE* out, bool terminal, std::string prefix,
                                   double interval_seconds, ProgressClock clock)
    : mode_(mode), out_(out), terminal_(terminal), prefix_(std::move(prefix)), interval_(interval_seconds),
      clock_(std::move(clock)) {
  if (!clock_) clock_ = [watch = Stopwatch()] { return watch.seconds(); };
  start_ = stage_start_ = now();
}

ProgressReporter ProgressReporter::on_stderr(ProgressMode mode, std::string prefix) {
  return ProgressReporter(mode, stderr, ::isatty(STDERR_FILENO) == 1, std::move(prefix));
}

ProgressReporter::~ProgressReporter() { finish(); }

void ProgressReporter::set_stage_count(int stages) {
  set_stage_weights(std::vector<double>(static_cast<std::size_t>(std::max(stages, 0)), 1.0));
}

void ProgressReporter::set_stage_weights(std::vector<double> weights) {
  for (double& w : weights)
    if (!(w >= 0.0) || !std::isfinite(w)) w = 0.0;
  weights_ = std::move(weights);
  stage_count_ = static_cast<int>(weights_.size());
  weight_total_ = 0.0;
  for (double w : weights_) weight_total_ += w;
  weight_before_ = 0.0;
  for (int k = 0; k + 1 < stage_index_ && k < stage_count_; ++k) weight_before_ += weights_[static_cast<std::size_t>(k)];
}

void ProgressReporter::report(std::string_view stage, double fraction) {
  if (mode_ == ProgressMode::never) return;
  fraction = std::clamp(std::isfinite(fraction) ? fraction : 0.0, 0.0, 1.0);
  const bool new_stage = stage_index_ == 0 || stage != stage_ || fraction < fraction_;
  if (new_stage) {
    if (stage_index_ >= 1 && stage_index_ <= stage_count_) weight_before_ += weights_[static_cast<std::size_t>(stage_index_ - 1)];
    ++stage_index_;
    stage_.assign(stage);
    stage_start_ = now();
  }
  fraction_ = fraction;
  show(new_stage);
}

StageProgress ProgressReporter::callback() {
  return [this](std::string_view stage, double fraction) { report(stage, fraction); };
}

std::optional<double> ProgressReporter::eta(double now, double stage_seconds) const {
  const double run_seconds = now - start_;
  if (stage_count_ == 0) return estimate_remaining_seconds(stage_seconds, fraction_, 1.0);
  if (stage_index_ > stage_count_ || !(weight_total_ > 0.0)) return std::nullopt;  // more stages than planned
  const double weight = weights_[static_cast<std::size_t>(stage_index_ - 1)];
  if (fraction_ == 0.0) {
    // No progress reported inside this stage yet: the stages before predict its length, at their rate.
    if (!(weight_before_ > 0.0)) return std::nullopt;
    const double predicted = (run_seconds - stage_seconds) / weight_before_ * weight;
    if (stage_seconds > predicted) return std::nullopt;
  }
  return estimate_remaining_seconds(run_seconds, weight_before_ + weight * fraction_, weight_total_);
}

void ProgressReporter::show(bool new_stage) {
  const double time = now();
  const double run_seconds = time - start_;
  const double stage_seconds = time - stage_start_;
  const bool counted = stage_index_ <= stage_count_;
  const std::string line = format_progress_line(stage_index_, counted ? stage_count_ : 0, stage_, fraction_, stage_seconds,
                                                run_seconds, eta(time, stage_seconds));
  if (terminal_) {
    // Ten redraws a second are plenty for the eye and cost nothing next to the work.
    if (!new_stage && run_seconds - last_shown_ < 0.1) return;
    std::fprintf(out_, "\r%s\033[K", line.c_str());
    line_open_ = true;
  } else {
    const bool stage_line = new_stage && mode_ == ProgressMode::always;
    if (!stage_line && run_seconds - last_shown_ < interval_) return;
    std::fprintf(out_, "%s: %s\n", prefix_.c_str(), line.c_str());
  }
  std::fflush(out_);
  last_shown_ = run_seconds;
}

void ProgressReporter::finish() {
  if (line_open_) {
    std::fprintf(out_, "\r\033[K");
    std::fflush(out_);
  }
  line_open_ = false;
}

void ProgressReporter::complete() {
  finish();
  if (mode_ != ProgressMode::always || terminal_ || stage_index_ == 0) return;
  std::fprintf(out_, "%s: done: %d stage%s in %s\n", prefix_.c_str(), stage_index_, stage_index_ == 1 ? "" : "s",
               format_duration(now() - start_).c_str());
  std::fflush(out_);
}

}  // namespace dfvn

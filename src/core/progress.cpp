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

std::string format_progress_line(int stage_index, int stage_count, std::string_view stage, double fraction,
                                 double stage_seconds, double total_seconds) {
  fraction = std::clamp(fraction, 0.0, 1.0);
  std::string line = stage_count > 0 ? fmt::format("[{}/{}] ", stage_index, stage_count) : fmt::format("[{}] ", stage_index);
  fmt::format_to(std::back_inserter(line), "{} {:.1f}% (stage {}", stage, 100.0 * fraction, format_duration(stage_seconds));
  // The rate is only worth extrapolating once some of the stage has been seen.
  if (fraction > 0.0 && fraction < 1.0 && (fraction >= 0.01 || stage_seconds >= 0.5))
    fmt::format_to(std::back_inserter(line), ", ETA {}", format_duration(stage_seconds * (1.0 - fraction) / fraction));
  fmt::format_to(std::back_inserter(line), "; elapsed {})", format_duration(total_seconds));
  return line;
}

ProgressReporter::ProgressReporter(ProgressMode mode, std::FILE* out, bool terminal, std::string prefix,
                                   double interval_seconds)
    : mode_(mode), out_(out), terminal_(terminal), prefix_(std::move(prefix)), interval_(interval_seconds) {}

ProgressReporter ProgressReporter::on_stderr(ProgressMode mode, std::string prefix) {
  return ProgressReporter(mode, stderr, ::isatty(STDERR_FILENO) == 1, std::move(prefix));
}

ProgressReporter::~ProgressReporter() { finish(); }

void ProgressReporter::report(std::string_view stage, double fraction) {
  if (mode_ == ProgressMode::never) return;
  const bool new_stage = stage_index_ == 0 || stage != stage_ || fraction < fraction_;
  if (new_stage) {
    ++stage_index_;
    stage_.assign(stage);
    stage_clock_.restart();
  }
  fraction_ = fraction;
  show(new_stage);
}

StageProgress ProgressReporter::callback() {
  return [this](std::string_view stage, double fraction) { report(stage, fraction); };
}

void ProgressReporter::show(bool new_stage) {
  const double now = total_.seconds();
  const std::string line =
      format_progress_line(stage_index_, stage_count_, stage_, fraction_, stage_clock_.seconds(), now);
  if (terminal_) {
    // Ten redraws a second are plenty for the eye and cost nothing next to the work.
    if (!new_stage && now - last_shown_ < 0.1) return;
    std::fprintf(out_, "\r%s\033[K", line.c_str());
    line_open_ = true;
  } else {
    const bool stage_line = new_stage && mode_ == ProgressMode::always;
    if (!stage_line && now - last_shown_ < interval_) return;
    std::fprintf(out_, "%s: %s\n", prefix_.c_str(), line.c_str());
  }
  std::fflush(out_);
  last_shown_ = now;
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
               format_duration(total_.seconds()).c_str());
  std::fflush(out_);
}

}  // namespace dfvn

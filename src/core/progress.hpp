// Progress of long work: the library reports from inside its loops (points placed, queries done,
// pairs summed), a ProgressReporter decides what, if anything, reaches the user. Reporting never
// changes a result: loops report counts they compute anyway, from one thread, and nothing read back
// from the reporter enters the computation.
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <string_view>

#include "dfvn/core/stopwatch.hpp"

namespace dfvn {

// The fraction of one loop's work that is done, in [0, 1]. Called from one thread at a time.
using FractionProgress = std::function<void(double fraction)>;

// A named stage of a longer run and the fraction of it that is done. A stage ends when the next
// call names another stage, or names the same one with a smaller fraction (the next realization).
using StageProgress = std::function<void(std::string_view stage, double fraction)>;

// `done` of `total` as a fraction for a FractionProgress, calling it about `reports` times over the
// loop (every total / reports units); a loop calls tick(done) as it goes.
class ProgressTicker {
 public:
  ProgressTicker(const FractionProgress& progress, std::uint64_t total, std::uint64_t reports = 200)
      : progress_(progress), total_(total), every_(total / reports > 0 ? total / reports : 1) {}
  bool wanted(std::uint64_t done) const { return progress_ && done % every_ == 0; }
  void tick(std::uint64_t done) const {
    if (wanted(done)) progress_(total_ > 0 ? static_cast<double>(done) / static_cast<double>(total_) : 1.0);
  }

 private:
  const FractionProgress& progress_;
  std::uint64_t total_;
  std::uint64_t every_;
};

// --progress: auto (a live line on a terminal, a plain line every few seconds otherwise), always (also
// a plain line when each stage starts, so even short runs leave a log) or never.
enum class ProgressMode { automatic, always, never };
ProgressMode parse_progress_mode(std::string_view name);  // "auto" | "always" | "never"
std::string_view to_string(ProgressMode mode);

// "4.2 s" below a minute, "2:05" (minutes:seconds) above, "1:02:05" above an hour.
std::string format_duration(double seconds);

// One progress line: "[3/8] pds 41.2% (stage 11.3 s, ETA 16.1 s; elapsed 25.0 s)". `stage_count` 0:
// unknown (then "[3]"). The ETA extrapolates the stage's own rate; it is left out until 1% of the
// stage or half a second has passed.
std::string format_progress_line(int stage_index, int stage_count, std::string_view stage, double fraction,
                                 double stage_seconds, double total_seconds);

// Shows StageProgress reports on a stream: on a terminal one line rewritten in place (at most ten
// times a second), otherwise plain lines prefixed with the program's name, one every `interval`
// seconds while a stage runs (and, with ProgressMode::always, one as each stage starts).
class ProgressReporter {
 public:
  ProgressReporter(ProgressMode mode, std::FILE* out, bool terminal, std::string prefix, double interval_seconds = 5.0);
  // On standard error, a terminal if isatty says so.
  static ProgressReporter on_stderr(ProgressMode mode, std::string prefix);
  ~ProgressReporter();
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  void set_stage_count(int stages) { stage_count_ = stages; }
  void report(std::string_view stage, double fraction);
  // A StageProgress that reports here (it refers to this reporter: keep the reporter alive).
  StageProgress callback();
  // Clears the live line; the next report starts on a clean line.
  void finish();
  // The run is over: clears the live line and, in a log with ProgressMode::always, says how many
  // stages took how long ("done: 8 stages in 59.4 s").
  void complete();

 private:
  void show(bool force);

  ProgressMode mode_;
  std::FILE* out_;
  bool terminal_;
  std::string prefix_;
  double interval_;
  int stage_count_ = 0;
  int stage_index_ = 0;
  std::string stage_;
  double fraction_ = 0.0;
  Stopwatch total_;
  Stopwatch stage_clock_;
  double last_shown_ = 0.0;     // total_ seconds at the last line shown
  bool line_open_ = false;      // a live line is on the terminal
};

}  // namespace dfvn

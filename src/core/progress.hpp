// Progress of long work: the library reports from inside its loops (points placed, queries done,
// pairs summed), a ProgressReporter decides what, if anything, reaches the user. Reporting never
// changes a result: loops report counts they compute anyway, from one thread, and nothing read back
// from the reporter enters the computation.
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

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

// The seconds left of a run of `work_total` units of which `work_done` took `elapsed` seconds:
// elapsed / work_done * (work_total - work_done), the measured rate extrapolated. None (no ETA shown)
// before any work is done, once it is all done, while under 1% is done and under half a second has
// passed (too little to extrapolate), or when the answer would print as "0.0 s".
std::optional<double> estimate_remaining_seconds(double elapsed, double work_done, double work_total);

// One progress line: "[3/8] pds 41.2% (stage 11.3 s; elapsed 25.0 s, ETA 16.1 s)": the 3rd of 8
// stages, the share of that stage done, seconds in it and in the run, and the seconds the whole run
// has left (no ETA when `eta_seconds` is empty). `stage_count` 0: unknown (then "[3]").
std::string format_progress_line(int stage_index, int stage_count, std::string_view stage, double fraction,
                                 double stage_seconds, double total_seconds, std::optional<double> eta_seconds);

// Seconds since an arbitrary start, never decreasing: the reporter's clock (a test injects its own).
using ProgressClock = std::function<double()>;

// Shows StageProgress reports on a stream: on a terminal one line rewritten in place (at most ten
// times a second), otherwise plain lines prefixed with the program's name, one every `interval`
// seconds while a stage runs (and, with ProgressMode::always, one as each stage starts).
//
// The ETA is the whole run's: the stages' expected costs (set_stage_weights; set_stage_count: all
// alike) make the work units, the stages done plus the current one's reported fraction the work
// done, and the elapsed time over the work done the rate (estimate_remaining_seconds). A stage that
// reports no fraction beyond 0 and outlasts what its weight predicts shows no ETA, only its seconds,
// rather than a guess already proven wrong. Without a stage count, the ETA is the current stage's.
class ProgressReporter {
 public:
  ProgressReporter(ProgressMode mode, std::FILE* out, bool terminal, std::string prefix, double interval_seconds = 5.0,
                   ProgressClock clock = {});
  // On standard error, a terminal if isatty says so.
  static ProgressReporter on_stderr(ProgressMode mode, std::string prefix);
  ~ProgressReporter();
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  // The run's stages, all of the same expected cost.
  void set_stage_count(int stages);
  // The run's stages in the order they report and the expected cost of each, in any unit (points,
  // field evaluations, ...); their number is the n of "[k/n]".
  void set_stage_weights(std::vector<double> weights);
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
  double now() const { return clock_(); }
  std::optional<double> eta(double now, double stage_seconds) const;

  ProgressMode mode_;
  std::FILE* out_;
  bool terminal_;
  std::string prefix_;
  double interval_;
  ProgressClock clock_;
  int stage_count_ = 0;
  std::vector<double> weights_;  // expected cost of each stage (stage_count_ of them)
  double weight_total_ = 0.0;
  double weight_before_ = 0.0;   // of the stages before the current one
  int stage_index_ = 0;
  std::string stage_;
  double fraction_ = 0.0;
  double start_ = 0.0;          // clock_ at construction
  double stage_start_ = 0.0;    // clock_ when the current stage began
  double last_shown_ = 0.0;     // run seconds at the last line shown
  bool line_open_ = false;      // a live line is on the terminal
};

}  // namespace dfvn

// The progress reporter: what reaches the stream in each mode, and the line it writes.
#include "dfvn/core/progress.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>

namespace dfvn {
namespace {

// Everything written to a temporary stream.
class Capture {
 public:
  Capture() : file_(std::tmpfile()) {}
  ~Capture() { std::fclose(file_); }
  std::FILE* file() { return file_; }
  std::string text() {
    std::fflush(file_);
    std::rewind(file_);
    std::string out;
    for (int c = std::fgetc(file_); c != EOF; c = std::fgetc(file_)) out += static_cast<char>(c);
    return out;
  }

 private:
  std::FILE* file_;
};

int count_lines(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

TEST(Progress, ParsesModes) {
  EXPECT_EQ(parse_progress_mode("auto"), ProgressMode::automatic);
  EXPECT_EQ(parse_progress_mode("always"), ProgressMode::always);
  EXPECT_EQ(parse_progress_mode("never"), ProgressMode::never);
  EXPECT_THROW(parse_progress_mode("sometimes"), std::invalid_argument);
  EXPECT_EQ(to_string(ProgressMode::automatic), "auto");
}

TEST(Progress, FormatsDurations) {
  EXPECT_EQ(format_duration(0.0), "0.0 s");
  EXPECT_EQ(format_duration(4.24), "4.2 s");
  EXPECT_EQ(format_duration(59.9), "59.9 s");
  EXPECT_EQ(format_duration(125.0), "2:05");
  EXPECT_EQ(format_duration(3725.0), "1:02:05");
  EXPECT_EQ(format_duration(-1.0), "0.0 s");
}

TEST(Progress, LineHasCounterFractionAndEta) {
  EXPECT_EQ(format_progress_line(3, 8, "pds", 0.25, 10.0, 25.0, 30.0), "[3/8] pds 25.0% (stage 10.0 s; elapsed 25.0 s, ETA 30.0 s)");
  EXPECT_EQ(format_progress_line(2, 0, "rdf", 0.5, 1.0, 2.0, 1.0), "[2] rdf 50.0% (stage 1.0 s; elapsed 2.0 s, ETA 1.0 s)");
  EXPECT_EQ(format_progress_line(1, 2, "cnj", 0.0, 0.0, 0.0, std::nullopt), "[1/2] cnj 0.0% (stage 0.0 s; elapsed 0.0 s)");
  EXPECT_EQ(format_progress_line(1, 2, "cnj", 1.5, 3.0, 3.0, 125.0), "[1/2] cnj 100.0% (stage 3.0 s; elapsed 3.0 s, ETA 2:05)");
}

TEST(Progress, RemainingTimeExtrapolatesTheMeasuredRate) {
  // A quarter of the work in 10 s: the other three quarters take 30 s.
  EXPECT_DOUBLE_EQ(*estimate_remaining_seconds(10.0, 25.0, 100.0), 30.0);
  EXPECT_DOUBLE_EQ(*estimate_remaining_seconds(2.0, 0.5, 1.0), 2.0);
  // Nothing done, all done, or too little seen to extrapolate: no estimate.
  EXPECT_FALSE(estimate_remaining_seconds(8.0, 0.0, 1.0));
  EXPECT_FALSE(estimate_remaining_seconds(8.0, 1.0, 1.0));
  EXPECT_FALSE(estimate_remaining_seconds(0.1, 0.001, 1.0));
  EXPECT_TRUE(estimate_remaining_seconds(0.6, 0.001, 1.0));   // half a second is enough
  EXPECT_TRUE(estimate_remaining_seconds(0.01, 0.02, 1.0));   // and so is 1% of the work
  // Never a "0.0 s" ETA while work remains: below 0.05 s it is left out.
  EXPECT_FALSE(estimate_remaining_seconds(1.0, 0.99, 1.0));
  EXPECT_TRUE(estimate_remaining_seconds(10.0, 0.99, 1.0));
}

// A clock the test moves by hand: no sleeping.
struct FakeClock {
  double now = 0.0;
  ProgressClock clock() {
    return [this] { return now; };
  }
};

std::string last_line(const std::string& text) {
  const std::size_t end = text.find_last_of('\n');
  const std::size_t begin = text.find_last_of('\n', end - 1);
  return text.substr(begin == std::string::npos ? 0 : begin + 1, end - (begin == std::string::npos ? 0 : begin + 1));
}

TEST(Progress, EtaIsTheRunsWeightedByStageCost) {
  Capture out;
  FakeClock time;
  ProgressReporter reporter(ProgressMode::automatic, out.file(), false, "prog", 0.0, time.clock());
  // A cheap stage then one nine times as costly (a reference warp): 10 units in all.
  reporter.set_stage_weights({1.0, 9.0});
  reporter.report("cheap", 0.0);
  EXPECT_EQ(last_line(out.text()), "prog: [1/2] cheap 0.0% (stage 0.0 s; elapsed 0.0 s)");
  time.now = 2.0;
  reporter.report("cheap", 0.5);  // half a unit in 2 s: 9.5 units left take 38 s
  EXPECT_EQ(last_line(out.text()), "prog: [1/2] cheap 50.0% (stage 2.0 s; elapsed 2.0 s, ETA 38.0 s)");
  time.now = 4.0;
  reporter.report("costly", 0.0);  // 1 unit in 4 s: 9 left, 36 s
  EXPECT_EQ(last_line(out.text()), "prog: [2/2] costly 0.0% (stage 0.0 s; elapsed 4.0 s, ETA 36.0 s)");
  time.now = 22.0;
  reporter.report("costly", 0.5);  // 5.5 units in 22 s: 4.5 left, 18 s
  EXPECT_EQ(last_line(out.text()), "prog: [2/2] costly 50.0% (stage 18.0 s; elapsed 22.0 s, ETA 18.0 s)");
  time.now = 39.99;
  reporter.report("costly", 0.9999);  // 0.009 s left would read 0.0 s: left out
  EXPECT_EQ(last_line(out.text()), "prog: [2/2] costly 100.0% (stage 36.0 s; elapsed 40.0 s)");
}

TEST(Progress, EqualStagesCountUnitsDone) {
  Capture out;
  FakeClock time;
  ProgressReporter reporter(ProgressMode::automatic, out.file(), false, "prog", 0.0, time.clock());
  reporter.set_stage_count(4);
  for (int k = 0; k < 3; ++k) {
    reporter.report("realization " + std::to_string(k), 0.0);
    time.now += 5.0;
  }
  reporter.report("realization 3", 0.0);  // 3 of 4 in 15 s: 5 s left
  EXPECT_EQ(last_line(out.text()), "prog: [4/4] realization 3 0.0% (stage 0.0 s; elapsed 15.0 s, ETA 5.0 s)");
}

TEST(Progress, AStageWithoutInnerProgressDropsAnEtaItOutlasts) {
  Capture out;
  FakeClock time;
  ProgressReporter reporter(ProgressMode::automatic, out.file(), false, "prog", 0.0, time.clock());
  reporter.set_stage_weights({1.0, 1.0, 1.0});
  reporter.report("first", 0.0);
  time.now = 2.0;
  reporter.report("second", 0.0);  // predicted 2 s
  time.now = 3.0;
  reporter.report("second", 0.0);  // 1 s in: within the prediction, 1 unit in 3 s, 2 left: 6 s
  EXPECT_EQ(last_line(out.text()), "prog: [2/3] second 0.0% (stage 1.0 s; elapsed 3.0 s, ETA 6.0 s)");
  time.now = 10.0;
  reporter.report("second", 0.0);  // 8 s in a stage predicted at 2 s, nothing reported inside it: no ETA
  EXPECT_EQ(last_line(out.text()), "prog: [2/3] second 0.0% (stage 8.0 s; elapsed 10.0 s)");
  // The first stage has nothing before it to predict from.
  Capture first;
  FakeClock t2;
  ProgressReporter alone(ProgressMode::automatic, first.file(), false, "prog", 0.0, t2.clock());
  alone.set_stage_count(2);
  alone.report("only", 0.0);
  t2.now = 8.0;
  alone.report("only", 0.0);
  EXPECT_EQ(last_line(first.text()), "prog: [1/2] only 0.0% (stage 8.0 s; elapsed 8.0 s)");
}

TEST(Progress, MoreStagesThanPlannedDropTheCountAndEta) {
  Capture out;
  FakeClock time;
  ProgressReporter reporter(ProgressMode::automatic, out.file(), false, "prog", 0.0, time.clock());
  reporter.set_stage_count(1);
  reporter.report("a", 0.0);
  time.now = 1.0;
  reporter.report("b", 0.5);
  EXPECT_EQ(last_line(out.text()), "prog: [2] b 50.0% (stage 0.0 s; elapsed 1.0 s)");
}

TEST(Progress, WithoutAStageCountTheEtaIsTheStages) {
  Capture out;
  FakeClock time;
  ProgressReporter reporter(ProgressMode::automatic, out.file(), false, "prog", 0.0, time.clock());
  reporter.report("a", 0.0);
  time.now = 4.0;
  reporter.report("b", 0.0);
  time.now = 6.0;
  reporter.report("b", 0.25);
  EXPECT_EQ(last_line(out.text()), "prog: [2] b 25.0% (stage 2.0 s; elapsed 6.0 s, ETA 6.0 s)");
}

TEST(Progress, AlwaysWritesALineAsEachStageStarts) {
  Capture out;
  {
    ProgressReporter reporter(ProgressMode::always, out.file(), false, "prog", 1e9);
    reporter.set_stage_count(3);
    reporter.report("cnj", 0.0);
    reporter.report("cnj", 0.5);  // same stage: no line before the interval
    reporter.report("cnj statistics", 0.0);
    reporter.report("cnj statistics", 0.7);
    reporter.report("cnj statistics", 0.1);  // a smaller fraction: the next stage (another realization)
    reporter.complete();
  }
  const std::string text = out.text();
  EXPECT_EQ(count_lines(text), 4) << text;
  EXPECT_NE(text.find("prog: done: 3 stages in "), std::string::npos) << text;
  EXPECT_NE(text.find("prog: [1/3] cnj 0.0%"), std::string::npos) << text;
  EXPECT_NE(text.find("prog: [2/3] cnj statistics 0.0%"), std::string::npos) << text;
  EXPECT_NE(text.find("prog: [3/3] cnj statistics 10.0%"), std::string::npos) << text;
  EXPECT_EQ(text.find('\r'), std::string::npos) << "plain lines only when not on a terminal";
}

TEST(Progress, AutoWritesPlainLinesOnlyEveryInterval) {
  Capture quiet, busy;
  {
    ProgressReporter reporter(ProgressMode::automatic, quiet.file(), false, "prog", 1e9);
    for (int k = 0; k <= 100; ++k) reporter.report("pds", k / 100.0);
  }
  EXPECT_EQ(quiet.text(), "");
  {
    ProgressReporter reporter(ProgressMode::automatic, busy.file(), false, "prog", 0.0);  // every report
    reporter.report("pds", 0.0);
    reporter.report("pds", 0.5);
  }
  EXPECT_EQ(count_lines(busy.text()), 2) << busy.text();
}

TEST(Progress, NeverWritesNothing) {
  Capture out;
  {
    ProgressReporter reporter(ProgressMode::never, out.file(), true, "prog", 0.0);
    reporter.report("cnj", 0.0);
    reporter.report("pds", 0.5);
    reporter.finish();
  }
  EXPECT_EQ(out.text(), "");
}

TEST(Progress, TerminalRewritesOneLineAndClearsIt) {
  Capture out;
  {
    ProgressReporter reporter(ProgressMode::automatic, out.file(), true, "prog");
    reporter.report("cnj", 0.0);
    reporter.report("pds", 0.0);
  }
  const std::string text = out.text();
  EXPECT_EQ(text.find('\n'), std::string::npos) << "a live line never scrolls";
  EXPECT_NE(text.find("\r[1] cnj 0.0%"), std::string::npos);
  EXPECT_NE(text.find("\r[2] pds 0.0%"), std::string::npos);
  EXPECT_TRUE(text.ends_with("\r\033[K")) << "finish (the destructor) clears the line";
}

TEST(Progress, TickerReportsAFewTimesOverTheLoop) {
  int calls = 0;
  double last = -1.0;
  const FractionProgress progress = [&](double f) {
    ++calls;
    EXPECT_GT(f, last);
    last = f;
  };
  const ProgressTicker ticker(progress, 1000, 10);
  for (std::uint64_t done = 1; done <= 1000; ++done) ticker.tick(done);
  EXPECT_EQ(calls, 10);
  EXPECT_DOUBLE_EQ(last, 1.0);
}

}  // namespace
}  // namespace dfvn

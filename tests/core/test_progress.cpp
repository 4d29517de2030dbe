// The progress reporter: what reaches the stream in each mode, and the line it writes.
#include "dfvn/core/progress.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
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
  // 25% after 10 s: the remaining 75% at the same rate take 30 s.
  EXPECT_EQ(format_progress_line(3, 8, "pds", 0.25, 10.0, 25.0), "[3/8] pds 25.0% (stage 10.0 s, ETA 30.0 s; elapsed 25.0 s)");
  EXPECT_EQ(format_progress_line(2, 0, "rdf", 0.5, 1.0, 2.0), "[2] rdf 50.0% (stage 1.0 s, ETA 1.0 s; elapsed 2.0 s)");
  // No ETA before anything is done, nor when it is all done.
  EXPECT_EQ(format_progress_line(1, 2, "cnj", 0.0, 0.0, 0.0), "[1/2] cnj 0.0% (stage 0.0 s; elapsed 0.0 s)");
  EXPECT_EQ(format_progress_line(1, 2, "cnj", 1.0, 3.0, 3.0), "[1/2] cnj 100.0% (stage 3.0 s; elapsed 3.0 s)");
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

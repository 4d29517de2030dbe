#include "dfvn/io/atomic_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace dfvn {
namespace {

namespace fs = std::filesystem;

// A fresh folder per test, removed afterwards.
class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("dfvn-atomic-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  static std::string read(const std::string& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
  bool has_temporaries() const {
    for (const auto& entry : fs::directory_iterator(dir_))
      if (entry.path().filename().string().find(".tmp.") != std::string::npos) return true;
    return false;
  }
  fs::path dir_;
};

TEST_F(AtomicFileTest, TargetsAreClassifiedByWhatThePathLeadsTo) {
  EXPECT_EQ(resolve_output_target("-").kind, OutputKind::standard_output);
  EXPECT_EQ(resolve_output_target(path("new.csv")).kind, OutputKind::replace);
  std::ofstream(path("file.csv")) << "x";
  EXPECT_EQ(resolve_output_target(path("file.csv")).kind, OutputKind::replace);
  fs::create_symlink("file.csv", path("link"));
  fs::create_symlink(path("link"), path("link2"));
  const OutputTarget through_links = resolve_output_target(path("link2"));
  EXPECT_EQ(through_links.kind, OutputKind::replace);
  EXPECT_TRUE(fs::equivalent(through_links.path, path("file.csv"))) << through_links.path;
  EXPECT_EQ(resolve_output_target("/dev/null").kind, OutputKind::write_through);
  EXPECT_EQ(resolve_output_target("/dev/stdout").kind, OutputKind::write_through);
  EXPECT_EQ(resolve_output_target("/dev/fd/1").kind, OutputKind::write_through);
  EXPECT_EQ(resolve_output_target("/proc/self/fd/1").kind, OutputKind::write_through);
  ASSERT_EQ(::mkfifo(path("fifo").c_str(), 0600), 0);
  EXPECT_EQ(resolve_output_target(path("fifo")).kind, OutputKind::write_through);
  EXPECT_THROW(resolve_output_target(dir_.string()), std::runtime_error);
  fs::create_symlink("loop-b", path("loop-a"));
  fs::create_symlink("loop-a", path("loop-b"));
  EXPECT_THROW(resolve_output_target(path("loop-a")), std::runtime_error);
}

TEST_F(AtomicFileTest, ASymlinkStaysAndItsTargetIsReplacedWhole) {
  std::ofstream(path("target.csv")) << "old";
  ::chmod(path("target.csv").c_str(), 0640);
  fs::create_symlink("target.csv", path("link.csv"));
  write_file_atomically(path("link.csv"), "new\n");
  EXPECT_TRUE(fs::is_symlink(path("link.csv")));
  EXPECT_EQ(read(path("target.csv")), "new\n");
  EXPECT_EQ(fs::status(path("target.csv")).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  EXPECT_FALSE(has_temporaries());
}

TEST_F(AtomicFileTest, DevicesAreWrittenThroughNotReplaced) {
  write_file_atomically("/dev/null", "discarded\n");
  struct stat status {};
  ASSERT_EQ(::stat("/dev/null", &status), 0);
  EXPECT_TRUE(S_ISCHR(status.st_mode));
  EXPECT_NO_THROW(check_writable("/dev/null"));
}

TEST_F(AtomicFileTest, AnUncommittedOutputLeavesNothing) {
  {
    AtomicOutput out(path("result.csv"));
    out.stream() << "partial";
    EXPECT_TRUE(has_temporaries());
  }
  EXPECT_FALSE(has_temporaries());
  EXPECT_FALSE(fs::exists(path("result.csv")));
  check_writable(path("probe.csv"));
  EXPECT_FALSE(has_temporaries());
}

TEST_F(AtomicFileTest, TwoOutputsOnOneFileAreRefused) {
  std::ofstream(path("a.csv")) << "x";
  fs::create_symlink("a.csv", path("link-to-a"));
  fs::create_hard_link(path("a.csv"), path("hard-a"));
  EXPECT_NO_THROW(check_distinct_outputs({{"--stats", path("a.csv")}, {"--rdf", path("b.csv")}, {"--x", "-"}}));
  EXPECT_THROW(check_distinct_outputs({{"--stats", path("b.csv")}, {"--rdf", (dir_ / "." / "b.csv").string()}}),
               std::invalid_argument);
  EXPECT_THROW(check_distinct_outputs({{"--stats", path("a.csv")}, {"--rdf", path("link-to-a")}}), std::invalid_argument);
  EXPECT_THROW(check_distinct_outputs({{"--stats", path("a.csv")}, {"--rdf", path("hard-a")}}), std::invalid_argument);
  // Written through, nothing is replaced: both may go to /dev/null.
  EXPECT_NO_THROW(check_distinct_outputs({{"--stats", "/dev/null"}, {"--rdf", "/dev/null"}}));
  try {
    check_distinct_outputs({{"--stats", path("b.csv")}, {"--rdf", path("b.csv")}});
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--stats and --rdf"), std::string::npos) << e.what();
  }
}

// Issue 23: one check of a run's outputs for every subcommand (stats --spectrum P -o P.csv wrote the
// statistics over the spectrum): standard output once, no file twice, each writable, and the run's
// folders made only after the outputs are known not to clash.
TEST_F(AtomicFileTest, OneCheckOfARunsOutputs) {
  const auto error_of = [](const std::vector<std::pair<std::string, std::string>>& outputs,
                           const std::vector<std::string>& directories = {}) -> std::string {
    try {
      check_outputs(outputs, directories);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(error_of({{"--output", "-"}, {"--json", path("a.json")}, {"--spectrum (P.csv)", path("P.csv")}}), "");
  EXPECT_EQ(error_of({{"--stats", "-"}, {"--rdf", "-"}}), "--stats - and --rdf - would both write to standard output; send one to a file");
  EXPECT_EQ(error_of({{"the statistics (default --output -)", "-"}, {"--json", "-"}}),
            "the statistics (default --output -) and --json - would both write to standard output; send one to a file");
  const std::string clash = error_of({{"--output", path("P.csv")}, {"--spectrum (P.csv)", (dir_ / "." / "P.csv").string()}});
  EXPECT_NE(clash.find("--output and --spectrum (P.csv) would write the same file"), std::string::npos) << clash;
  // A clash inside a folder the run would create: refused before the folder exists.
  const std::string folder = path("new-folder");
  EXPECT_NE(error_of({{"--stats", path("new-folder/x.csv")}, {"--points (x.csv)", path("new-folder/x.csv")}}, {folder}), "");
  EXPECT_FALSE(fs::exists(folder));
  EXPECT_EQ(error_of({{"--stats", path("new-folder/x.csv")}, {"--points (y.csv)", path("new-folder/y.csv")}}, {folder}), "");
  EXPECT_TRUE(fs::is_directory(folder));
  // Unwritable: a directory in place of a file.
  fs::create_directory(path("taken"));
  EXPECT_NE(error_of({{"--out (table1.csv)", path("taken")}}).find("it is a directory"), std::string::npos);
  EXPECT_FALSE(has_temporaries());
}

}  // namespace
}  // namespace dfvn

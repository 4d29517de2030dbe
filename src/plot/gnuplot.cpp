#include "dfvn/plot/gnuplot.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "dfvn/core/message_text.hpp"
#include "dfvn/io/atomic_file.hpp"
#include "plot_programs.hpp"

extern char** environ;

namespace dfvn {

std::string_view plot_program_name(PlotProgram program) {
  switch (program) {
    case PlotProgram::figure4: return "figure4.gp";
    case PlotProgram::figure5: return "figure5.gp";
    case PlotProgram::integration: return "integration.gp";
    case PlotProgram::cnj_study: return "cnj_study.gp";
    case PlotProgram::spectrum: return "spectrum.gp";
    case PlotProgram::animation: return "animation.gp";
    case PlotProgram::figure8: return "figure8.gp";
    case PlotProgram::curl_obstacle: return "curl_obstacle.gp";
    case PlotProgram::figure6: return "figure6.gp";
    case PlotProgram::figure7: return "figure7.gp";
    case PlotProgram::slope: return "slope.gp";
    case PlotProgram::titled: return "titled.gp";
  }
  return "?";
}

std::string_view plot_program_text(PlotProgram program) {
  switch (program) {
    case PlotProgram::figure4: return kFigure4Program;
    case PlotProgram::figure5: return kFigure5Program;
    case PlotProgram::integration: return kIntegrationProgram;
    case PlotProgram::cnj_study: return kCnjStudyProgram;
    case PlotProgram::spectrum: return kSpectrumProgram;
    case PlotProgram::animation: return kAnimationProgram;
    case PlotProgram::figure8: return kFigure8Program;
    case PlotProgram::curl_obstacle: return kCurlObstacleProgram;
    case PlotProgram::figure6: return kFigure6Program;
    case PlotProgram::figure7: return kFigure7Program;
    case PlotProgram::slope: return kSlopeProgram;
    case PlotProgram::titled: return kTitledProgram;
  }
  return "";
}

std::string find_gnuplot() {
  const char* path = std::getenv("PATH");
  std::string_view dirs = path ? path : "/usr/local/bin:/usr/bin:/bin";  // execvp's default
  while (true) {
    const std::size_t colon = dirs.find(':');
    std::string dir(dirs.substr(0, colon));
    if (dir.empty()) dir = ".";  // an empty PATH entry is the current directory
    const std::string candidate = dir + "/gnuplot";
    struct stat info {};
    if (::stat(candidate.c_str(), &info) == 0 && S_ISREG(info.st_mode) && ::access(candidate.c_str(), X_OK) == 0)
      return candidate;
    if (colon == std::string_view::npos) return "";
    dirs.remove_prefix(colon + 1);
  }
}

namespace {

// The folder for temporary files: $TMPDIR when set, else /tmp (as std::filesystem::temp_directory_path,
// whose own error, "filesystem error: temp_directory_path", names no variable). Throws PlotError
// naming TMPDIR when it is not a directory; `figure` starts the message.
std::filesystem::path temporary_folder(const std::string& figure) {
  const char* variable = std::getenv("TMPDIR");
  const std::string folder = variable && *variable ? variable : "/tmp";
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    throw PlotError(fmt::format("{}: the temporary folder {} ({}) is not a directory; set TMPDIR to a writable directory",
                                figure, quote_for_message(folder, kMaxPathEchoChars),
                                variable && *variable ? "TMPDIR" : "TMPDIR is unset"));
  return folder;
}

// A private directory under the temporary folder, removed with what is in it: by the destructor on
// every return and exception, and by the signal and exit handlers (io/atomic_file.hpp) when the
// program is interrupted or exits from elsewhere. Files made in it are registered with file().
class TemporaryDirectory {
 public:
  explicit TemporaryDirectory(const std::string& figure) {
    std::string pattern = (temporary_folder(figure) / "dfvn-plot-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr)
      throw PlotError(fmt::format("{}: cannot create a temporary directory {} (set TMPDIR to a writable directory): {}",
                                  figure, quote_for_message(pattern, kMaxPathEchoChars), std::strerror(errno)));
    path_ = pattern;
    registrations_.push_back(
        std::make_unique<TemporaryRegistration>(path_.string(), TemporaryRegistration::Kind::directory));
  }
  ~TemporaryDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  // The path of a file `name` in the directory, registered for removal before it exists.
  std::string file(const std::string& name) {
    const std::string path = (path_ / name).string();
    registrations_.push_back(std::make_unique<TemporaryRegistration>(path, TemporaryRegistration::Kind::file));
    return path;
  }

 private:
  std::filesystem::path path_;
  std::vector<std::unique_ptr<TemporaryRegistration>> registrations_;
};

struct ProcessOutcome {
  int status = 0;  // as from waitpid
  std::string output;  // standard output and standard error, interleaved
};

// Runs `executable` with `arguments` (argv[0] included), standard input from /dev/null and standard
// output and error captured. No shell is involved: the arguments reach the program byte for byte.
ProcessOutcome run_capturing(const std::string& executable, const std::vector<std::string>& arguments) {
  int pipe_fds[2];
  if (::pipe2(pipe_fds, O_CLOEXEC) != 0) throw std::runtime_error(fmt::format("cannot create a pipe: {}", std::strerror(errno)));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], 1);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], 2);
  std::vector<char*> argv;
  for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  // The interrupting signals stay blocked from the spawn until the child is registered, so that the
  // handler knows every child it must kill; the child starts with none blocked.
  sigset_t interrupting, previous, none;
  sigemptyset(&interrupting);
  sigemptyset(&none);
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) sigaddset(&interrupting, signal_number);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);
  ::pthread_sigmask(SIG_BLOCK, &interrupting, &previous);
  pid_t pid = 0;
  const int spawn_error = ::posix_spawn(&pid, executable.c_str(), &actions, &attributes, argv.data(), environ);
  std::optional<ChildRegistration> child;
  if (spawn_error == 0) child.emplace(pid);
  ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_fds[1]);
  if (spawn_error != 0) {
    ::close(pipe_fds[0]);
    throw PlotError(fmt::format("cannot run {}: {}", quote_for_message(executable, kMaxPathEchoChars), std::strerror(spawn_error)));
  }
  ProcessOutcome outcome;
  char buffer[4096];
  while (true) {
    const ssize_t n = ::read(pipe_fds[0], buffer, sizeof buffer);
    if (n > 0) {
      outcome.output.append(buffer, static_cast<std::size_t>(n));
    } else if (n == 0 || errno != EINTR) {
      break;
    }
  }
  ::close(pipe_fds[0]);
  // Wait for the exit without reaping, so that the pid cannot be reused while the signal handler may
  // still kill it; then unregister and reap.
  siginfo_t exited{};
  while (::waitid(P_PID, static_cast<id_t>(pid), &exited, WEXITED | WNOWAIT) < 0 && errno == EINTR) {
  }
  child.reset();
  while (::waitpid(pid, &outcome.status, 0) < 0 && errno == EINTR) {
  }
  return outcome;
}

std::vector<std::string> nonempty_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.find_first_not_of(" \t\r^") != std::string::npos) lines.push_back(line);
  return lines;
}

}  // namespace

void check_figure_prerequisites() {
  if (!find_gnuplot().empty()) temporary_folder("cannot draw the figures");
}

bool draw_figure(PlotProgram program, const std::string& output, const std::vector<std::string>& arguments,
                 const std::function<void(const std::string&)>& log) {
  if (arguments.size() > 8) throw std::invalid_argument("draw_figure: gnuplot 5.4 passes at most 9 arguments (ARG1..ARG9)");
  const std::string figure = quote_for_message(output, kMaxPathEchoChars);
  const std::string gnuplot = find_gnuplot();
  if (gnuplot.empty()) {
    log(fmt::format("{} not drawn: gnuplot is not installed (Debian/Ubuntu: apt-get install gnuplot-nox); install it "
                    "and run this command again",
                    figure));
    return false;
  }
  TemporaryDirectory work(figure + " not drawn");
  const std::string name(plot_program_name(program));
  const std::string program_path = work.file(name);
  const std::string png = work.file("figure.png");
  {
    std::ofstream file(program_path, std::ios::binary);
    file << plot_program_text(program);
    if (!file.flush()) throw std::runtime_error(fmt::format("cannot write {}", quote_for_message(program_path, kMaxPathEchoChars)));
  }
  std::vector<std::string> command = {gnuplot, "-c", program_path, png};
  command.insert(command.end(), arguments.begin(), arguments.end());
  const ProcessOutcome outcome = run_capturing(gnuplot, command);
  const std::vector<std::string> lines = nonempty_lines(outcome.output);
  const std::string last = lines.empty() ? "no message" : escape_bytes(lines.back());
  if (!WIFEXITED(outcome.status) || WEXITSTATUS(outcome.status) != 0) {
    const std::string how = WIFEXITED(outcome.status) ? fmt::format("exit status {}", WEXITSTATUS(outcome.status))
                                                      : fmt::format("signal {}", WTERMSIG(outcome.status));
    throw PlotError(fmt::format("{} not drawn: gnuplot ({}) failed with {}: {}", figure, name, how, last));
  }
  std::ifstream drawn(png, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(drawn), std::istreambuf_iterator<char>()};
  if (bytes.empty()) throw PlotError(fmt::format("{} not drawn: gnuplot ({}) wrote no image: {}", figure, name, last));
  for (const std::string& line : lines) log(fmt::format("gnuplot ({}): {}", name, escape_bytes(line)));
  write_file_atomically(output, bytes);
  return true;
}

}  // namespace dfvn

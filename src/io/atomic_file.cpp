#include "dfvn/io/atomic_file.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include "dfvn/core/message_text.hpp"

namespace dfvn {

namespace {

namespace fs = std::filesystem;

std::string quoted_path(const std::string& path) { return quote_for_message(path, kMaxPathEchoChars); }

[[noreturn]] void throw_cannot_write(const std::string& path, const std::string& why) {
  throw std::runtime_error("cannot write " + quoted_path(path) + ": " + why);
}

std::string temporary_name(const std::string& path) { return path + ".tmp." + std::to_string(::getpid()); }

// ---- The registry of live temporaries, read by the signal handler ----
// Fixed storage and lock-free atomics only: a handler may not allocate or lock. A slot is free (0),
// being filled (1) or holds a path to remove (2); `kind` says how.
constexpr int kTemporarySlots = 64;
constexpr std::size_t kMaxTemporaryPath = 4096;
struct TemporarySlot {
  std::atomic<int> state{0};
  TemporaryRegistration::Kind kind = TemporaryRegistration::Kind::file;
  char path[kMaxTemporaryPath];
};
TemporarySlot g_temporaries[kTemporarySlots];
static_assert(std::atomic<int>::is_always_lock_free);
// The child process to kill before removing temporaries (0: none).
std::atomic<pid_t> g_child{0};
static_assert(std::atomic<pid_t>::is_always_lock_free);

// Returns the slot, or -1 when the path is too long or every slot is taken (then only the
// destructor removes the temporary).
int register_temporary(const std::string& path,
                       TemporaryRegistration::Kind kind = TemporaryRegistration::Kind::file) {
  if (path.size() >= kMaxTemporaryPath) return -1;
  for (int i = 0; i < kTemporarySlots; ++i) {
    int expected = 0;
    if (g_temporaries[i].state.compare_exchange_strong(expected, 1)) {
      std::memcpy(g_temporaries[i].path, path.c_str(), path.size() + 1);
      g_temporaries[i].kind = kind;
      g_temporaries[i].state.store(2);
      return i;
    }
  }
  return -1;
}

void unregister_temporary(int slot) {
  if (slot >= 0) g_temporaries[slot].state.store(0);
}

// Unlinks every entry of the directory `path` (its files: a tree's directory holds no folders) and then
// the directory, with system calls only (open, getdents64, unlinkat, rmdir: opendir may allocate). Another
// thread of the program may still be creating a file in it while the handler runs (the signal can arrive
// on any thread), so the directory is emptied again until rmdir succeeds, a bounded number of times.
void remove_directory_tree(const char* path) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;  // not created yet, or gone
    alignas(8) char buffer[8192];
    for (;;) {
      const long bytes = ::syscall(SYS_getdents64, fd, buffer, sizeof buffer);
      if (bytes <= 0) break;
      for (long at = 0; at < bytes;) {
        // struct linux_dirent64: d_ino (8), d_off (8), d_reclen (2), d_type (1), d_name
        unsigned short record = 0;
        std::memcpy(&record, buffer + at + 16, sizeof record);
        const char* name = buffer + at + 19;
        if (!(name[0] == '.' && (name[1] == '\0' || (name[1] == '.' && name[2] == '\0')))) ::unlinkat(fd, name, 0);
        at += record;
      }
    }
    ::close(fd);
    if (::rmdir(path) == 0 || errno == ENOENT) return;
  }
}

// Async-signal-safe throughout: kill, waitpid, unlink, rmdir and remove_directory_tree's calls.
void remove_registered_temporaries() {
  using Kind = TemporaryRegistration::Kind;
  if (const pid_t child = g_child.exchange(0); child > 0) {
    ::kill(child, SIGKILL);
    while (::waitpid(child, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
  for (TemporarySlot& slot : g_temporaries)
    if (slot.state.load() == 2 && slot.kind == Kind::file) ::unlink(slot.path);
  for (TemporarySlot& slot : g_temporaries)
    if (slot.state.load() == 2 && slot.kind == Kind::directory) ::rmdir(slot.path);
  for (TemporarySlot& slot : g_temporaries)
    if (slot.state.load() == 2 && slot.kind == Kind::tree) remove_directory_tree(slot.path);
}

extern "C" void remove_temporaries_and_die(int signal_number) {
  const int saved_errno = errno;
  remove_registered_temporaries();
  errno = saved_errno;
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

// True when the folder of `path`, its links resolved, is in /proc: /dev/stdout leads to
// /proc/self/fd/1, and /dev/fd/1 is in /dev/fd, a link to /proc/self/fd.
bool is_under_proc(const fs::path& path) {
  const fs::path absolute = fs::absolute(path).lexically_normal();
  std::error_code error;
  fs::path folder = fs::weakly_canonical(absolute.parent_path(), error);
  if (error) folder = absolute.parent_path();
  auto part = folder.begin();
  return part != folder.end() && ++part != folder.end() && *part == "proc";
}

}  // namespace

OutputTarget resolve_output_target(const std::string& path) {
  if (path == "-") return {path, OutputKind::standard_output};
  if (path.empty()) throw std::runtime_error("cannot write '': the path is empty");
  fs::path current = path;
  // The kernel allows 40 links in a chain (ELOOP); so do we.
  for (int links = 0; links <= 40; ++links) {
    // /proc/self/fd/N and the like name open files, not places: write through the path as given.
    if (is_under_proc(current)) return {path, OutputKind::write_through};
    struct stat status {};
    if (::lstat(current.c_str(), &status) != 0) {
      if (errno == ENOENT) return {current.string(), OutputKind::replace};
      throw_cannot_write(path, std::strerror(errno));
    }
    if (S_ISLNK(status.st_mode)) {
      std::error_code error;
      fs::path target = fs::read_symlink(current, error);
      if (error) throw_cannot_write(path, error.message());
      current = target.is_absolute() ? target : current.parent_path() / target;
      continue;
    }
    if (S_ISDIR(status.st_mode)) throw_cannot_write(path, "it is a directory");
    if (S_ISREG(status.st_mode)) return {current.string(), OutputKind::replace};
    return {current.string(), OutputKind::write_through};
  }
  throw_cannot_write(path, "too many levels of symbolic links");
}

AtomicOutput::AtomicOutput(std::string path) : path_(std::move(path)), target_(resolve_output_target(path_)) {
  switch (target_.kind) {
    case OutputKind::standard_output:
      return;
    case OutputKind::write_through:
      // Appending leaves devices and FIFOs as they are, and adds after what the shell's redirection
      // already holds when /dev/stdout leads to a file.
      file_.open(target_.path, std::ios::binary | std::ios::app);
      if (!file_) throw_cannot_write(path_, std::strerror(errno));
      return;
    case OutputKind::replace:
      temporary_ = temporary_name(target_.path);
      temporary_slot_ = register_temporary(temporary_);  // before it exists: a signal may come at any time
      file_.open(temporary_, std::ios::binary | std::ios::trunc);
      if (!file_) {
        const int error = errno;
        unregister_temporary(temporary_slot_);
        throw_cannot_write(path_, std::strerror(error));
      }
      return;
  }
}

AtomicOutput::~AtomicOutput() {
  if (target_.kind == OutputKind::replace && !committed_) {
    file_.close();
    std::error_code ignored;
    fs::remove(temporary_, ignored);
    unregister_temporary(temporary_slot_);
  }
}

std::ostream& AtomicOutput::stream() { return target_.kind == OutputKind::standard_output ? std::cout : file_; }

void AtomicOutput::commit() {
  if (target_.kind == OutputKind::standard_output) {
    std::cout.flush();
    if (!std::cout) throw std::runtime_error("cannot write to standard output");
    committed_ = true;
    return;
  }
  file_.flush();
  const bool good = static_cast<bool>(file_);
  file_.close();
  if (!good || file_.fail()) throw_cannot_write(path_, "write error (disk full?)");
  if (target_.kind == OutputKind::write_through) {
    committed_ = true;
    return;
  }
  // A replaced file keeps its permission bits.
  struct stat existing {};
  if (::stat(target_.path.c_str(), &existing) == 0) ::chmod(temporary_.c_str(), existing.st_mode & 07777);
  if (std::rename(temporary_.c_str(), target_.path.c_str()) != 0)
    throw std::runtime_error("cannot rename " + quoted_path(temporary_) + " to " + quoted_path(target_.path) + ": " +
                             std::strerror(errno));
  committed_ = true;
  unregister_temporary(temporary_slot_);
}

void write_file_atomically(const std::string& path, const std::string& text) {
  AtomicOutput out(path);
  out.stream() << text;
  out.commit();
}

void check_writable(const std::string& path) {
  const OutputTarget target = resolve_output_target(path);
  switch (target.kind) {
    case OutputKind::standard_output:
      return;
    case OutputKind::write_through:
      // Not opened: opening a FIFO for writing waits for a reader.
      if (::access(target.path.c_str(), W_OK) != 0) throw_cannot_write(path, std::strerror(errno));
      return;
    case OutputKind::replace: {
      const std::string probe = temporary_name(target.path);
      const int slot = register_temporary(probe);
      std::FILE* f = std::fopen(probe.c_str(), "wb");
      const int error = errno;
      if (f) {
        std::fclose(f);
        std::remove(probe.c_str());
      }
      unregister_temporary(slot);
      if (!f) throw_cannot_write(path, std::strerror(error));
      return;
    }
  }
}

void check_distinct_outputs(const std::vector<std::pair<std::string, std::string>>& outputs) {
  // An existing file is known by its device and inode (so hard links match too), a new one by its
  // canonical path; outputs written through get no identity and never clash.
  std::vector<std::string> identities;
  for (const auto& [option, path] : outputs) {
    const OutputTarget target = resolve_output_target(path);
    struct stat status {};
    std::error_code error;
    if (target.kind != OutputKind::replace)
      identities.emplace_back();
    else if (::stat(target.path.c_str(), &status) == 0)
      identities.push_back(std::to_string(status.st_dev) + ":" + std::to_string(status.st_ino));
    else
      identities.push_back(fs::weakly_canonical(fs::absolute(target.path), error).string());
  }
  for (std::size_t i = 0; i < outputs.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (!identities[i].empty() && identities[i] == identities[j])
        throw std::invalid_argument(outputs[j].first + " and " + outputs[i].first + " would write the same file " +
                                    quoted_path(outputs[i].second) + "; give them different paths");
}

namespace {

// The regular file a path (or "-": the given descriptor) leads to, as device:inode, following symbolic
// links; empty when there is none yet, or when it is not a regular file (a device, a FIFO, a terminal).
std::string existing_file_identity(const std::string& path, int standard_descriptor) {
  struct stat status {};
  const int result = path == "-" ? ::fstat(standard_descriptor, &status) : ::stat(path.c_str(), &status);
  if (result != 0 || !S_ISREG(status.st_mode)) return {};
  return std::to_string(status.st_dev) + ":" + std::to_string(status.st_ino);
}

std::string option_as_given(const std::string& option, const std::string& path) {
  // "the statistics (default --output -)" already says where it goes.
  if (option.ends_with(")")) return option;
  // "--lift npy:" takes its path without a space.
  return option + (option.ends_with(":") ? "" : " ") + (path == "-" ? std::string("-") : quoted_path(path));
}

}  // namespace

void check_outputs_are_not_inputs(const std::vector<std::pair<std::string, std::string>>& outputs,
                                  const std::vector<std::pair<std::string, std::string>>& inputs) {
  std::vector<std::string> input_identities;
  for (const auto& [option, path] : inputs) input_identities.push_back(existing_file_identity(path, STDIN_FILENO));
  for (const auto& [output_option, output_path] : outputs) {
    const std::string identity = existing_file_identity(output_path, STDOUT_FILENO);
    if (identity.empty()) continue;
    for (std::size_t i = 0; i < inputs.size(); ++i)
      if (identity == input_identities[i]) {
        const std::string output = output_path == "-" ? "standard output" : option_as_given(output_option, output_path);
        const std::string input = inputs[i].second == "-" ? "standard input" : option_as_given(inputs[i].first, inputs[i].second);
        throw std::invalid_argument(output + " and " + input +
                                    " are the same file: writing the output would destroy the input; give it another path");
      }
  }
}

void make_output_directory(const std::string& dir) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error || !fs::is_directory(dir)) throw std::runtime_error("cannot create directory " + quoted_path(dir));
  check_writable((fs::path(dir) / "probe").string());
}

void check_outputs(const std::vector<std::pair<std::string, std::string>>& outputs,
                   const std::vector<std::string>& directories,
                   const std::vector<std::pair<std::string, std::string>>& inputs) {
  check_outputs_are_not_inputs(outputs, inputs);
  // Two outputs on one standard output would interleave. "--rdf -" names an option as given; a
  // description in parentheses ("the statistics (default --stats -)") already says it.
  const auto as_given = [](const std::string& option) { return option.ends_with(")") ? option : option + " -"; };
  const std::string* on_stdout = nullptr;
  for (const auto& [option, path] : outputs)
    if (path == "-") {
      if (on_stdout)
        throw std::invalid_argument(as_given(*on_stdout) + " and " + as_given(option) +
                                    " would both write to standard output; send one to a file");
      on_stdout = &option;
    }
  check_distinct_outputs(outputs);
  for (const std::string& dir : directories) make_output_directory(dir);
  for (const auto& [option, path] : outputs) check_writable(path);
}

TemporaryRegistration::TemporaryRegistration(const std::string& path, Kind kind) : slot_(register_temporary(path, kind)) {}

TemporaryRegistration::~TemporaryRegistration() { unregister_temporary(slot_); }

ChildRegistration::ChildRegistration(int pid) { g_child.store(pid); }

ChildRegistration::~ChildRegistration() { g_child.store(0); }

void remove_temporaries_on_signals() {
  struct sigaction action {};
  action.sa_handler = remove_temporaries_and_die;
  sigemptyset(&action.sa_mask);
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) {
    struct sigaction previous {};
    if (::sigaction(signal_number, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN) continue;
    ::sigaction(signal_number, &action, nullptr);
  }
  // std::exit skips destructors of objects on the stack; their temporaries go too.
  std::atexit(remove_registered_temporaries);
}

}  // namespace dfvn

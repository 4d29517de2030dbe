// Output files that appear whole or not at all, without ever destroying what the path leads to.
//
// Where a path leads decides how it is written (resolve_output_target):
//  - "-": standard output;
//  - a regular file, or nothing yet: a temporary beside it (<name>.tmp.<pid>), renamed over it on
//    commit(), so the file is replaced whole or not at all (keeping its permission bits);
//  - a symbolic link (or a chain of them): its final target, written as above; the link stays;
//  - anything else (a character device such as /dev/null or a terminal, a FIFO, a socket), and any
//    path through /proc (/dev/stdout, /dev/fd/N name already open files): written through in place.
//    Such a target cannot be replaced: renaming over /dev/null replaced the machine's /dev/null.
// A temporary is removed when its AtomicOutput is destroyed uncommitted (any error path) and, after
// remove_temporaries_on_signals(), when the process is interrupted (SIGINT, SIGTERM, SIGHUP,
// SIGPIPE), which then dies of that signal as usual (shell status 128 + signal: 130, 143). Other
// temporaries (a work directory) and a child process join the same cleanup by registration.
#pragma once

#include <fstream>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace dfvn {

enum class OutputKind { standard_output, replace, write_through };

struct OutputTarget {
  std::string path;  // where the bytes go: symbolic links resolved, except through /proc
  OutputKind kind = OutputKind::replace;
};

// Throws std::runtime_error (naming the path) for a directory, a symbolic-link loop or a path that
// cannot be examined.
OutputTarget resolve_output_target(const std::string& path);

class AtomicOutput {
 public:
  // Opens the temporary (or the write-through target, or stdout for "-"). Throws std::runtime_error
  // if it cannot be opened, naming the path.
  explicit AtomicOutput(std::string path);
  ~AtomicOutput();  // removes the temporary unless committed
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  std::ostream& stream();
  // Flushes, checks for write errors and renames into place. Throws std::runtime_error on failure.
  void commit();
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  OutputTarget target_;
  std::string temporary_;
  int temporary_slot_ = -1;  // in the registry the signal handler cleans
  std::ofstream file_;
  bool committed_ = false;
};

// Writes `text` to `path` ("-" = standard output) whole or not at all. Throws std::runtime_error.
void write_file_atomically(const std::string& path, const std::string& text);

// Throws std::runtime_error if `path` cannot be written (checked before long computations, so a bad
// path fails fast instead of after minutes of work).
void check_writable(const std::string& path);

// Throws std::invalid_argument when two outputs of one run, given as (option, path), would write the
// same file (through links or different spellings): one would silently replace the other. Outputs
// written through (devices such as /dev/null, FIFOs) may be shared.
void check_distinct_outputs(const std::vector<std::pair<std::string, std::string>>& outputs);

// Creates the directory `dir` with its parents and checks that a file can be written in it. Throws
// std::runtime_error naming it.
void make_output_directory(const std::string& dir);

// Throws std::invalid_argument, naming both options, when an output of a run is one of its inputs (the
// same file by any path: symbolic links, hard links, "./" and ".." spellings, standard output or input
// redirected to it): writing it would destroy the input. Both are (option, path) pairs; "-" is standard
// output among the outputs and standard input among the inputs. Only files that exist can clash (an input
// that does not exist fails when it is read); devices, FIFOs and terminals never clash.
void check_outputs_are_not_inputs(const std::vector<std::pair<std::string, std::string>>& outputs,
                                  const std::vector<std::pair<std::string, std::string>>& inputs);

// The one check of a run's outputs, made by every subcommand before its work starts. `outputs` are
// (option, path) pairs, e.g. {"--json", "run.json"} or {"--spectrum (P.csv)", "P.csv"}; `directories`
// are the folders the run writes into, which are created here once the outputs are known not to clash
// (outputs inside them are checked after); `inputs` are the files the run reads, as (option, path).
// Refuses, with std::invalid_argument naming both options, an output that is an input
// (check_outputs_are_not_inputs), two outputs on standard output ("-") and two on the same file
// (check_distinct_outputs); then creates the directories and checks that each output can be written
// (check_writable). Nothing is created or written before the refusals.
void check_outputs(const std::vector<std::pair<std::string, std::string>>& outputs,
                   const std::vector<std::string>& directories = {},
                   const std::vector<std::pair<std::string, std::string>>& inputs = {});

// Temporaries that library code keeps outside AtomicOutput (the figures' gnuplot work directory and
// its files, sample --stream's bucket folder): while a registration lives, the signal handlers and the
// exit handler of remove_temporaries_on_signals() remove the path: files first, then directories (so a
// directory holding only registered files goes too), then trees. A tree is a directory removed with
// every file in it, registered or not (sample --stream's thousands of bucket files): register it before
// creating it, and it is removed at any moment of its filling. The registration does not create or
// remove anything itself. There are 64 slots: a registration made when all are taken does nothing (its
// owner's destructor still removes the path on ordinary exits).
class TemporaryRegistration {
 public:
  enum class Kind { file, directory, tree };
  TemporaryRegistration(const std::string& path, Kind kind);
  ~TemporaryRegistration();
  TemporaryRegistration(const TemporaryRegistration&) = delete;
  TemporaryRegistration& operator=(const TemporaryRegistration&) = delete;

 private:
  int slot_ = -1;
};

// A child process (gnuplot) that the signal handlers kill (SIGKILL) and reap before they remove the
// temporaries, so that it neither outlives the interrupted program nor writes into a directory being
// removed. At most one child is registered at a time.
class ChildRegistration {
 public:
  explicit ChildRegistration(int pid);
  ~ChildRegistration();
  ChildRegistration(const ChildRegistration&) = delete;
  ChildRegistration& operator=(const ChildRegistration&) = delete;
};

// Installs handlers that delete every live temporary on SIGINT, SIGTERM, SIGHUP and SIGPIPE and then
// die of the signal; signals that are ignored (nohup, background jobs) stay ignored. For programs,
// not for the library to call on its own.
void remove_temporaries_on_signals();

}  // namespace dfvn

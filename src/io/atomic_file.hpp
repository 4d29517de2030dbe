// Output files that appear whole or not at all: written to a temporary name beside the target and
// renamed into place on commit(). "-" means standard output.
#pragma once

#include <fstream>
#include <ostream>
#include <string>

namespace dfvn {

class AtomicOutput {
 public:
  // Opens path + ".tmp.<pid>" (or stdout for "-"). Throws std::runtime_error if it cannot be opened,
  // naming the path.
  explicit AtomicOutput(std::string path);
  ~AtomicOutput();  // removes the temporary file unless committed
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  std::ostream& stream();
  // Flushes, checks for write errors and renames into place. Throws std::runtime_error on failure.
  void commit();
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::string temporary_;
  std::ofstream file_;
  bool to_stdout_ = false;
  bool committed_ = false;
};

// Writes `text` to `path` ("-" = standard output) whole or not at all. Throws std::runtime_error.
void write_file_atomically(const std::string& path, const std::string& text);

// Throws std::runtime_error if a file cannot be created in the folder of path (checked before long
// computations, so a bad path fails fast instead of after minutes of work).
void check_writable(const std::string& path);

}  // namespace dfvn

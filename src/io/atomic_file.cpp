#include "io/atomic_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <unistd.h>

namespace dfvn {

namespace {
std::string temporary_name(const std::string& path) {
  return path + ".tmp." + std::to_string(::getpid());
}
}  // namespace

AtomicOutput::AtomicOutput(std::string path) : path_(std::move(path)) {
  if (path_ == "-") {
    to_stdout_ = true;
    return;
  }
  temporary_ = temporary_name(path_);
  file_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!file_)
    throw std::runtime_error("cannot write '" + path_ + "': " + std::strerror(errno));
}

AtomicOutput::~AtomicOutput() {
  if (!to_stdout_ && !committed_) {
    file_.close();
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
  }
}

std::ostream& AtomicOutput::stream() { return to_stdout_ ? std::cout : file_; }

void AtomicOutput::commit() {
  if (to_stdout_) {
    std::cout.flush();
    if (!std::cout) throw std::runtime_error("cannot write to standard output");
    committed_ = true;
    return;
  }
  file_.flush();
  const bool good = static_cast<bool>(file_);
  file_.close();
  if (!good || file_.fail()) throw std::runtime_error("cannot write '" + path_ + "' (disk full?)");
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0)
    throw std::runtime_error("cannot rename '" + temporary_ + "' to '" + path_ + "': " + std::strerror(errno));
  committed_ = true;
}

void write_file_atomically(const std::string& path, const std::string& text) {
  AtomicOutput out(path);
  out.stream() << text;
  out.commit();
}

void check_writable(const std::string& path) {
  if (path == "-") return;
  if (std::filesystem::is_directory(path)) throw std::runtime_error("cannot write '" + path + "': it is a directory");
  const std::string probe = temporary_name(path);
  std::FILE* f = std::fopen(probe.c_str(), "wb");
  if (!f) throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
  std::fclose(f);
  std::remove(probe.c_str());
}

}  // namespace dfvn

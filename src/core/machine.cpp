#include "dfvn/core/machine.hpp"

#include <fstream>
#include <thread>

#include <fmt/format.h>

namespace dfvn {

std::string machine_description() {
  std::string model = "unknown CPU";
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);) {
    if (line.rfind("model name", 0) != 0) continue;
    const std::size_t colon = line.find(':');
    const std::size_t start = colon == std::string::npos ? std::string::npos : line.find_first_not_of(" \t", colon + 1);
    if (start != std::string::npos) model = line.substr(start);
    break;
  }
  const unsigned threads = std::thread::hardware_concurrency();
  return threads > 0 ? fmt::format("{} ({} hardware threads)", model, threads) : model;
}

}  // namespace dfvn

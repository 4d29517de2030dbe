// The machine a time was measured on, for the reports that quote times.
#pragma once

#include <string>

namespace dfvn {

// "<CPU model> (<n> hardware threads)": the model from /proc/cpuinfo ("model name", or "unknown CPU"
// where there is none), the count from std::thread::hardware_concurrency.
std::string machine_description();

}  // namespace dfvn

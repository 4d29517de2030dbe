// PNG output through libpng.
#pragma once

#include <string>

#include "dfvn/core/image.hpp"

namespace dfvn {

// Writes an 8-bit greyscale PNG, whole or not at all (AtomicOutput). Throws std::runtime_error.
void write_png(const std::string& path, const GrayImage& image);

}  // namespace dfvn

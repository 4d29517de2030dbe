// PNG output through libpng.
#pragma once

#include <string>

#include "dfvn/core/image.hpp"

namespace dfvn {

// Writes an 8-bit greyscale PNG, whole or not at all (AtomicOutput). Throws std::runtime_error.
void write_png(const std::string& path, const GrayImage& image);

// Reads a colour PNG (RGB or RGBA, any bit depth; alpha dropped) as 8-bit RGB. Throws InputError (io/csv.hpp) with
// one line for a file that cannot be read, is no PNG, or is grey (`what` names the option, for the message).
RgbImage read_png_rgb(const std::string& path);

}  // namespace dfvn

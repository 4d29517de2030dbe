// Grey images: the type image warping makes and the PNG writer (io/png.hpp) reads.
#pragma once

#include <cstdint>
#include <vector>

namespace dfvn {

// An 8-bit grey image, row-major, row 0 at the top: for looking at (PNG).
struct GrayImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;
};

// An 8-bit RGB image, row-major, row 0 at the top, three bytes per pixel (R, G, B).
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;
};

// A grey image with values in [0, 1] kept in float, row-major, row 0 at the top: for measuring.
struct FloatImage {
  int width = 0;
  int height = 0;
  std::vector<float> values;
};

}  // namespace dfvn

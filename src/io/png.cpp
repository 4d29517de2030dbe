#include "dfvn/io/png.hpp"

#include <png.h>

#include <stdexcept>
#include <string>

#include "dfvn/io/atomic_file.hpp"
#include "dfvn/io/csv.hpp"

namespace dfvn {

namespace {
void write_to_stream(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::ostream*>(png_get_io_ptr(png));
  out->write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(length));
}
void flush_stream(png_structp png) { static_cast<std::ostream*>(png_get_io_ptr(png))->flush(); }
}  // namespace

void write_png(const std::string& path, const GrayImage& image) {
  AtomicOutput out(path);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error("libpng could not start writing '" + path + "'");
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error("libpng failed writing '" + path + "'");
  }
  png_set_write_fn(png, &out.stream(), write_to_stream, flush_stream);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int row = 0; row < image.height; ++row)
    png_write_row(png, const_cast<png_bytep>(image.pixels.data() + static_cast<std::size_t>(row) * image.width));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  out.commit();
}

RgbImage read_png_rgb(const std::string& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str()))
    throw InputError(std::string("not a readable PNG (") + image.message + ")");
  if (!(image.format & PNG_FORMAT_FLAG_COLOR)) {
    png_image_free(&image);
    throw InputError("a grey PNG: a direction field needs colour (R and G hold the direction)");
  }
  image.format = PNG_FORMAT_RGB;
  RgbImage out{static_cast<int>(image.width), static_cast<int>(image.height), {}};
  out.pixels.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out.pixels.data(), 0, nullptr)) {
    png_image_free(&image);
    throw InputError(std::string("the PNG could not be decoded (") + image.message + ")");
  }
  return out;
}

}  // namespace dfvn

// SPDX-License-Identifier: MIT
// RGB image, line drawing and the PNG writer.

#include "rastrules/io/image.hpp"

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdlib>
#include <cstring>
#include <utility>

#include <png.h>

namespace rastrules::io {

Image::Image(int width, int height, Rgb background)
    : width_(width), height_(height),
      rgb_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3) {
  for (std::size_t i = 0; i < rgb_.size(); i += 3) {
    rgb_[i] = background.r;
    rgb_[i + 1] = background.g;
    rgb_[i + 2] = background.b;
  }
}

Rgb Image::at(int x, int y) const {
  const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                         static_cast<std::size_t>(x)) *
                        3;
  return Rgb{rgb_[i], rgb_[i + 1], rgb_[i + 2]};
}

void Image::set(int x, int y, Rgb c) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_)
    return;
  const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                         static_cast<std::size_t>(x)) *
                        3;
  rgb_[i] = c.r;
  rgb_[i + 1] = c.g;
  rgb_[i + 2] = c.b;
}

void Image::fill_rect(int x0, int y0, int x1, int y1, Rgb c) {
  x0 = std::max(x0, 0);
  y0 = std::max(y0, 0);
  x1 = std::min(x1, width_);
  y1 = std::min(y1, height_);
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x)
      set(x, y, c);
  }
}

void Image::line(double x0, double y0, double x1, double y1, Rgb c, int dash) {
  // Liang-Barsky clipping to the image (with half a pixel of margin), then Bresenham.
  const double lo_x = -0.5, lo_y = -0.5;
  const double hi_x = width_ - 0.5, hi_y = height_ - 0.5;
  const double dx = x1 - x0, dy = y1 - y0;
  double t0 = 0.0, t1 = 1.0;
  const std::pair<double, double> checks[4] = {
      {-dx, x0 - lo_x}, {dx, hi_x - x0}, {-dy, y0 - lo_y}, {dy, hi_y - y0}};
  for (const auto& [p, q] : checks) {
    if (p == 0.0) {
      if (q < 0.0)
        return;
      continue;
    }
    const double t = q / p;
    if (p < 0.0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
    if (t0 > t1)
      return;
  }
  int ax = static_cast<int>(std::lround(x0 + t0 * dx));
  int ay = static_cast<int>(std::lround(y0 + t0 * dy));
  const int bx = static_cast<int>(std::lround(x0 + t1 * dx));
  const int by = static_cast<int>(std::lround(y0 + t1 * dy));
  const int sx = ax < bx ? 1 : -1;
  const int sy = ay < by ? 1 : -1;
  const int ddx = std::abs(bx - ax);
  const int ddy = -std::abs(by - ay);
  int err = ddx + ddy;
  for (int step = 0;; ++step) {
    if (dash <= 0 || (step / dash) % 2 == 0)
      set(ax, ay, c);
    if (ax == bx && ay == by)
      break;
    const int e2 = 2 * err;
    if (e2 >= ddy) {
      err += ddy;
      ax += sx;
    }
    if (e2 <= ddx) {
      err += ddx;
      ay += sy;
    }
  }
}

void Image::disc(int cx, int cy, int r, Rgb c, bool filled) {
  // Integer test x^2 + y^2 <= r^2 (filled) or the ring r^2 - 2r < x^2 + y^2 <= r^2 (hollow).
  const int outer = r * r + r;
  const int inner = (r - 1) * (r - 1) + (r - 1);
  for (int y = -r; y <= r; ++y) {
    for (int x = -r; x <= r; ++x) {
      const int d = x * x + y * y;
      if (d <= outer && (filled || d > inner))
        set(cx + x, cy + y, c);
    }
  }
}

namespace {

struct PngError {
  char message[256];
};

[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
  auto* err = static_cast<PngError*>(png_get_error_ptr(png));
  std::strncpy(err->message, message, sizeof(err->message) - 1);
  err->message[sizeof(err->message) - 1] = '\0';
  png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

// libpng reports errors by longjmp: this frame holds only trivially destructible objects.
bool write_png_rows(std::FILE* out, png_uint_32 width, png_uint_32 height, png_bytepp rows,
                    PngError* err, int color_type = PNG_COLOR_TYPE_RGB) {
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, err, on_png_error, on_png_warning);
  if (png == nullptr) {
    std::strcpy(err->message, "cannot create the PNG writer");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    std::strcpy(err->message, "cannot create the PNG writer");
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, out);
  png_set_IHDR(png, info, width, height, 8, color_type, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

} // namespace

std::optional<std::string> write_png(std::FILE* out, const Image& image) {
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.height()));
  // libpng takes non-const row pointers but does not write through them when writing.
  auto* base = const_cast<std::uint8_t*>(image.rgb().data());
  for (std::size_t y = 0; y < rows.size(); ++y) {
    rows[y] = base + y * static_cast<std::size_t>(image.width()) * 3;
  }
  PngError err{};
  if (!write_png_rows(out, static_cast<png_uint_32>(image.width()),
                      static_cast<png_uint_32>(image.height()), rows.data(), &err)) {
    return std::string("PNG: ") + err.message;
  }
  if (std::fflush(out) != 0 || std::ferror(out) != 0)
    return std::string("PNG: write failed");
  return std::nullopt;
}

std::optional<std::string> write_png_rgba(std::FILE* out, int width, int height,
                                          const std::vector<std::uint8_t>& rgba) {
  if (width < 1 || height < 1 ||
      rgba.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
    return std::string("PNG: the pixel buffer does not match the size");
  }
  std::vector<png_bytep> rows(static_cast<std::size_t>(height));
  auto* base = const_cast<std::uint8_t*>(rgba.data());
  for (std::size_t y = 0; y < rows.size(); ++y) {
    rows[y] = base + y * static_cast<std::size_t>(width) * 4;
  }
  PngError err{};
  if (!write_png_rows(out, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height),
                      rows.data(), &err, PNG_COLOR_TYPE_RGB_ALPHA)) {
    return std::string("PNG: ") + err.message;
  }
  if (std::fflush(out) != 0 || std::ferror(out) != 0)
    return std::string("PNG: write failed");
  return std::nullopt;
}

} // namespace rastrules::io

// SPDX-License-Identifier: MIT
// A small RGB image with the few drawing operations the pictures need, and a PNG writer
// (libpng). Drawing is for people only: no rule decision is ever read back from an image.

#pragma once

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace rastrules::io {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend constexpr bool operator==(const Rgb&, const Rgb&) = default;
};

class Image {
public:
  // Preconditions: width, height >= 1.
  Image(int width, int height, Rgb background);

  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] Rgb at(int x, int y) const;
  // Sets one pixel; pixels outside the image are ignored.
  void set(int x, int y, Rgb c);
  // Fills the rectangle [x0, x1) x [y0, y1), clipped to the image.
  void fill_rect(int x0, int y0, int x1, int y1, Rgb c);
  // Draws a one-pixel line between two points in image coordinates (any values; the line is
  // clipped to the image first). dash > 0 draws dash pixels on, dash pixels off.
  void line(double x0, double y0, double x1, double y1, Rgb c, int dash = 0);
  // Draws a disc of radius r around (cx, cy): filled, or only its one-pixel outline.
  void disc(int cx, int cy, int r, Rgb c, bool filled);
  // Returns the rows, top first, 3 bytes per pixel.
  [[nodiscard]] const std::vector<std::uint8_t>& rgb() const { return rgb_; }

private:
  int width_;
  int height_;
  std::vector<std::uint8_t> rgb_;
};

// Writes the image as an 8-bit RGB PNG. Returns an error message, or nullopt on success.
[[nodiscard]] std::optional<std::string> write_png(std::FILE* out, const Image& image);

// Writes width x height RGBA8 pixels (rows top first, 4 bytes per pixel) as an 8-bit RGBA PNG
// (the resolved target of `rastrules render --resolve`). Returns an error message, or nullopt.
[[nodiscard]] std::optional<std::string> write_png_rgba(std::FILE* out, int width, int height,
                                                        const std::vector<std::uint8_t>& rgba);

} // namespace rastrules::io

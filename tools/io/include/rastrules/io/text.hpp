// SPDX-License-Identifier: MIT
// Text in pictures: a 5x7 bitmap font (digits, letters drawn lower case, punctuation) and a
// function that draws a string on an Image. Used by the fuzzer's panels (titles, legends,
// pixel coordinates), the path ladder's pictures and the precision ladder's plot. For people
// only: no rule decision is read back from a picture.

#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "rastrules/io/image.hpp"

namespace rastrules::io {

// Returns the 7 rows (bit 4 = leftmost column) of the glyph of c (upper-case letters are drawn
// as lower-case ones), or nullopt when the font has none.
[[nodiscard]] std::optional<std::array<std::uint8_t, 7>> glyph(char c);

// Glyph cell size at scale 1: 6 image pixels across (5 and a space), 7 down.
inline constexpr int kGlyphAdvance = 6;
inline constexpr int kGlyphHeight = 7;

// Draws s with its top-left corner at (x, y), each font pixel scale x scale image pixels;
// characters without a glyph are left blank. Pixels outside the image are clipped.
void draw_text(Image& img, int x, int y, std::string_view s, Rgb c, int scale = 1);

// Returns the width in image pixels of s drawn at `scale`.
[[nodiscard]] int text_width(std::string_view s, int scale = 1);

} // namespace rastrules::io

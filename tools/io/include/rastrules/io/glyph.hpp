// SPDX-License-Identifier: MIT
// Glyph outlines of font files through FreeType (outline only: no hinting, no bitmaps), as
// kernel paths (rastrules/path.hpp): so real fonts become test and benchmark corpora for the
// PATH.* rules. FreeType's 26.6 coordinates become raw 16.8 by a factor of 4, exactly; y is
// flipped to point down. Also FreeType's own monochrome and gray rasterizers on the same
// outline, placed the same way, for comparisons (bench/, tests/glyph).
// Implements: PATH.GLYPH.SOURCE, PATH.GLYPH.PLACE, PATH.GLYPH.ERRORS

#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "rastrules/path.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::io {

// The smallest and largest pixel size accepted (PATH.GLYPH.ERRORS).
inline constexpr int kGlyphMinPixelSize = 1;
inline constexpr int kGlyphMaxPixelSize = 4096;

// A glyph placed in its target: the path (raw 16.8, y down) and the target [0, width) x
// [0, height) that holds the outline's control box with a margin of 1 px on every side.
// origin_x, origin_y: where FreeType's origin (the pen position on the baseline) lies, in whole
// pixels of the target; raw = 4 * (26.6 value) + 256 * origin for x, 256 * origin_y - 4 * y for y.
// rule: PATH.GLYPH.SOURCE, PATH.GLYPH.PLACE
struct Glyph {
  path::Path path;
  std::int32_t width = 0;
  std::int32_t height = 0;
  std::int32_t origin_x = 0;
  std::int32_t origin_y = 0;
};

// Why a glyph could not be loaded, in one line ("cannot read font file 'x.ttf' (FreeType error
// 0x02)", "no glyph for U+1F600 in 'x.ttf'", "pixel size 0 outside [1, 4096]", ...).
// rule: PATH.GLYPH.ERRORS
struct GlyphError {
  std::string problem;
  [[nodiscard]] const std::string& what() const { return problem; }
};

// A FreeType bitmap of the glyph in the same target as Glyph: one byte a pixel, row by row (y
// down), 0 or 1 for mono, 0..255 for gray.
struct GlyphBitmap {
  std::int32_t width = 0;
  std::int32_t height = 0;
  std::vector<std::uint8_t> pixels;
  [[nodiscard]] std::uint8_t at(std::int32_t x, std::int32_t y) const {
    return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(x)];
  }
};

// A glyph loaded once: its path and FreeType's outline, moved to the target's placement, so
// that FreeType's rasterizers can run again and again on it (benchmarks). Not copyable.
// rule: PATH.GLYPH.SOURCE
class FreeTypeGlyph {
public:
  ~FreeTypeGlyph();
  FreeTypeGlyph(const FreeTypeGlyph&) = delete;
  FreeTypeGlyph& operator=(const FreeTypeGlyph&) = delete;
  FreeTypeGlyph(FreeTypeGlyph&&) noexcept;
  FreeTypeGlyph& operator=(FreeTypeGlyph&&) noexcept;

  [[nodiscard]] const Glyph& glyph() const;
  // FreeType's monochrome rasterizer (FT_Outline_Get_Bitmap into an FT_PIXEL_MODE_MONO bitmap,
  // its dropout control and boundary rule) and its gray (antialiased, 256 levels) rasterizer on
  // the outline; `out` is reused between calls (no allocation once sized).
  void render_mono(GlyphBitmap& out) const;
  void render_gray(GlyphBitmap& out) const;
  // FreeType's work alone, for timing: clears the glyph's own bitmap and renders into it;
  // returns its rows, top first (mono: packed, (width + 7) / 8 bytes a row, bit 7 leftmost;
  // gray: width bytes a row). Valid until the next call.
  const std::uint8_t* raster_mono() const;
  const std::uint8_t* raster_gray() const;
  // The number of the font's outline points (FreeType's n_points) and the FreeType version.
  [[nodiscard]] int outline_points() const;
  [[nodiscard]] static std::string freetype_version();

  struct Impl;

private:
  friend std::variant<FreeTypeGlyph, GlyphError> load_freetype_glyph(const std::string&, char32_t,
                                                                     int);
  friend std::variant<FreeTypeGlyph, GlyphError> freetype_outline_of(const Glyph&);
  explicit FreeTypeGlyph(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// Loads the glyph of Unicode code point `code_point` of the font file at `pixel_size` px
// (FT_Set_Pixel_Sizes(0, pixel_size), FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP): lines, conic
// arcs as quadratics (implied on-points included, as FT_Outline_Decompose gives them), cubics
// as cubics; FT_OUTLINE_EVEN_ODD_FILL gives evenodd, otherwise nonzero.
// rule: PATH.GLYPH.SOURCE, PATH.GLYPH.PLACE, PATH.GLYPH.ERRORS
[[nodiscard]] std::variant<FreeTypeGlyph, GlyphError>
load_freetype_glyph(const std::string& font_file, char32_t code_point, int pixel_size);

// FreeType's outline of any path in its target (lines, quadratics as conic arcs, cubics;
// evenodd as FT_OUTLINE_EVEN_ODD_FILL), so that FreeType's rasterizers fill exactly the path the
// kernel fills: every coordinate must be a multiple of 4 raw (a 26.6 value); otherwise an
// error naming the first point that is not. g.origin_x and g.origin_y are not used.
// rule: PATH.GLYPH.PLACE
[[nodiscard]] std::variant<FreeTypeGlyph, GlyphError> freetype_outline_of(const Glyph& g);

// The same, the path and its target only.
// rule: PATH.GLYPH.SOURCE
[[nodiscard]] std::variant<Glyph, GlyphError> load_glyph(const std::string& font_file,
                                                         char32_t code_point, int pixel_size);

// The glyph as a scene of one path primitive in its target, with the glyph's fill rule and the
// coverage asked for: every control point as the float32 raw / 256, exact (|raw| < 2^24) and
// snapped back to raw by SNAP.VERTEX.ROUND (what `rastrules glyph` writes).
// rule: PATH.GLYPH.SOURCE
[[nodiscard]] Scene glyph_scene(const Glyph& g, path::Coverage coverage);

} // namespace rastrules::io

// SPDX-License-Identifier: MIT
// Properties: glyph outlines through FreeType (rastrules/io/glyph.hpp) over random printable
// characters, sizes and the two fonts (DejaVu Sans: quadratics; Nimbus Sans: cubics). The path
// has FreeType's contours, every point of FreeType's outline at exactly 4 x its 26.6 value
// inside the target with a margin of 1 px; sizes outside [1, 4096] and characters the font does
// not have are one-line errors; and the kernel's sample coverage of a glyph equals the oracle's.
// Implements (properties for): PATH.GLYPH.SOURCE, PATH.GLYPH.PLACE, PATH.GLYPH.ERRORS,
//   PATH.COVER.SAMPLE

#include <cstdint>
#include <string>
#include <variant>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "glyph_support.hpp"
#include "rastrules/io/glyph.hpp"

namespace {

namespace kp = rastrules::path;
using rastrules::io::Glyph;
using rastrules::io::GlyphError;

std::string any_font() {
  return *rc::gen::element(std::string(RASTRULES_FONT_DEJAVU), std::string(RASTRULES_FONT_CUBIC));
}

char32_t any_printable() {
  return static_cast<char32_t>(*rc::gen::inRange(0x21, 0x7F));
}

// A random printable character of a random font at a size in [1, max_size], loaded (it must
// load).
struct Drawn {
  std::string font;
  char32_t c = 0;
  int size = 0;
  Glyph glyph;
};

Drawn any_glyph(int max_size) {
  Drawn d{any_font(), any_printable(), *rc::gen::inRange(1, max_size + 1), {}};
  auto r = rastrules::io::load_glyph(d.font, d.c, d.size);
  RC_ASSERT(std::holds_alternative<Glyph>(r));
  d.glyph = std::get<Glyph>(r);
  return d;
}

// rule: PATH.GLYPH.SOURCE, PATH.GLYPH.PLACE
RC_GTEST_PROP(GlyphProps, PathIsFreeTypesOutlineTimesFourInsideItsTarget, ()) {
  const Drawn d = any_glyph(400);
  const auto o = rastrules::glyph_support::read_freetype_outline(d.font, d.c, d.size);
  RC_ASSERT(rastrules::glyph_support::outline_mismatch(d.glyph, o) == "");
}

// rule: PATH.GLYPH.ERRORS
RC_GTEST_PROP(GlyphProps, BadSizesAndMissingGlyphsAreOneLineErrors, ()) {
  const std::string font = any_font();
  const int size = *rc::gen::oneOf(rc::gen::inRange(-100000, 1), rc::gen::inRange(4097, 1000000));
  auto r = rastrules::io::load_glyph(font, any_printable(), size);
  RC_ASSERT(std::holds_alternative<GlyphError>(r));
  RC_ASSERT(std::get<GlyphError>(r).what() ==
            "pixel size " + std::to_string(size) + " outside [1, 4096]");
  // Plane 15 is private use: neither font has a glyph there.
  const auto cp = static_cast<char32_t>(*rc::gen::inRange(0xF0000, 0xFFFFE));
  auto m = rastrules::io::load_glyph(font, cp, *rc::gen::inRange(1, 4097));
  RC_ASSERT(std::holds_alternative<GlyphError>(m));
  const std::string e = std::get<GlyphError>(m).what();
  RC_ASSERT(e.rfind("no glyph for U+", 0) == 0);
  RC_ASSERT(e.find('\n') == std::string::npos);
}

// rule: PATH.COVER.SAMPLE
RC_GTEST_PROP(GlyphProps, KernelSamplesEqualOracleOnGlyphs, ()) {
  const Drawn d = any_glyph(20);
  const std::uint32_t samples = *rc::gen::element(1u, 4u);
  const std::string diff = rastrules::glyph_support::mask_difference(d.glyph, samples);
  RC_ASSERT(diff == "");
}

} // namespace

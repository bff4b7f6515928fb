// SPDX-License-Identifier: MIT
// Examples: glyph outlines of real fonts through FreeType (rastrules/io/glyph.hpp): contours
// and their orientation, quadratics and cubics, coordinates exactly 4 x FreeType's 26.6, the
// placement in the target, and one-line errors for a bad file, a missing glyph and bad sizes.
// Tests: PATH.GLYPH.SOURCE, PATH.GLYPH.PLACE, PATH.GLYPH.ERRORS

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>
#include <variant>

#include <gtest/gtest.h>

#include "glyph_support.hpp"
#include "rastrules/io/glyph.hpp"
#include "rastrules/path.hpp"

namespace {

namespace kp = rastrules::path;
namespace gs = rastrules::glyph_support;
using rastrules::io::Glyph;
using rastrules::io::GlyphError;

using rastrules::glyph_support::kCubic;
using rastrules::glyph_support::kDejaVu;

std::string error_of(const std::string& font, char32_t c, int size) {
  auto r = rastrules::io::load_glyph(font, c, size);
  if (const auto* e = std::get_if<GlyphError>(&r))
    return e->what();
  return "";
}

// Twice the signed area of the contour's control polygon (closed), raw units: > 0 for a
// clockwise contour on screen (y down), w = +1 inside by PATH.WINDING.
double twice_area(const kp::Contour& c) {
  double a = 0;
  kp::Point prev = c.start;
  const auto add = [&](kp::Point q) {
    a += static_cast<double>(prev.x) * q.y - static_cast<double>(q.x) * prev.y;
    prev = q;
  };
  for (const kp::Segment& s : c.segments) {
    for (int i = 0; i < gs::points_of(s); ++i)
      add(s.p[static_cast<std::size_t>(i)]);
  }
  add(c.start);
  return a;
}

int count_kind(const kp::Path& p, kp::SegmentKind k) {
  int n = 0;
  for (const auto& c : p.contours)
    for (const auto& s : c.segments)
      n += s.kind == k ? 1 : 0;
  return n;
}

// rule: PATH.GLYPH.SOURCE
TEST(Glyph, DejaVuOHasTwoContoursOfOppositeOrientation) {
  const Glyph g = gs::load_or_fail(kDejaVu, U'o', 32);
  ASSERT_EQ(g.path.contours.size(), 2u);
  EXPECT_EQ(g.path.fill_rule, kp::FillRule::kNonZero); // TrueType: nonzero
  const double a0 = twice_area(g.path.contours[0]), a1 = twice_area(g.path.contours[1]);
  EXPECT_LT(a0 * a1, 0.0) << a0 << " " << a1; // the hole runs the other way: w = 0 inside it
  EXPECT_GT(count_kind(g.path, kp::SegmentKind::kQuadratic), 0);
  EXPECT_EQ(count_kind(g.path, kp::SegmentKind::kCubic), 0);
  // The hole's centre is not covered under nonzero; the ring left of the hole is.
  const kp::Contour& hole = std::abs(a0) < std::abs(a1) ? g.path.contours[0] : g.path.contours[1];
  const kp::Contour& ring = std::abs(a0) < std::abs(a1) ? g.path.contours[1] : g.path.contours[0];
  const auto box = [](const kp::Contour& c) {
    std::int32_t x0 = c.start.x, x1 = c.start.x, y0 = c.start.y, y1 = c.start.y;
    for (const auto& s : c.segments)
      for (int i = 0; i < gs::points_of(s); ++i) {
        const kp::Point q = s.p[static_cast<std::size_t>(i)];
        x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y),
        y1 = std::max(y1, q.y);
      }
    return std::array<std::int32_t, 4>{x0, y0, x1, y1};
  };
  const auto h = box(hole), r = box(ring);
  const std::int32_t my = (h[1] + h[3]) / 2;
  EXPECT_FALSE(
      kp::covers_sample(g.path, {(h[0] + h[2]) / 2, my}, rastrules::FillConvention::kTopLeft));
  EXPECT_TRUE(
      kp::covers_sample(g.path, {(h[0] + r[0]) / 2, my}, rastrules::FillConvention::kTopLeft));
}

// rule: PATH.GLYPH.SOURCE
TEST(Glyph, DejaVuLIsOneContourOfLines) {
  const Glyph g = gs::load_or_fail(kDejaVu, U'l', 24);
  ASSERT_EQ(g.path.contours.size(), 1u);
  EXPECT_EQ(count_kind(g.path, kp::SegmentKind::kCubic), 0);
  EXPECT_GE(g.path.contours[0].segments.size(), 3u);
}

// rule: PATH.GLYPH.SOURCE
TEST(Glyph, Type1GlyphHasCubics) {
  const Glyph g = gs::load_or_fail(kCubic, U'S', 40);
  ASSERT_FALSE(g.path.contours.empty());
  EXPECT_GT(count_kind(g.path, kp::SegmentKind::kCubic), 0);
  EXPECT_EQ(count_kind(g.path, kp::SegmentKind::kQuadratic), 0);
}

// Every point of FreeType's outline (on-curve points and controls) is a point of the path at
// exactly 4 x its 26.6 value, moved by whole pixels and flipped; FreeType's own outline is read
// here independently of glyph.cpp.
// rule: PATH.GLYPH.SOURCE, PATH.GLYPH.PLACE
TEST(Glyph, CoordinatesAreExactlyFourTimesFreeTypes) {
  for (const auto& [font, c] : {std::pair{kDejaVu, U'g'}, std::pair{kDejaVu, U'@'},
                                std::pair{kCubic, U'g'}, std::pair{kCubic, U'&'}}) {
    const Glyph g = gs::load_or_fail(font, c, 37);
    const auto o = rastrules::glyph_support::read_freetype_outline(font, c, 37);
    EXPECT_EQ(rastrules::glyph_support::outline_mismatch(g, o), "")
        << "U+" << static_cast<unsigned>(c) << " in " << font;
    EXPECT_FALSE(o.points.empty());
    // Unhinted outlines use the whole 26.6 grid: the mapping keeps what 16.8 / 4 would lose.
    int odd_sixty_fourths = 0;
    for (const auto& q : o.points)
      odd_sixty_fourths += q[0] % 4 != 0 ? 1 : 0;
    EXPECT_GT(odd_sixty_fourths, 0);
  }
}

// rule: PATH.GLYPH.PLACE
TEST(Glyph, SpaceIsAnEmptyPathInATwoPixelTarget) {
  const Glyph g = gs::load_or_fail(kDejaVu, U' ', 16);
  EXPECT_TRUE(g.path.contours.empty());
  EXPECT_EQ(g.width, 2);
  EXPECT_EQ(g.height, 2);
}

// rule: PATH.GLYPH.ERRORS
TEST(Glyph, MissingCodePointIsAnError) {
  EXPECT_EQ(error_of(kDejaVu, 0x10FFFD, 16), "no glyph for U+10FFFD in '" + kDejaVu + "'");
  EXPECT_EQ(error_of(kDejaVu, 0x110000, 16), "no glyph for U+110000 in '" + kDejaVu + "'");
}

// rule: PATH.GLYPH.ERRORS
TEST(Glyph, BadFileIsAnError) {
  EXPECT_EQ(error_of("/nonexistent/font.ttf", U'a', 16)
                .rfind("cannot read font file '/nonexistent/font.ttf' (FreeType error 0x", 0),
            0u);
  const std::string junk = testing::TempDir() + "rastrules_glyph_junk.ttf";
  {
    std::ofstream out(junk, std::ios::binary);
    out << "this is not a font, just some bytes\n";
  }
  const std::string e = error_of(junk, U'a', 16);
  EXPECT_EQ(e.rfind("cannot read font file '" + junk + "' (FreeType error 0x", 0), 0u) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos);
  std::remove(junk.c_str());
}

// rule: PATH.GLYPH.ERRORS
TEST(Glyph, SizeOutsideTheRangeIsAnError) {
  EXPECT_EQ(error_of(kDejaVu, U'a', 0), "pixel size 0 outside [1, 4096]");
  EXPECT_EQ(error_of(kDejaVu, U'a', 4097), "pixel size 4097 outside [1, 4096]");
  EXPECT_EQ(error_of(kDejaVu, U'a', -3), "pixel size -3 outside [1, 4096]");
  EXPECT_EQ(error_of(kDejaVu, U'W', 4096), ""); // the largest size loads
  EXPECT_EQ(error_of(kDejaVu, U'.', 1), "");
}

} // namespace

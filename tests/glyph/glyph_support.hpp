// SPDX-License-Identifier: MIT
// Shared by tests/glyph and properties/glyph: loading a glyph in a test, FreeType's outline read
// independently of glyph.cpp and compared with the path, a kernel path as the oracle's plain
// integers, and the difference of the kernel's and the oracle's sample masks of a glyph.

#pragma once

#include <array>
#include <cstdint>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include "rastrules/io/glyph.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/oracle/msaa.hpp"
#include "rastrules/oracle/path.hpp"
#include "rastrules/path.hpp"

namespace rastrules::glyph_support {

// The fonts of the tests (tools/io/CMakeLists.txt: RASTRULES_FONT_DEJAVU, _CUBIC).
inline const std::string kDejaVu = RASTRULES_FONT_DEJAVU;
inline const std::string kCubic = RASTRULES_FONT_CUBIC;

namespace kp = rastrules::path;
namespace op = rastrules::oracle::path;
using rastrules::io::Glyph;
using rastrules::io::GlyphError;

// The glyph, or an empty one after a test failure naming the error.
inline Glyph load_or_fail(const std::string& font, char32_t c, int size) {
  auto r = rastrules::io::load_glyph(font, c, size);
  if (const auto* e = std::get_if<GlyphError>(&r))
    ADD_FAILURE() << e->what();
  return std::holds_alternative<Glyph>(r) ? std::get<Glyph>(r) : Glyph{};
}

// The number of points a segment uses (1, 2 or 3: the rest of s.p is unused).
inline int points_of(const kp::Segment& s) {
  return s.kind == kp::SegmentKind::kLine ? 1 : s.kind == kp::SegmentKind::kQuadratic ? 2 : 3;
}

// FreeType's unhinted outline of the glyph, read here without glyph.cpp: its points (26.6, y
// up), contour count and even-odd flag; ok = false when FreeType failed.
struct FreeTypeOutline {
  bool ok = false;
  std::vector<std::array<std::int64_t, 2>> points;
  std::size_t contours = 0;
  bool evenodd = false;
};

inline FreeTypeOutline read_freetype_outline(const std::string& font, char32_t c, int size) {
  FreeTypeOutline out;
  FT_Library lib = nullptr;
  if (FT_Init_FreeType(&lib) != 0)
    return out;
  FT_Face face = nullptr;
  if (FT_New_Face(lib, font.c_str(), 0, &face) == 0) {
    if (FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(size)) == 0 &&
        FT_Load_Char(face, c, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) == 0) {
      const FT_Outline& o = face->glyph->outline;
      for (int i = 0; i < o.n_points; ++i)
        out.points.push_back({o.points[i].x, o.points[i].y});
      out.contours = static_cast<std::size_t>(o.n_contours);
      out.evenodd = (o.flags & FT_OUTLINE_EVEN_ODD_FILL) != 0;
      out.ok = true;
    }
    FT_Done_Face(face);
  }
  FT_Done_FreeType(lib);
  return out;
}

// "" when every point of FreeType's outline is a point of the path at exactly 4 x its 26.6
// value (moved by whole pixels, y flipped), inside the target with a margin of 1 px, and the
// contours and the fill rule are FreeType's; otherwise what differs.
inline std::string outline_mismatch(const Glyph& g, const FreeTypeOutline& o) {
  if (!o.ok)
    return "FreeType could not load the glyph";
  std::set<std::pair<std::int64_t, std::int64_t>> points;
  for (const auto& ct : g.path.contours) {
    points.insert({ct.start.x, ct.start.y});
    for (const auto& s : ct.segments)
      for (int i = 0; i < points_of(s); ++i)
        points.insert({s.p[static_cast<std::size_t>(i)].x, s.p[static_cast<std::size_t>(i)].y});
  }
  std::string bad;
  for (std::size_t i = 0; i < o.points.size(); ++i) {
    const std::int64_t x = 4 * o.points[i][0] + 256 * std::int64_t{g.origin_x};
    const std::int64_t y = 256 * std::int64_t{g.origin_y} - 4 * o.points[i][1];
    if (points.count({x, y}) == 0)
      bad += "point " + std::to_string(i) + " missing; ";
    if (x < 256 || x > 256 * std::int64_t{g.width - 1} || y < 256 ||
        y > 256 * std::int64_t{g.height - 1})
      bad += "point " + std::to_string(i) + " outside the 1 px margin; ";
  }
  if (g.path.contours.size() != o.contours)
    bad += "contours " + std::to_string(g.path.contours.size()) + " vs FreeType's " +
           std::to_string(o.contours) + "; ";
  if ((g.path.fill_rule == kp::FillRule::kEvenOdd) != o.evenodd)
    bad += "fill rule differs; ";
  return bad;
}

// The kernel's path as the oracle's plain integers.
inline op::Path to_oracle(const kp::Path& p) {
  op::Path o;
  o.fill_rule = p.fill_rule == kp::FillRule::kEvenOdd ? "evenodd" : "nonzero";
  for (const kp::Contour& c : p.contours) {
    op::Contour oc;
    oc.start = {c.start.x, c.start.y};
    for (const kp::Segment& s : c.segments) {
      op::Piece q;
      const int n = s.kind == kp::SegmentKind::kLine        ? 1
                    : s.kind == kp::SegmentKind::kQuadratic ? 2
                                                            : 3;
      q.kind = n == 1   ? op::PieceKind::kLine
               : n == 2 ? op::PieceKind::kQuadratic
                        : op::PieceKind::kCubic;
      for (int i = 0; i < n; ++i)
        q.to.push_back({s.p[static_cast<std::size_t>(i)].x, s.p[static_cast<std::size_t>(i)].y});
      oc.pieces.push_back(q);
    }
    o.contours.push_back(oc);
  }
  return o;
}

// Compares the kernel's and the oracle's masks; returns "" or the first differences.
inline std::string mask_difference(const Glyph& g, std::uint32_t samples) {
  const auto kernel = kp::cover_samples(g.path, rastrules::standard_pattern(samples),
                                        rastrules::FillConvention::kTopLeft, g.width, g.height);
  const auto oracle =
      op::cover_samples(to_oracle(g.path), rastrules::oracle::msaa::standard_pattern(samples),
                        "top-left", g.width, g.height);
  std::ostringstream out;
  std::size_t i = 0, j = 0;
  int shown = 0;
  while ((i < kernel.size() || j < oracle.size()) && shown < 5) {
    const bool take_k =
        j == oracle.size() ||
        (i < kernel.size() &&
         (kernel[i].y < oracle[j].y || (kernel[i].y == oracle[j].y && kernel[i].x < oracle[j].x)));
    const bool take_o =
        i == kernel.size() ||
        (j < oracle.size() &&
         (oracle[j].y < kernel[i].y || (oracle[j].y == kernel[i].y && oracle[j].x < kernel[i].x)));
    if (take_k) {
      out << "kernel only (" << kernel[i].x << ", " << kernel[i].y << ") ";
      ++i, ++shown;
    } else if (take_o) {
      out << "oracle only (" << oracle[j].x << ", " << oracle[j].y << ") ";
      ++j, ++shown;
    } else {
      if (kernel[i].mask != oracle[j].mask) {
        out << "(" << kernel[i].x << ", " << kernel[i].y << ") kernel " << kernel[i].mask
            << " oracle " << oracle[j].mask << " ";
        ++shown;
      }
      ++i, ++j;
    }
  }
  return out.str();
}

} // namespace rastrules::glyph_support

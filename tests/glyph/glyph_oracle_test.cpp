// SPDX-License-Identifier: MIT
// Examples: glyphs of real fonts as a corpus for the path rules. The kernel's sample coverage
// (rastrules/path.hpp) equals the exact oracle's (rastrules/oracle/path.hpp) on glyphs of DejaVu
// Sans (quadratics) and Nimbus Sans (cubics) at a few sizes, with 1 and 4 samples a pixel, and
// the kernel's exact areas equal the oracle's on a glyph of lines only.
// Tests: PATH.COVER.SAMPLE, PATH.CURVE.SAMPLE, PATH.AREA.EXACT, PATH.GLYPH.SOURCE

#include <cstdint>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "glyph_support.hpp"
#include "rastrules/io/glyph.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/oracle/msaa.hpp"
#include "rastrules/oracle/path.hpp"
#include "rastrules/path.hpp"

namespace {

namespace kp = rastrules::path;
namespace op = rastrules::oracle::path;
using rastrules::io::Glyph;

using rastrules::glyph_support::kCubic;
using rastrules::glyph_support::kDejaVu;

using rastrules::glyph_support::load_or_fail;
using rastrules::glyph_support::mask_difference;
using rastrules::glyph_support::to_oracle;

// rule: PATH.COVER.SAMPLE, PATH.CURVE.SAMPLE
TEST(GlyphCorpus, KernelSamplesEqualOracleOnDejaVu) {
  int covered = 0;
  for (const int size : {9, 17})
    for (const char32_t c : {U'o', U'g', U'&', U'@'}) {
      const Glyph g = load_or_fail(kDejaVu, c, size);
      EXPECT_EQ(mask_difference(g, 1), "") << "U+" << static_cast<unsigned>(c) << " at " << size;
      covered +=
          static_cast<int>(kp::cover_samples(g.path, rastrules::standard_pattern(1),
                                             rastrules::FillConvention::kTopLeft, g.width, g.height)
                               .size());
    }
  EXPECT_GT(covered, 150); // the glyphs are not empty
  // Four samples a pixel on one glyph.
  EXPECT_EQ(mask_difference(load_or_fail(kDejaVu, U'a', 14), 4), "");
}

// rule: PATH.COVER.SAMPLE, PATH.CURVE.SAMPLE
TEST(GlyphCorpus, KernelSamplesEqualOracleOnType1Cubics) {
  for (const int size : {10, 19})
    for (const char32_t c : {U'S', U'&'}) {
      const Glyph g = load_or_fail(kCubic, c, size);
      EXPECT_EQ(mask_difference(g, 1), "") << "U+" << static_cast<unsigned>(c) << " at " << size;
    }
  EXPECT_EQ(mask_difference(load_or_fail(kCubic, U'e', 13), 4), "");
}

// A glyph of lines only: the kernel's exact areas equal the oracle's arrangement.
// rule: PATH.AREA.EXACT
TEST(GlyphCorpus, KernelAreasEqualOracleOnALinesOnlyGlyph) {
  for (const char32_t c : {U'k', U'#'}) {
    const Glyph g = load_or_fail(kDejaVu, c, 15);
    for (const auto& ct : g.path.contours)
      for (const auto& s : ct.segments)
        ASSERT_EQ(s.kind, kp::SegmentKind::kLine) << "U+" << static_cast<unsigned>(c);
    const auto kernel = kp::cover_area(g.path, g.width, g.height);
    const auto oracle = op::cover_area(to_oracle(g.path), g.width, g.height);
    ASSERT_EQ(kernel.size(), oracle.size()) << "U+" << static_cast<unsigned>(c);
    for (std::size_t i = 0; i < kernel.size(); ++i) {
      EXPECT_EQ(kernel[i].x, oracle[i].x);
      EXPECT_EQ(kernel[i].y, oracle[i].y);
      EXPECT_EQ(kernel[i].area.str(),
                oracle[i].num + (oracle[i].den == "1" ? "" : "/" + oracle[i].den));
    }
  }
}

} // namespace

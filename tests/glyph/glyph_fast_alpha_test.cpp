// SPDX-License-Identifier: MIT
// Examples: the 8-bit alpha of real glyphs' curved outlines (DejaVu Sans quadratics, Nimbus Sans
// cubics) by the certified floating-point cells of PATH.AREA.FAST, and by the certified sweep of
// PATH.AREA.SWEEP in front of them, equals the exact methods' (PATH.AREA.CURVE's alpha where
// its interval decides it); the fast cells decide nearly every row (sharp corners between
// curves and lines, extrema on grid lines, half-covered pixels beside curves), the sweep nearly
// every row too.
// Tests: PATH.AREA.FAST, PATH.AREA.SWEEP, PATH.AREA.ALPHA

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "glyph_support.hpp"
#include "path_detail.hpp"
#include "rastrules/path.hpp"

namespace {

namespace kp = rastrules::path;
namespace kd = rastrules::path::detail;
namespace gs = rastrules::glyph_support;
using Rational = boost::multiprecision::cpp_rational;

struct Count {
  std::size_t rows = 0, fast = 0, swept = 0;
};

// Every pixel's fast alpha lies in the alphas of [A - E, A + E] of cover_area.
void check_glyphs(const std::string& font, const std::u32string& text, int size, Count& n) {
  for (const char32_t ch : text) {
    const rastrules::io::Glyph g = gs::load_or_fail(font, ch, size);
    const auto w = static_cast<std::size_t>(g.width), h = static_cast<std::size_t>(g.height);
    std::vector<std::uint8_t> lo(w * h, 0), hi(w * h, 0), alpha(w * h, 7);
    for (const kp::AreaCoverage& a : kp::cover_area(g.path, g.width, g.height)) {
      const std::size_t at = static_cast<std::size_t>(a.y) * w + static_cast<std::size_t>(a.x);
      lo[at] = kd::alpha_of(std::clamp<Rational>(a.area - a.error_bound, 0, 1));
      hi[at] = kd::alpha_of(std::clamp<Rational>(a.area + a.error_bound, 0, 1));
    }
    n.rows += h;
    for (const kd::AreaMethod m : {kd::AreaMethod::kFast, kd::AreaMethod::kSweep}) {
      kd::AreaRows rows;
      std::fill(alpha.begin(), alpha.end(), std::uint8_t{7});
      kd::cover_alpha_by(g.path, g.width, g.height, m, alpha, &rows);
      n.fast += m == kd::AreaMethod::kFast ? rows.fast : 0;
      n.swept += rows.swept;
      for (std::size_t at = 0; at < alpha.size(); ++at)
        ASSERT_TRUE(alpha[at] >= lo[at] && alpha[at] <= hi[at])
            << font << " U+" << static_cast<std::uint32_t>(ch) << " at " << size << " px, pixel ("
            << at % w << ", " << at / w << "), " << (m == kd::AreaMethod::kFast ? "fast" : "sweep")
            << ": " << int{alpha[at]} << ", exact " << int{lo[at]} << ".." << int{hi[at]};
    }
  }
}

// rule: PATH.AREA.FAST, PATH.AREA.SWEEP, PATH.AREA.ALPHA
TEST(GlyphFastAlpha, EqualsTheExactAlphaOnDejaVuAndNimbus) {
  const std::u32string text = U"@&69eRSgw";
  Count dejavu, nimbus;
  for (const int size : {12, 40}) {
    check_glyphs(gs::kDejaVu, text, size, dejavu);
    check_glyphs(gs::kCubic, text, size, nimbus);
  }
  // Nearly every row by the fast cells (a row left to the exact methods costs them 10-100 ms).
  EXPECT_GE(dejavu.fast * 100, dejavu.rows * 98) << dejavu.fast << " of " << dejavu.rows;
  EXPECT_GE(nimbus.fast * 100, nimbus.rows * 98) << nimbus.fast << " of " << nimbus.rows;
  // And nearly every row by the sweep in front of them (PATH.AREA.SWEEP; 380 of 390 and 376 of
  // 383 rows when this was written: it leaves a row with a pixel of more than two chains, or of
  // a chain turning back at a sharp joint, mostly at 12 px).
  EXPECT_GE(dejavu.swept * 100, dejavu.rows * 95) << dejavu.swept << " of " << dejavu.rows;
  EXPECT_GE(nimbus.swept * 100, nimbus.rows * 95) << nimbus.swept << " of " << nimbus.rows;
}

} // namespace

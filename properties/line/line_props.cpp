// SPDX-License-Identifier: MIT
// Aliased lines: the kernel equals the exact oracle in both profiles on random and tie-heavy
// lines; strips equal their sequence of lines; whole-pixel translation; Vulkan with end points
// on pixel centres is textbook Bresenham without the last pixel; pixels come in travel order;
// the explanation agrees with the decision.
// Implements (properties for): LINE.D3D.EXIT, LINE.D3D.TEST_AREA, LINE.VK.EXIT,
//   LINE.VK.TEST_AREA, LINE.DIAMOND.GEOMETRY, LINE.MAJOR.AXIS, LINE.ZERO_LENGTH,
//   LINE.TARGET.CLIP, LINE.STRIP.SEQUENCE, LINE.INVARIANCE.TRANSLATION,
//   LINE.VK.BRESENHAM_CENTRES, LINE.ORDER.TRAVEL

#include <algorithm>
#include <array>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "line_gen.hpp"
#include "rastrules/line.hpp"
#include "rastrules/line_aliased.hpp"
#include "rastrules/oracle/line.hpp"

namespace {

namespace lg = rastrules::linegen;
using rastrules::LineMode;
using Px = std::array<std::int32_t, 2>;

std::vector<Px> kernel_pixels(rastrules::Vec2 a, rastrules::Vec2 b, LineMode mode, std::int32_t w,
                              std::int32_t h) {
  std::vector<Px> out;
  rastrules::rasterize_aliased_line(a, b, mode, w, h, [&](std::int32_t x, std::int32_t y) {
    out.push_back({x, y});
  });
  return out;
}

std::vector<Px> by_row(std::vector<Px> v) {
  std::sort(v.begin(), v.end(),
            [](const Px& p, const Px& q) { return p[1] != q[1] ? p[1] < q[1] : p[0] < q[0]; });
  return v;
}

std::string show(const std::vector<Px>& v) {
  std::ostringstream os;
  for (const Px& p : v)
    os << "(" << p[0] << "," << p[1] << ") ";
  return os.str();
}

void classify(const lg::RawLine& l) {
  const lg::Ties t = lg::ties(l);
  RC_TAG(l.kind);
  RC_CLASSIFY(t.zero_length, "zero length");
  RC_CLASSIFY(t.forty_five, "exactly 45 degrees");
  RC_CLASSIFY(t.axis_aligned, "axis-aligned");
  RC_CLASSIFY(t.start_on_centre || t.end_on_centre, "end point on a pixel centre");
  RC_CLASSIFY(t.end_on_corner, "end point on a diamond corner");
  RC_CLASSIFY(t.through_corner, "passes through a diamond corner");
  RC_CLASSIFY(t.outside, "partly outside the target");
}

void check_against_oracle(const lg::RawLine& l, LineMode mode) {
  classify(l);
  const auto kernel =
      by_row(kernel_pixels(lg::start(l), lg::end(l), mode, lg::kTarget, lg::kTarget));
  const auto oracle = rastrules::oracle::aliased_line_pixels(
      lg::ostart(l), lg::oend(l), std::string(rastrules::to_string(mode)), lg::kTarget,
      lg::kTarget);
  if (kernel != oracle) {
    RC_FAIL("kernel " + show(kernel) + "\noracle " + show(oracle));
  }
}

// rule: LINE.D3D.EXIT, LINE.D3D.TEST_AREA, LINE.DIAMOND.GEOMETRY, LINE.MAJOR.AXIS, LINE.ZERO_LENGTH, LINE.TARGET.CLIP
RC_GTEST_PROP(LineD3D, KernelEqualsExactOracleOnRandomAndTieHeavyLines, ()) {
  check_against_oracle(*lg::any_line(), LineMode::kD3DDiamond);
}

// rule: LINE.VK.EXIT, LINE.VK.TEST_AREA, LINE.DIAMOND.GEOMETRY, LINE.ZERO_LENGTH, LINE.TARGET.CLIP
RC_GTEST_PROP(LineVulkan, KernelEqualsExactOracleOnRandomAndTieHeavyLines, ()) {
  check_against_oracle(*lg::any_line(), LineMode::kVulkanBresenham);
}

// rule: LINE.STRIP.SEQUENCE
RC_GTEST_PROP(LineStrip, StripEqualsTheSequenceOfIndependentLines, ()) {
  const LineMode mode = *rc::gen::element(LineMode::kD3DDiamond, LineMode::kVulkanBresenham);
  const auto n = *rc::gen::weightedOneOf<std::size_t>(
      {{1, rc::gen::inRange<std::size_t>(0, 2)}, {6, rc::gen::inRange<std::size_t>(2, 7)}});
  std::vector<rastrules::Vec2> vs;
  for (std::size_t i = 0; i < n; ++i) {
    const auto p = *rc::gen::oneOf(rc::gen::apply(
                                       [](std::int64_t x, std::int64_t y) {
                                         return std::array<std::int64_t, 2>{x, y};
                                       },
                                       lg::coord(), lg::coord()),
                                   lg::diamond_point());
    vs.push_back(lg::vec(p[0], p[1]));
  }
  std::vector<Px> strip, lines;
  rastrules::rasterize_aliased_line_strip(vs, mode, lg::kTarget, lg::kTarget,
                                          [&](std::int32_t x, std::int32_t y) {
                                            strip.push_back({x, y});
                                          });
  for (std::size_t i = 0; i + 1 < vs.size(); ++i) {
    const auto seg = kernel_pixels(vs[i], vs[i + 1], mode, lg::kTarget, lg::kTarget);
    lines.insert(lines.end(), seg.begin(), seg.end());
  }
  RC_CLASSIFY(vs.size() < 2, "fewer than two vertices");
  RC_ASSERT(strip == lines);
}

// rule: LINE.INVARIANCE.TRANSLATION
RC_GTEST_PROP(LineInvariance, WholePixelTranslationMovesPixelsExactly, ()) {
  const LineMode mode = *rc::gen::element(LineMode::kD3DDiamond, LineMode::kVulkanBresenham);
  // Lines near the small target (not the partly-outside family, which reaches beyond kBig).
  const lg::RawLine l = *rc::gen::weightedOneOf<lg::RawLine>({{2, lg::random_line()},
                                                              {2, lg::through_diamond_point()},
                                                              {2, lg::along_edge()},
                                                              {1, lg::between_diamond_points()},
                                                              {1, lg::axis_aligned()}});
  const auto i = *rc::gen::inRange<std::int64_t>(-3, 4);
  const auto j = *rc::gen::inRange<std::int64_t>(-3, 4);
  // A target large enough that neither line is clipped: 16 + 2 + 3 pixels margin on each side,
  // with the origin moved so that all coordinates stay non-negative.
  constexpr std::int64_t kShift = 64 * 256;
  constexpr std::int32_t kBig = 16 + 2 * 64 + 8;
  const auto a0 = lg::vec(l.ax + kShift, l.ay + kShift), b0 = lg::vec(l.bx + kShift, l.by + kShift);
  const auto a1 = lg::vec(l.ax + kShift + 256 * i, l.ay + kShift + 256 * j);
  const auto b1 = lg::vec(l.bx + kShift + 256 * i, l.by + kShift + 256 * j);
  auto moved = kernel_pixels(a0, b0, mode, kBig, kBig);
  for (Px& p : moved) {
    p[0] = static_cast<std::int32_t>(p[0] + i);
    p[1] = static_cast<std::int32_t>(p[1] + j);
  }
  RC_ASSERT(moved == kernel_pixels(a1, b1, mode, kBig, kBig));
}

// Textbook Bresenham between pixel centres (x0, y0) -> (x1, y1), last pixel not drawn, with
// ties (the line's y exactly on a row boundary at a column centre) broken as
// LINE.VK.BRESENHAM_CENTRES says: x-major to the row below for positive slope and above for
// negative slope; y-major to the column on the left. Integer only; written independently.
std::vector<Px> textbook_bresenham(std::int64_t x0, std::int64_t y0, std::int64_t x1,
                                   std::int64_t y1, int& ties) {
  std::vector<Px> out;
  ties = 0;
  const std::int64_t dx = x1 - x0, dy = y1 - y0;
  const bool x_major = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
  const std::int64_t n = x_major ? (dx < 0 ? -dx : dx) : (dy < 0 ? -dy : dy);
  const std::int64_t dm = x_major ? dx : dy, dn = x_major ? dy : dx;
  const std::int64_t m0 = x_major ? x0 : y0, n0 = x_major ? y0 : x0;
  const std::int64_t sm = dm > 0 ? 1 : -1;
  for (std::int64_t i = 0; i < n; ++i) {
    // Minor centre coordinate in half-pixels: 2 n0 + 1 + 2 i dn / |dm|; the pixel is
    // floor((2 n0 + 1) / 2 + i dn / |dm|). With err = 2 i dn + |dm| (2 n0 + 1) over 2 |dm|:
    const std::int64_t adm = dm < 0 ? -dm : dm;
    const std::int64_t num = adm * (2 * n0 + 1) + 2 * i * dn; // twice the centre, times |dm|
    const std::int64_t den = 2 * adm;
    std::int64_t q = num / den;
    std::int64_t r = num % den;
    if (r < 0) {
      r += den;
      --q;
    }
    if (r == 0) { // exactly on a boundary between pixel q - 1 and q
      ++ties;
      const bool to_lower = x_major ? (dy * dx > 0) : false;
      if (!to_lower)
        --q;
    }
    const std::int64_t m = m0 + sm * i;
    out.push_back(x_major ? Px{static_cast<std::int32_t>(m), static_cast<std::int32_t>(q)}
                          : Px{static_cast<std::int32_t>(q), static_cast<std::int32_t>(m)});
  }
  return out;
}

// rule: LINE.VK.BRESENHAM_CENTRES
RC_GTEST_PROP(LineVulkan, EndPointsOnPixelCentresGiveBresenhamWithoutTheLastPixel, ()) {
  constexpr std::int32_t kSize = 24;
  const auto x0 = *rc::gen::inRange<std::int64_t>(0, kSize);
  const auto y0 = *rc::gen::inRange<std::int64_t>(0, kSize);
  const auto x1 = *rc::gen::inRange<std::int64_t>(0, kSize);
  const auto y1 = *rc::gen::inRange<std::int64_t>(0, kSize);
  const auto kernel = kernel_pixels(lg::vec(256 * x0 + 128, 256 * y0 + 128),
                                    lg::vec(256 * x1 + 128, 256 * y1 + 128),
                                    LineMode::kVulkanBresenham, kSize, kSize);
  int ties = 0;
  const auto expected = textbook_bresenham(x0, y0, x1, y1, ties);
  RC_CLASSIFY(x0 == x1 && y0 == y1, "zero length");
  RC_CLASSIFY(ties > 0, "line passes exactly between two pixel centres (tie)");
  RC_CLASSIFY(std::abs(x1 - x0) == std::abs(y1 - y0), "exactly 45 degrees");
  if (kernel != expected)
    RC_FAIL("kernel " + show(kernel) + "\nbresenham " + show(expected));
}

// rule: LINE.ORDER.TRAVEL
RC_GTEST_PROP(LineOrder, PixelsComeInTheOrderTheLineTravels, ()) {
  const LineMode mode = *rc::gen::element(LineMode::kD3DDiamond, LineMode::kVulkanBresenham);
  const lg::RawLine l = *lg::any_line();
  const auto px = kernel_pixels(lg::start(l), lg::end(l), mode, lg::kTarget, lg::kTarget);
  const bool x_major = rastrules::is_x_major(lg::start(l), lg::end(l));
  const std::int64_t sm = x_major ? (l.bx > l.ax ? 1 : -1) : (l.by > l.ay ? 1 : -1);
  const std::int64_t sn = x_major ? (l.by >= l.ay ? 1 : -1) : (l.bx >= l.ax ? 1 : -1);
  for (std::size_t k = 1; k < px.size(); ++k) {
    const std::int64_t m0 = x_major ? px[k - 1][0] : px[k - 1][1],
                       m1 = x_major ? px[k][0] : px[k][1];
    const std::int64_t n0 = x_major ? px[k - 1][1] : px[k - 1][0],
                       n1 = x_major ? px[k][1] : px[k][0];
    RC_ASSERT((m1 - m0) * sm > 0 || (m1 == m0 && (n1 - n0) * sn > 0));
  }
}

// rule: LINE.D3D.EXIT, LINE.VK.EXIT
RC_GTEST_PROP(LineExplain, ExplanationAgreesWithTheDecision, ()) {
  const LineMode mode = *rc::gen::element(LineMode::kD3DDiamond, LineMode::kVulkanBresenham);
  const lg::RawLine l = *lg::any_line();
  const auto px = *rc::gen::inRange<std::int32_t>(0, lg::kTarget);
  const auto py = *rc::gen::inRange<std::int32_t>(0, lg::kTarget);
  const auto d = rastrules::explain_aliased_line_pixel(lg::start(l), lg::end(l), mode, px, py);
  RC_ASSERT(d.covered == rastrules::aliased_line_covers(lg::start(l), lg::end(l), mode, px, py));
  RC_ASSERT(d.covered ==
            rastrules::oracle::aliased_line_covers(
                lg::ostart(l), lg::oend(l), std::string(rastrules::to_string(mode)), px, py));
  RC_ASSERT(!d.reason.empty());
  // Entering requires meeting the closed diamond somewhere.
  if (d.entered)
    RC_ASSERT(d.met_features != 0u);
}

} // namespace

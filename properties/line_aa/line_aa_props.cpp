// SPDX-License-Identifier: MIT
// Antialiased lines: the kernel's fixed-point coverage against the exact oracle (within
// LINE.AA.PRECISION), the fragment set against the oracle's exact "coverage > 0", and the
// invariances the rule implies (whole-pixel translation, reversal, mirrors), on random and
// tie-heavy lines; the 8-bit blend against its exact value.
// Implements (properties for): LINE.AA.RECT, LINE.AA.COVERAGE, LINE.AA.FRAGMENT,
//   LINE.AA.ZERO_LENGTH, LINE.AA.PRECISION, LINE.AA.TRAVERSAL, LINE.AA.INVARIANCE, LINE.AA.BLEND

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "rastrules/fixed.hpp"
#include "rastrules/line.hpp"
#include "rastrules/line_aa.hpp"
#include "rastrules/oracle/line_aa.hpp"

namespace {

using Raw = std::array<std::int64_t, 2>;

constexpr std::int32_t kW = 10;
constexpr std::int32_t kH = 10;

struct AALine {
  std::string kind;
  Raw a;
  Raw b;
};

rastrules::Vec2 v2(const Raw& r) {
  return rastrules::Vec2{rastrules::Subpixel::from_raw(static_cast<std::int32_t>(r[0])),
                         rastrules::Subpixel::from_raw(static_cast<std::int32_t>(r[1]))};
}

std::string show(const AALine& l) {
  return l.kind + " a=(" + std::to_string(l.a[0]) + "," + std::to_string(l.a[1]) + ") b=(" +
         std::to_string(l.b[0]) + "," + std::to_string(l.b[1]) + ") raw";
}

// A coordinate near the target: [-3, kW + 3) px, in raw 16.8 units.
rc::Gen<std::int64_t> near_coord() {
  return rc::gen::inRange<std::int64_t>(-3 * 256, (kW + 3) * 256);
}

// Lines around the 10 x 10 target, in tie classes chosen to hit the rule's special cases.
AALine gen_line() {
  // Uniform over the classes at every size (inRange alone favours small values early on).
  const int kind = *rc::gen::resize(rc::kNominalSize, rc::gen::inRange(0, 10));
  AALine l;
  const std::int64_t x0 = *near_coord(), y0 = *near_coord();
  switch (kind) {
  case 0:
    l = {"random", {x0, y0}, {*near_coord(), *near_coord()}};
    break;
  case 1:
    l = {"horizontal", {x0, y0}, {*near_coord(), y0}};
    break;
  case 2:
    l = {"vertical", {x0, y0}, {x0, *near_coord()}};
    break;
  case 3: {
    const std::int64_t t = *rc::gen::inRange<std::int64_t>(-8 * 256, 8 * 256);
    const std::int64_t s = *rc::gen::element<std::int64_t>(-1, 1);
    l = {"diagonal45", {x0, y0}, {x0 + t, y0 + s * t}};
    break;
  }
  case 4: { // endpoints on pixel centres
    auto c = [] { return *rc::gen::inRange<std::int64_t>(-2, kW + 2) * 256 + 128; };
    l = {"centres", {c(), c()}, {c(), c()}};
    break;
  }
  case 5: { // endpoints on pixel corners
    auto c = [] { return *rc::gen::inRange<std::int64_t>(-2, kW + 3) * 256; };
    l = {"corners", {c(), c()}, {c(), c()}};
    break;
  }
  case 6: { // very short: at most 4 subpixels each way, possibly zero
    auto s = [] { return *rc::gen::inRange<std::int64_t>(-4, 5); };
    l = {"short", {x0, y0}, {x0 + s(), y0 + s()}};
    break;
  }
  case 7: { // long, partly outside the target
    auto far = [] { return *rc::gen::inRange<std::int64_t>(-40000, 40000); };
    l = {"long_partly_outside", {x0, y0}, {far(), far()}};
    break;
  }
  case 8:
    l = {"zero_length", {x0, y0}, {x0, y0}};
    break;
  default: { // small direction with a common factor: slopes like 1/2, 2/3 through centres
    const std::int64_t k = *rc::gen::inRange<std::int64_t>(1, 6);
    const std::int64_t ux = *rc::gen::inRange<std::int64_t>(-3, 4);
    const std::int64_t uy = *rc::gen::inRange<std::int64_t>(-3, 4);
    const std::int64_t cx = (x0 / 256) * 256 + 128, cy = (y0 / 256) * 256 + 128;
    l = {"small_slope_centres", {cx, cy}, {cx + k * ux * 128, cy + k * uy * 128}};
    break;
  }
  }
  RC_CLASSIFY(true, l.kind);
  return l;
}

struct Frag {
  std::int32_t x;
  std::int32_t y;
  std::uint32_t q;
  friend bool operator==(const Frag&, const Frag&) = default;
};

std::vector<Frag> kernel_frags(const Raw& a, const Raw& b, std::int32_t w, std::int32_t h) {
  std::vector<Frag> out;
  rastrules::rasterize_aa_line(v2(a), v2(b), w, h,
                               [&](std::int32_t x, std::int32_t y, std::uint32_t q) {
                                 out.push_back({x, y, q});
                               });
  return out;
}

// rule: LINE.AA.RECT, LINE.AA.COVERAGE, LINE.AA.PRECISION, LINE.AA.FRAGMENT, LINE.AA.ZERO_LENGTH, LINE.AA.TRAVERSAL
RC_GTEST_PROP(LineAA, KernelCoverageIsWithinTheStatedBoundAndFragmentsMatchTheOracle, ()) {
  const AALine l = gen_line();
  RC_LOG() << show(l) << "\n";
  const std::vector<Frag> k = kernel_frags(l.a, l.b, kW, kH);
  // Fragment set: exactly the pixels whose exact coverage is > 0, in row order.
  std::vector<std::array<std::int32_t, 2>> kp;
  for (const Frag& f : k)
    kp.push_back({f.x, f.y});
  RC_ASSERT(kp == rastrules::oracle::aa_pixels(l.a, l.b, kW, kH));
  bool floor_used = false;
  for (const Frag& f : k) {
    RC_ASSERT(f.q >= 1u);
    RC_ASSERT(f.q <= 65536u);
    const auto c = rastrules::oracle::aa_check(l.a, l.b, f.x, f.y, f.q);
    RC_LOG() << "pixel (" << f.x << "," << f.y << ") kernel " << f.q << " exact*65536 "
             << c.approx * 65536.0 << "\n";
    RC_ASSERT(c.positive);
    RC_ASSERT(c.within_bound);
    // Tighter: rounding to nearest, except where the floor of 1 lifts a tiny coverage.
    RC_ASSERT(c.nearest || f.q == 1u);
    floor_used = floor_used || !c.nearest;
  }
  RC_CLASSIFY(floor_used, "coverage floored to 1");
  RC_CLASSIFY(k.empty(), "no fragments");
}

// Far from the origin and long: coordinates anywhere in SNAP.VERTEX.RANGE, pixels taken around
// a point of the segment, coverage compared pixel by pixel (aa_line_coverage accepts any pixel).
// rule: LINE.AA.COVERAGE, LINE.AA.PRECISION, LINE.AA.FRAGMENT
RC_GTEST_PROP(LineAA, CoverageIsWithinTheBoundAnywhereInTheVertexRange, ()) {
  auto any = [] {
    return *rc::gen::inRange<std::int64_t>(rastrules::kMinVertexRaw, rastrules::kMaxVertexRaw + 1);
  };
  const Raw a{any(), any()};
  const bool shortish = *rc::gen::arbitrary<bool>();
  Raw b;
  if (shortish) {
    auto s = [] { return *rc::gen::inRange<std::int64_t>(-1024, 1025); };
    b = {std::clamp<std::int64_t>(a[0] + s(), rastrules::kMinVertexRaw, rastrules::kMaxVertexRaw),
         std::clamp<std::int64_t>(a[1] + s(), rastrules::kMinVertexRaw, rastrules::kMaxVertexRaw)};
  } else {
    b = {any(), any()};
  }
  RC_CLASSIFY(shortish, "within 4 px");
  const std::int64_t t = *rc::gen::inRange<std::int64_t>(0, 1025);
  const std::int64_t mx = a[0] + (b[0] - a[0]) * t / 1024;
  const std::int64_t my = a[1] + (b[1] - a[1]) * t / 1024;
  const std::int32_t cx = static_cast<std::int32_t>(mx >> 8),
                     cy = static_cast<std::int32_t>(my >> 8);
  RC_LOG() << "a=(" << a[0] << "," << a[1] << ") b=(" << b[0] << "," << b[1] << ")\n";
  for (std::int32_t dy = -2; dy <= 2; ++dy) {
    for (std::int32_t dx = -2; dx <= 2; ++dx) {
      const auto k = rastrules::aa_line_coverage(v2(a), v2(b), cx + dx, cy + dy);
      const auto c = rastrules::oracle::aa_check(a, b, cx + dx, cy + dy, k.q16);
      RC_LOG() << "pixel (" << cx + dx << "," << cy + dy << ") kernel " << k.q16 << " exact*65536 "
               << c.approx * 65536.0 << "\n";
      RC_ASSERT(k.positive == c.positive);
      RC_ASSERT(c.within_bound);
      RC_ASSERT(c.nearest || k.q16 <= 1u);
    }
  }
}

// rule: LINE.AA.INVARIANCE
RC_GTEST_PROP(LineAA, WholePixelTranslationMovesCoverageExactly, ()) {
  const AALine l = gen_line();
  const std::int64_t tx = *rc::gen::inRange<std::int64_t>(-kW, kW + 1);
  const std::int64_t ty = *rc::gen::inRange<std::int64_t>(-kH, kH + 1);
  const Raw a2{l.a[0] + tx * 256, l.a[1] + ty * 256};
  const Raw b2{l.b[0] + tx * 256, l.b[1] + ty * 256};
  // On a target big enough for both, every fragment moves by (tx, ty) with identical coverage.
  const std::int32_t W = 4 * kW, H = 4 * kH;
  const Raw off{kW * 256, kH * 256}; // keep both copies inside the big target
  auto sh = [&](const Raw& r) { return Raw{r[0] + off[0], r[1] + off[1]}; };
  std::vector<Frag> k1 = kernel_frags(sh(l.a), sh(l.b), W, H);
  const std::vector<Frag> k2 = kernel_frags(sh(a2), sh(b2), W, H);
  for (Frag& f : k1) {
    f.x += static_cast<std::int32_t>(tx);
    f.y += static_cast<std::int32_t>(ty);
  }
  k1.erase(
      std::remove_if(k1.begin(), k1.end(),
                     [&](const Frag& f) { return f.x < 0 || f.y < 0 || f.x >= W || f.y >= H; }),
      k1.end());
  std::vector<Frag> k2in = k2;
  // Fragments of the moved line that came from pixels outside the target before the move.
  k2in.erase(std::remove_if(k2in.begin(), k2in.end(),
                            [&](const Frag& f) {
                              const std::int64_t ox = f.x - tx, oy = f.y - ty;
                              return ox < 0 || oy < 0 || ox >= W || oy >= H;
                            }),
             k2in.end());
  RC_ASSERT(k1 == k2in);
  // And pixel by pixel far away, through the per-pixel function.
  const std::int64_t far = *rc::gen::inRange<std::int64_t>(-30000, 30000);
  const Raw a3{l.a[0] + far * 256, l.a[1] - far * 256};
  const Raw b3{l.b[0] + far * 256, l.b[1] - far * 256};
  const std::int32_t px = *rc::gen::inRange(-2, kW + 2), py = *rc::gen::inRange(-2, kH + 2);
  const auto c1 = rastrules::aa_line_coverage(v2(l.a), v2(l.b), px, py);
  const auto c3 = rastrules::aa_line_coverage(v2(a3), v2(b3), px + static_cast<std::int32_t>(far),
                                              py - static_cast<std::int32_t>(far));
  RC_ASSERT(c1.positive == c3.positive);
  RC_ASSERT(c1.q16 == c3.q16);
}

// rule: LINE.AA.INVARIANCE
RC_GTEST_PROP(LineAA, ReversalAndMirrorsPreserveCoverageExactly, ()) {
  const AALine l = gen_line();
  RC_LOG() << show(l) << "\n";
  const std::vector<Frag> k = kernel_frags(l.a, l.b, kW, kH);
  // Reversal: the same fragments, same order, same values.
  RC_ASSERT(kernel_frags(l.b, l.a, kW, kH) == k);
  // Mirror in x about the target's centre line: x -> kW * 256 - x, pixel i -> kW - 1 - i.
  auto mx = [](const Raw& r) { return Raw{kW * 256 - r[0], r[1]}; };
  std::vector<Frag> m = kernel_frags(mx(l.a), mx(l.b), kW, kH);
  for (Frag& f : m)
    f.x = kW - 1 - f.x;
  std::sort(m.begin(), m.end(),
            [](const Frag& p, const Frag& q) { return std::tie(p.y, p.x) < std::tie(q.y, q.x); });
  RC_ASSERT(m == k);
  // Mirror in y likewise.
  auto my = [](const Raw& r) { return Raw{r[0], kH * 256 - r[1]}; };
  std::vector<Frag> n = kernel_frags(my(l.a), my(l.b), kW, kH);
  for (Frag& f : n)
    f.y = kH - 1 - f.y;
  std::sort(n.begin(), n.end(),
            [](const Frag& p, const Frag& q) { return std::tie(p.y, p.x) < std::tie(q.y, q.x); });
  RC_ASSERT(n == k);
}

// rule: LINE.AA.BLEND
RC_GTEST_PROP(LineAA, BlendIsTheExactValueRoundedHalvesUp, ()) {
  const auto src = *rc::gen::inRange<std::uint32_t>(0, 256);
  const auto sa = *rc::gen::inRange<std::uint32_t>(0, 256);
  const auto dst = *rc::gen::inRange<std::uint32_t>(0, 256);
  const auto cov = *rc::gen::oneOf(rc::gen::inRange<std::uint32_t>(0, 65537),
                                   rc::gen::element<std::uint32_t>(0, 1, 32768, 65535, 65536));
  const std::uint8_t out =
      rastrules::aa_blend_unorm8(static_cast<std::uint8_t>(src), static_cast<std::uint8_t>(sa),
                                 static_cast<std::uint8_t>(dst), cov);
  RC_ASSERT(rastrules::oracle::aa_blend_ok(src, sa, dst, cov, out));
}

} // namespace

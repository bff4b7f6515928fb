// SPDX-License-Identifier: MIT
// Properties of the centroid evaluation point: the kernel's centroid() equals the oracle's for
// every coverage and mask (exhaustively for the standard patterns up to 8 samples, randomly
// for 16 and custom patterns); the outward order is by exact squared distance, ties by index;
// and CENTROID WITHIN COVERAGE: on random scenes, whenever c & m != 0 the fragment's
// evaluation point lies in the pixel's half-open square, is covered by the primitive under the
// tie rule (decided by the exact oracle at that point), and is the profile's choice exactly —
// for every standard and centre pattern, and for custom patterns exactly when the oracle says
// the centre lies in the samples' hull (an example shows a custom pattern where it does not).
// Implements (properties for): MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10, MSAA.CENTROID.WITHIN

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "msaa_gen.hpp"
#include "rastrules/oracle/msaa.hpp"
#include "rastrules/oracle/point.hpp"
#include "rastrules/oracle/triangle.hpp"
#include "rastrules/scene.hpp"

namespace {

namespace mg = rastrules::msaa_gen;
namespace om = rastrules::oracle::msaa;
namespace oracle = rastrules::oracle;
using rastrules::CentroidRule;

std::string rule_name(CentroidRule r) {
  return r == CentroidRule::kD3D11 ? "d3d11" : "d3d10";
}

void check_centroid(const mg::Pattern& p, CentroidRule r, std::uint32_t c, std::uint32_t m) {
  const om::CentroidPoint want = om::centroid(rule_name(r), c, m, p.oracle);
  const om::CentroidPoint got = mg::to_oracle(rastrules::centroid(r, c, m, p.kernel));
  if (!(got == want)) {
    std::ostringstream os;
    os << p.name() << " " << rule_name(r) << " c 0x" << std::hex << c << " m 0x" << m << std::dec
       << ": kernel (" << got.offset.x << "," << got.offset.y << ") branch "
       << static_cast<int>(got.branch) << ", oracle (" << want.offset.x << "," << want.offset.y
       << ") branch " << static_cast<int>(want.branch);
    RC_FAIL(os.str());
  }
}

// rule: MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
TEST(MsaaCentroid, EqualsTheOracleForEveryCoverageAndMaskOfStandardPatternsUpTo8) {
  for (const std::uint32_t n : {1u, 2u, 4u, 8u}) {
    const mg::Pattern p = mg::standard(n);
    const std::uint32_t all = rastrules::full_mask(n);
    for (const CentroidRule r : {CentroidRule::kD3D11, CentroidRule::kD3D10}) {
      for (std::uint32_t c = 0; c <= all; ++c) {
        for (std::uint32_t m = 0; m <= all; ++m) {
          const om::CentroidPoint want = om::centroid(rule_name(r), c, m, p.oracle);
          const om::CentroidPoint got = mg::to_oracle(rastrules::centroid(r, c, m, p.kernel));
          ASSERT_TRUE(got == want)
              << p.name() << " " << rule_name(r) << " c " << c << " m " << m << ": kernel ("
              << got.offset.x << "," << got.offset.y << ") branch " << static_cast<int>(got.branch)
              << ", oracle (" << want.offset.x << "," << want.offset.y << ") branch "
              << static_cast<int>(want.branch);
        }
      }
    }
  }
}

// rule: MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
RC_GTEST_PROP(MsaaCentroid, EqualsTheOracleOnAnyPatternCoverageAndMask, ()) {
  const mg::Pattern p = *mg::any_pattern();
  const CentroidRule r = *rc::gen::element(CentroidRule::kD3D11, CentroidRule::kD3D10);
  const std::uint32_t all = rastrules::full_mask(p.count());
  const std::uint32_t c = *rc::gen::weightedOneOf<std::uint32_t>(
      {{1, rc::gen::just(all)},
       {3, rc::gen::map(rc::gen::arbitrary<std::uint32_t>(),
                        [all](std::uint32_t v) { return v & all; })}});
  const std::uint32_t m = *mg::sample_mask(p.count());
  RC_TAG(p.name());
  check_centroid(p, r, c, m);
}

// rule: MSAA.CENTROID.D3D10
RC_GTEST_PROP(MsaaCentroid, OutwardOrderIsByExactSquaredDistanceThenIndex, ()) {
  const mg::Pattern p = *mg::any_pattern();
  const std::vector<std::uint32_t> order = rastrules::outward_order(p.kernel);
  RC_ASSERT(order.size() == p.count());
  std::vector<std::uint32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::uint32_t k = 0; k < p.count(); ++k)
    RC_ASSERT(sorted[k] == k); // a permutation
  const auto d2 = [&](std::uint32_t k) {
    const om::Offset& o = p.oracle[k];
    return std::int64_t{o.x} * o.x + std::int64_t{o.y} * o.y;
  };
  for (std::size_t i = 0; i + 1 < order.size(); ++i) {
    const std::uint32_t a = order[i], b = order[i + 1];
    RC_ASSERT(d2(a) < d2(b) || (d2(a) == d2(b) && a < b));
  }
}

// Returns whether the unit of fragment f (its primitive, or its segment) covers raw point e.
bool unit_covers(const mg::MsScene& s, const rastrules::Fragment& f, const om::Raw2& e) {
  const mg::Prim& p = s.prims[f.prim];
  const std::string fill(rastrules::to_string(s.state.fill));
  switch (p.type) {
  case rastrules::PrimitiveType::kTriangle:
    return oracle::covers({p.v[0], p.v[1], p.v[2]}, e, rastrules::gen::to_oracle_state(s.state));
  case rastrules::PrimitiveType::kPoint:
    return oracle::point_covers(p.v[0], e, fill);
  default: {
    const std::size_t k = f.seg.value_or(0);
    const std::string mode =
        s.line_mode == rastrules::LineMode::kQuadNarrow ? "quad-narrow" : "quad-wide";
    return oracle::quad_line_covers(p.v[k], p.v[k + 1], mode, e, fill);
  }
  }
}

// The oracle's coverage (before the mask) of pixel (x, y) by the unit of fragment f.
std::uint32_t unit_coverage(const mg::MsScene& s, const rastrules::Fragment& f) {
  const mg::Prim& p = s.prims[f.prim];
  const std::string fill(rastrules::to_string(s.state.fill));
  switch (p.type) {
  case rastrules::PrimitiveType::kTriangle:
    return om::triangle_mask({p.v[0], p.v[1], p.v[2]}, rastrules::gen::to_oracle_state(s.state),
                             f.x, f.y, s.pattern.oracle);
  case rastrules::PrimitiveType::kPoint:
    return om::point_mask(p.v[0], fill, f.x, f.y, s.pattern.oracle);
  default: {
    const std::size_t k = f.seg.value_or(0);
    const std::string mode =
        s.line_mode == rastrules::LineMode::kQuadNarrow ? "quad-narrow" : "quad-wide";
    return om::quad_line_mask(p.v[k], p.v[k + 1], mode, fill, f.x, f.y, s.pattern.oracle);
  }
  }
}

// rule: MSAA.CENTROID.WITHIN, MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
RC_GTEST_PROP(MsaaCentroid, WithinCoverageWheneverAnySampleIsCovered, ()) {
  const mg::Pattern pat = *mg::any_pattern();
  // Quadrilateral lines are bad input on centre patterns of several samples.
  const bool lines = !(pat.family == mg::PatternFamily::kCenter && pat.count() > 1);
  mg::MsScene s = *mg::scene_on(pat, 6, lines, true);
  s.line_mode = *rc::gen::element(rastrules::LineMode::kQuadWide, rastrules::LineMode::kQuadNarrow);
  s.shading = rastrules::ShadingRate::kPixel;
  s.centroid = *rc::gen::element(CentroidRule::kD3D11, CentroidRule::kD3D10);
  for (mg::Prim& p : s.prims)
    p.aa = false;
  const bool hull = om::centre_in_hull(pat.oracle);
  if (pat.family != mg::PatternFamily::kCustom)
    RC_ASSERT(hull); // MSAA.CENTROID.WITHIN's premise

  auto r = rastrules::render(mg::to_kernel(s));
  if (const auto* err = std::get_if<rastrules::SceneError>(&r))
    RC_FAIL(err->what());
  const std::uint32_t m = s.sample_mask & rastrules::full_mask(pat.count());
  bool left = false, branch1 = false;
  for (const rastrules::Fragment& f : std::get<std::vector<rastrules::Fragment>>(r)) {
    if (f.helper)
      continue;
    RC_ASSERT(f.mask != 0u);
    RC_ASSERT(f.centroid.has_value());
    const rastrules::SampleOffset o = f.centroid->offset;
    // In the pixel's half-open square: offsets on the [-8, 7] grid.
    RC_ASSERT(rastrules::on_sample_grid(o.x, o.y));
    // The profile's rule exactly.
    const std::uint32_t c = unit_coverage(s, f);
    RC_ASSERT((c & m) == f.mask);
    const om::CentroidPoint want = om::centroid(rule_name(*s.centroid), c, m, pat.oracle);
    RC_ASSERT(mg::to_oracle(*f.centroid) == want);
    // Inside the primitive under the tie rule, at the exact point.
    const om::Raw2 e = om::sample_raw(f.x, f.y, om::Offset{o.x, o.y});
    const bool in = unit_covers(s, f, e);
    branch1 = branch1 || f.centroid->branch == rastrules::CentroidBranch::kFullCoverageCenter;
    if (!in) {
      std::ostringstream os;
      mg::show(s, os);
      os << "centroid (" << int{o.x} << "," << int{o.y} << ") of fragment (" << f.x << "," << f.y
         << ") mask 0x" << std::hex << f.mask << std::dec << " is not covered";
      if (hull)
        RC_FAIL(os.str());
      // Outside the hull only branch 1 (the centre) can leave the primitive.
      RC_ASSERT(f.centroid->branch == rastrules::CentroidBranch::kFullCoverageCenter);
      left = true;
    }
  }
  RC_CLASSIFY(branch1, "a pixel centre chosen by full coverage");
  RC_CLASSIFY(left, "custom pattern: centroid left the primitive (hull misses the centre)");
}

// The example MSAA.CENTROID.WITHIN announces: three samples in the upper-right quadrant, all
// covered by a small triangle that misses the pixel centre; both rules choose the centre.
// rule: MSAA.CENTROID.WITHIN
TEST(MsaaCentroid, CustomPatternWhoseHullMissesTheCentreCanLeaveThePrimitive) {
  const std::vector<om::Offset> offs = {{4, -4}, {6, -6}, {4, -6}};
  EXPECT_FALSE(om::centre_in_hull(offs));
  mg::MsScene s;
  s.width = 1;
  s.height = 1;
  s.pattern = mg::custom(offs);
  s.centroid = CentroidRule::kD3D11;
  s.sample_mask = 7;
  s.prims.push_back(
      mg::Prim{rastrules::PrimitiveType::kTriangle, {{170, 10}, {250, 10}, {170, 90}}});
  for (const CentroidRule r : {CentroidRule::kD3D11, CentroidRule::kD3D10}) {
    s.centroid = r;
    const auto out = rastrules::render(mg::to_kernel(s));
    ASSERT_TRUE(std::holds_alternative<std::vector<rastrules::Fragment>>(out));
    const auto& frags = std::get<std::vector<rastrules::Fragment>>(out);
    ASSERT_EQ(frags.size(), 1u);
    EXPECT_EQ(frags[0].mask, 7u);
    ASSERT_TRUE(frags[0].centroid.has_value());
    EXPECT_EQ(frags[0].centroid->branch, rastrules::CentroidBranch::kFullCoverageCenter);
    EXPECT_EQ(frags[0].centroid->offset, (rastrules::SampleOffset{0, 0}));
    EXPECT_FALSE(oracle::covers({om::Raw2{170, 10}, om::Raw2{250, 10}, om::Raw2{170, 90}},
                                om::Raw2{128, 128}, oracle::State{}));
  }
}

} // namespace

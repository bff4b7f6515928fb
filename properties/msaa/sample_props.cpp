// SPDX-License-Identifier: MIT
// Properties of samples and masks: the kernel's pattern tables equal the oracle's (typed
// separately from the spec); sample positions are the exact rationals of MSAA.PATTERN.GRID;
// the coverage mask equals the triangle rule at each sample (the oracle's exact test, and the
// kernel's own single-sample test at that point); one sample at the centre gives exactly the
// single-sample result (and a centre pattern of n samples the same pixels with all n bits);
// the sample mask only removes samples; resolve of one pixel is the exact average rounded half
// to even.
// Implements (properties for): MSAA.PATTERN.STANDARD, MSAA.PATTERN.CENTER, MSAA.PATTERN.GRID,
//   MSAA.SAMPLE.POSITION, MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.RESOLVE.AVERAGE

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "msaa_gen.hpp"
#include "rastrules/oracle/msaa.hpp"
#include "rastrules/oracle/triangle.hpp"
#include "rastrules/scene.hpp"
#include "rastrules/triangle.hpp"

namespace {

namespace mg = rastrules::msaa_gen;
namespace om = rastrules::oracle::msaa;
using rastrules::Fragment;

std::vector<Fragment> render_ok(const rastrules::Scene& s) {
  auto r = rastrules::render(s);
  if (const auto* err = std::get_if<rastrules::SceneError>(&r)) {
    RC_FAIL("kernel rejected a valid scene: " + err->what());
  }
  return std::get<std::vector<Fragment>>(r);
}

// rule: MSAA.PATTERN.STANDARD, MSAA.PATTERN.CENTER
TEST(MsaaSamples, StandardAndCentreTablesEqualTheOraclesTables) {
  for (std::uint32_t n = 0; n <= 17; ++n) {
    const bool standard = n == 1 || n == 2 || n == 4 || n == 8 || n == 16;
    EXPECT_EQ(rastrules::is_standard_count(n), standard) << n;
    if (!standard)
      continue;
    const rastrules::SamplePattern k = rastrules::standard_pattern(n);
    const std::vector<om::Offset> o = om::standard_pattern(n);
    EXPECT_EQ(k.kind, rastrules::PatternKind::kStandard);
    ASSERT_EQ(k.count(), o.size()) << n;
    for (std::size_t i = 0; i < o.size(); ++i) {
      EXPECT_EQ(int{k.positions[i].x}, o[i].x) << "count " << n << " sample " << i;
      EXPECT_EQ(int{k.positions[i].y}, o[i].y) << "count " << n << " sample " << i;
    }
    const rastrules::SamplePattern c = rastrules::center_pattern(n);
    EXPECT_EQ(c.kind, rastrules::PatternKind::kCenter);
    ASSERT_EQ(c.count(), n);
    for (const rastrules::SampleOffset& s : c.positions)
      EXPECT_EQ(s, (rastrules::SampleOffset{0, 0}));
  }
}

// rule: MSAA.SAMPLE.POSITION, MSAA.PATTERN.GRID
RC_GTEST_PROP(MsaaSamples, SamplePositionIsTheExactRational, ()) {
  const auto side = rc::gen::weightedOneOf<std::int32_t>(
      {{3, rc::gen::inRange(0, rastrules::kMaxTargetSide)},
       {1, rc::gen::element(0, 1, rastrules::kMaxTargetSide - 1)}});
  const std::int32_t px = *side, py = *side;
  const std::int32_t ox = *rc::gen::inRange(-8, 8), oy = *rc::gen::inRange(-8, 8);
  RC_ASSERT(rastrules::on_sample_grid(ox, oy));
  const rastrules::Vec2 k = rastrules::sample_position(
      px, py, rastrules::SampleOffset{static_cast<std::int8_t>(ox), static_cast<std::int8_t>(oy)});
  const om::Raw2 o = om::sample_raw(px, py, om::Offset{ox, oy});
  RC_ASSERT(std::int64_t{k.x.raw()} == o[0]);
  RC_ASSERT(std::int64_t{k.y.raw()} == o[1]);
  RC_ASSERT(!rastrules::on_sample_grid(*rc::gen::element(-9, 8), oy));
}

// rule: MSAA.COVER.SAMPLE
RC_GTEST_PROP(MsaaSamples, MaskBitsEqualTheTriangleRuleAtEachSample, ()) {
  constexpr std::int32_t kSide = 6;
  const auto v = mg::vertex(kSide, kSide);
  const std::array<om::Raw2, 3> t = {*v, *v, *v};
  const rastrules::RasterState state = *rastrules::gen::raster_state();
  const mg::Pattern p = *mg::any_pattern();
  // Mostly a pixel the triangle touches (a vertex's pixel), so that coverage is partial.
  const std::size_t near = *rc::gen::inRange<std::size_t>(0, 4);
  const auto clamp_px = [](std::int64_t raw) {
    return static_cast<std::int32_t>(
        std::clamp<std::int64_t>((raw + 256 * 8) / 256 - 8, 0, kSide - 1));
  };
  const std::int32_t px =
      near < 3 ? clamp_px(t[near][0]) : *mg::full_size(rc::gen::inRange(0, kSide));
  const std::int32_t py =
      near < 3 ? clamp_px(t[near][1]) : *mg::full_size(rc::gen::inRange(0, kSide));
  std::array<rastrules::Vec2, 3> kv{};
  for (std::size_t i = 0; i < 3; ++i) {
    kv[i] = rastrules::Vec2{rastrules::Subpixel::from_raw(static_cast<std::int32_t>(t[i][0])),
                            rastrules::Subpixel::from_raw(static_cast<std::int32_t>(t[i][1]))};
  }
  const rastrules::TriangleSetup setup = rastrules::setup_triangle(kv, state);
  const std::uint32_t got = rastrules::sample_coverage(setup, px, py, p.kernel);
  const std::uint32_t want =
      om::triangle_mask(t, rastrules::gen::to_oracle_state(state), px, py, p.oracle);
  RC_ASSERT(got == want);
  for (std::uint32_t k = 0; k < p.count(); ++k) {
    const bool bit = ((got >> k) & 1u) != 0;
    const bool single =
        setup.status == rastrules::TriangleStatus::kRasterized &&
        rastrules::covers(setup, rastrules::sample_position(px, py, p.kernel.positions[k]));
    RC_ASSERT(bit == single);
  }
  RC_ASSERT((got & ~rastrules::full_mask(p.count())) == 0u);
  RC_CLASSIFY(got != 0 && got != rastrules::full_mask(p.count()), "partial coverage");
}

// rule: MSAA.COVER.SAMPLE, MSAA.PATTERN.CENTER
RC_GTEST_PROP(MsaaSamples, OneSampleAtTheCentreEqualsTheSingleSampleResult, ()) {
  mg::MsScene s = *mg::scene_on(mg::standard(1), 7);
  s.sample_mask = 0xFFFFFFFFu;
  s.centroid.reset();
  s.shading = rastrules::ShadingRate::kPixel;
  s.quads = false;
  s.derivatives = rastrules::DerivativeMode::kNone;
  rastrules::Scene single = mg::to_kernel(s);
  single.msaa = rastrules::MultisampleState{}; // the default: single-sample rendering
  const std::vector<Fragment> want = render_ok(single);
  // The same scene through the multisample state with one sample at (0, 0): standard and
  // custom.
  for (const mg::Pattern& p : {mg::standard(1), mg::custom({om::Offset{0, 0}})}) {
    mg::MsScene t = s;
    t.pattern = p;
    RC_ASSERT(render_ok(mg::to_kernel(t)) == want);
  }
  // Centre patterns of n samples: the same pixels with every sample, for triangles, points
  // and Bresenham lines (quadrilateral lines are bad input there, d3d lines change shape).
  const std::uint32_t n = *rc::gen::element(2u, 4u, 8u, 16u);
  mg::MsScene t = s;
  t.pattern = mg::centre(n);
  const bool keep_lines = s.line_mode == rastrules::LineMode::kVulkanBresenham;
  std::vector<std::size_t> kept;
  t.prims.clear();
  for (std::size_t i = 0; i < s.prims.size(); ++i) {
    const bool line = s.prims[i].type == rastrules::PrimitiveType::kLine ||
                      s.prims[i].type == rastrules::PrimitiveType::kLineStrip;
    if (!line || keep_lines) {
      kept.push_back(i);
      t.prims.push_back(s.prims[i]);
    }
  }
  const std::uint32_t m = *mg::sample_mask(n);
  t.sample_mask = m;
  std::vector<Fragment> expect;
  if (m != 0) {
    for (const Fragment& f : want) {
      const auto it = std::find(kept.begin(), kept.end(), f.prim);
      if (it == kept.end())
        continue;
      Fragment g = f;
      g.prim = static_cast<std::uint32_t>(it - kept.begin());
      g.mask = m;
      expect.push_back(g);
    }
  }
  RC_ASSERT(render_ok(mg::to_kernel(t)) == expect);
  // And the single-sample triangles equal the original exact triangle oracle.
  std::vector<std::array<std::int32_t, 3>> tri_kernel, tri_oracle;
  rastrules::oracle::Scene os;
  os.width = s.width;
  os.height = s.height;
  os.state = rastrules::gen::to_oracle_state(s.state);
  std::vector<std::uint32_t> index;
  for (std::size_t i = 0; i < s.prims.size(); ++i) {
    if (s.prims[i].type != rastrules::PrimitiveType::kTriangle)
      continue;
    rastrules::oracle::FloatTriangle ft{};
    for (std::size_t j = 0; j < 3; ++j)
      ft[j] = mg::to_float(s.prims[i].v[j]);
    os.triangles.push_back(ft);
    index.push_back(static_cast<std::uint32_t>(i));
  }
  for (const rastrules::oracle::Fragment& f : rastrules::oracle::render(os))
    tri_oracle.push_back({static_cast<std::int32_t>(index[f.prim]), f.y, f.x});
  for (const Fragment& f : want) {
    if (s.prims[f.prim].type == rastrules::PrimitiveType::kTriangle) {
      RC_ASSERT(f.mask == 1u);
      tri_kernel.push_back({static_cast<std::int32_t>(f.prim), f.y, f.x});
    }
  }
  RC_ASSERT(tri_kernel == tri_oracle);
}

// rule: MSAA.MASK.AND
RC_GTEST_PROP(MsaaSamples, TheSampleMaskOnlyRemovesSamples, ()) {
  const mg::Pattern p = *mg::any_pattern();
  mg::MsScene s = *mg::scene_on(p, 7);
  s.centroid.reset(); // the centroid depends on the mask on purpose
  s.quads = false;
  s.derivatives = rastrules::DerivativeMode::kNone;
  const std::uint32_t all = rastrules::full_mask(p.count());
  s.sample_mask = all;
  mg::make_valid(s);
  const std::vector<Fragment> full = render_ok(mg::to_kernel(s));
  mg::MsScene t = s;
  t.sample_mask = *mg::sample_mask(p.count());
  const std::vector<Fragment> sub = render_ok(mg::to_kernel(t));
  // Expected: the full-mask fragments with their mask ANDed, those left empty dropped.
  std::vector<Fragment> expect;
  for (const Fragment& f : full) {
    RC_ASSERT((f.mask & ~all) == 0u);
    Fragment g = f;
    g.mask = f.mask & t.sample_mask;
    if (g.mask != 0)
      expect.push_back(g);
  }
  RC_ASSERT(sub == expect);
  RC_CLASSIFY(sub.size() < full.size(), "the mask removed whole fragments");
}

// rule: MSAA.RESOLVE.AVERAGE
RC_GTEST_PROP(MsaaSamples, ResolvePixelIsTheExactAverageRoundedHalfToEven, ()) {
  const auto n = static_cast<std::size_t>(*rc::gen::element(1, 2, 3, 4, 5, 8, 16));
  const auto value = rc::gen::weightedOneOf<std::uint8_t>(
      {{3, rc::gen::arbitrary<std::uint8_t>()},
       {1, rc::gen::element<std::uint8_t>(0, 1, 127, 128, 254, 255)}});
  std::vector<rastrules::Rgba8> samples;
  for (std::size_t i = 0; i < n; ++i)
    samples.push_back({*value, *value, *value, *value});
  const rastrules::Rgba8 got = rastrules::resolve_pixel(samples);
  const om::Rgba want = om::resolve_pixel(samples);
  RC_ASSERT(got == want);
}

} // namespace

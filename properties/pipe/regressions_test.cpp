// SPDX-License-Identifier: MIT
// Named regressions of the pipeline properties: counterexamples RapidCheck found (or cases at
// the edge of an interpretation the properties rely on), kept as plain tests so that they run
// every time, whatever the seed.
// Implements (regressions for): PIPE.CLIP.COMPUTE, PIPE.CLIP.POLYGON, PIPE.CLIP.VOLUME,
//   PIPE.CLIP.GUARD_BAND_BOUND, PIPE.CLIP.GUARD_BAND_SNAP, PIPE.VIEWPORT.RANGE, PIPE.DEPTH.BIAS

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "pipe_gen.hpp"
#include "rastrules/oracle/triangle.hpp"

namespace {

namespace pg = rastrules::pipe_gen;
namespace op = rastrules::oracle::pipe;
namespace kp = rastrules::pipe;

// Found by PipeGeometry.ClipperIsBitIdenticalToTheSpecAlgorithm while the oracle still rounded
// each plane's new vertices to float32: the vertex made at the w plane is clipped again at the
// guard band's x_lo plane (viewport 1 px wide: gx_lo = -63489), and rounding it between the two
// planes moves the final x by one ulp. PIPE.CLIP.COMPUTE says "rounded once to float32 when the
// vertex is complete": vertices stay doubles from plane to plane (the kernel and the oracle agree).
// rule: PIPE.CLIP.COMPUTE, PIPE.CLIP.POLYGON
TEST(PipeRegression, ClipVerticesStayDoubleBetweenPlanes) {
  const kp::Viewport vp{0.0f, 0.0f, 1.0f, 1.0f, 0.0f, 1.0f};
  const std::vector<kp::ClipVertex> t{{{-3.75f, -3.75f, 3.75f, 3.75f}, {}},
                                      {{-3.75f, -4.0f, -4.0f, -4.0f}, {}},
                                      {{-0.5f, -0.5f, 0.5f, 0.5f}, {}}};
  const std::vector<kp::Vec4f> pos{t[0].pos, t[1].pos, t[2].pos};
  const kp::ClipVolume vol = kp::clip_volume(pos, vp, false);
  const std::vector<kp::ClipVertex> got = kp::clip_polygon(t, vol);
  const std::vector<op::ClipVertex> want =
      op::clip_polygon(pg::to_oracle(t), op::clip_volume(pos, pg::to_oracle(vp), false));
  ASSERT_EQ(got.size(), 4u);
  ASSERT_EQ(want.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    for (std::size_t c = 0; c < 4; ++c)
      EXPECT_TRUE(pg::same_bits(got[i].pos[c], want[i].pos[c])) << i << " " << c;
  }
  // -0.861101 once rounded; rounded between the planes it would be -0.86110103 (0xBF5C711E).
  EXPECT_EQ(std::bit_cast<std::uint32_t>(got[2].pos[0]), 0xBF5C711Du);
}

// The constant term of the bias for d32f when the largest |Z_i| is subnormal: the spec takes
// exponent(0) as -126 (the exponent field's value), and a subnormal's exponent field is the
// same, so r = 2^-149 and one unit of bias is the smallest subnormal.
// rule: PIPE.DEPTH.BIAS
TEST(PipeRegression, BiasOfSubnormalDepthsForD32f) {
  const std::array<op::Raw2, 3> v{op::Raw2{0, 0}, op::Raw2{256, 0}, op::Raw2{0, 256}};
  const std::array<float, 3> z{1e-45f, 0.0f, 3e-45f};
  const kp::DepthBias b{1, 0.0f, 0.0f};
  const float got = kp::depth_bias(pg::to_vec2(v), z, b, kp::DepthFormat::kD32F);
  const float want = op::depth_bias(v, z, 1, 0.0f, 0.0f, "d32f");
  EXPECT_EQ(want, std::ldexp(1.0f, -149));
  EXPECT_TRUE(pg::same_bits(got, want)) << "kernel " << got << ", oracle " << want;
}

// Returns the pixel centres (farther than 1/64 px from every edge of the exactly projected and
// snapped unclipped triangle) whose coverage by run_pipeline differs from that triangle's.
std::string guard_band_mismatches(const std::array<kp::Vec4f, 3>& tri, std::int32_t w,
                                  std::int32_t h) {
  rastrules::Scene s;
  s.width = w;
  s.height = h;
  rastrules::Primitive p;
  p.pos = {tri[0], tri[1], tri[2]};
  s.primitives.push_back(p);
  const auto r = kp::run_pipeline(s);
  if (const auto* e = std::get_if<rastrules::SceneError>(&r))
    return "error " + e->what();
  std::vector<int> count(static_cast<std::size_t>(w * h), 0);
  for (const rastrules::Fragment& f : std::get<kp::PipeResult>(r).fragments)
    ++count[static_cast<std::size_t>(f.y * w + f.x)];
  const op::Viewport vp{0.0f, 0.0f, static_cast<float>(w), static_cast<float>(h), 0.0f, 1.0f};
  const op::ExactRegion exact = op::ExactRegion::unclipped_triangle(tri, vp);
  std::string out;
  for (std::int32_t y = 0; y < h; ++y) {
    for (std::int32_t x = 0; x < w; ++x) {
      const auto side =
          exact.classify({256 * std::int64_t{x} + 128, 256 * std::int64_t{y} + 128}, 4);
      if (side == op::ExactRegion::Side::kNear)
        continue;
      const int want = side == op::ExactRegion::Side::kInside ? 1 : 0;
      if (count[static_cast<std::size_t>(y * w + x)] != want)
        out += " (" + std::to_string(x) + ", " + std::to_string(y) + ")";
    }
  }
  return out;
}

// Found by PipeGeometry.GuardBandClippingKeepsCoverageAwayFromEdges. PIPE.CLIP.VOLUME's w plane
// was w >= 2^-40 M with M the largest |coordinate| of the primitive: one vertex with x = 2^41
// (x/w = 2^41, far inside the position limit) raised it to w >= 2, which every vertex (w = 1)
// failed, so the whole triangle was discarded although half of the target lies inside it (D3D
// clips at 0 < w and draws it), contradicting PIPE.CLIP.GUARD_BAND_BOUND. A spec problem, fixed
// in the spec: the w plane is now absolute (w >= 2^-126).
// rule: PIPE.CLIP.VOLUME, PIPE.CLIP.GUARD_BAND_BOUND
TEST(PipeRegression, FarVertexMustNotDiscardTheVisibleTriangle) {
  const std::array<kp::Vec4f, 3> tri{kp::Vec4f{std::ldexp(1.0f, 41), 0.0f, 0.5f, 1.0f},
                                     kp::Vec4f{-0.5f, -0.5f, 0.5f, 1.0f},
                                     kp::Vec4f{-0.5f, 0.5f, 0.5f, 1.0f}};
  EXPECT_EQ(guard_band_mismatches(tri, 8, 8), "");
}

// The property's own shrunk counterexample (w = 1, 0.5, 0.125; M = 2^40, so w >= 1).
// rule: PIPE.CLIP.VOLUME, PIPE.CLIP.GUARD_BAND_BOUND
TEST(PipeRegression, FarVertexMustNotDiscardTheVisibleTriangleShrunk) {
  const std::array<kp::Vec4f, 3> tri{kp::Vec4f{-2.0f, -2.0f, 0.0f, 1.0f},
                                     kp::Vec4f{-1.0f, -4194304.0f, 0.0f, 0.5f},
                                     kp::Vec4f{1048576.0f, 1099511627776.0f, 0.0f, 0.125f}};
  EXPECT_EQ(guard_band_mismatches(tri, 4, 6), "");
}

// The clipped polygon of t in vp without depth clipping: whether it has vertices, the largest
// |window x| or |y| among them, and whether each snaps (after PIPE.CLIP.SATURATE when
// saturate), by the oracle's snapping.
struct ClipReach {
  bool clipped = false;
  double worst = 0.0;
  bool snaps = true;
};
ClipReach clip_reach(const std::vector<kp::ClipVertex>& t, const kp::Viewport& vp, bool saturate) {
  const kp::ClipVolume vol = kp::clip_volume({t[0].pos, t[1].pos, t[2].pos}, vp, false);
  ClipReach r;
  for (const kp::ClipVertex& v : kp::clip_polygon(t, vol)) {
    r.clipped = true;
    const kp::WindowVertex w = kp::to_window(v.pos, vp);
    r.worst = std::max(
        {r.worst, std::fabs(static_cast<double>(w.x)), std::fabs(static_cast<double>(w.y))});
    const float x = saturate ? kp::saturate_to_snap_range(w.x) : w.x;
    const float y = saturate ? kp::saturate_to_snap_range(w.y) : w.y;
    r.snaps =
        r.snaps && rastrules::oracle::snap(x).has_value() && rastrules::oracle::snap(y).has_value();
  }
  return r;
}

// Whether a side x side scene of the clip-space triangle t (viewport vp, depth clipping off)
// goes through run_pipeline without an error.
bool draws_without_depth_clip(const std::vector<kp::ClipVertex>& t, const kp::Viewport& vp,
                              std::int32_t side) {
  rastrules::Scene s;
  s.width = side;
  s.height = side;
  s.viewport = vp;
  s.depth = kp::DepthState{};
  s.depth->clip = false;
  rastrules::Primitive p;
  p.pos = {t[0].pos, t[1].pos, t[2].pos};
  s.primitives.push_back(p);
  return std::holds_alternative<kp::PipeResult>(kp::run_pipeline(s));
}

// Found by PipeGeometry.ClipperIsBitIdenticalToTheSpecAlgorithm (its former guard band + 1 px
// check): a vertex at x = 2.7e11 is cut at the x_lo guard band plane; the double intersection
// I + t (O - I) cancels 2.7e11 down to -0.476, losing 2^-53 * 2.7e11 absolute, and the vertex
// lands at window x = -31745.26, 1.26 px beyond the band. The kernel computed exactly what
// PIPE.CLIP.COMPUTE prescribed (the oracle agreed bit for bit); the spec now computes the
// intersection from the endpoint nearer the plane, no longer assumes 1 px
// (PIPE.CLIP.GUARD_BAND_SNAP) and saturates clip-space vertices to the snap range
// (PIPE.CLIP.SATURATE).
// rule: PIPE.CLIP.GUARD_BAND_SNAP, PIPE.CLIP.COMPUTE, PIPE.CLIP.SATURATE
TEST(PipeRegression, GuardBandVertexMovedMoreThanOnePixel) {
  const kp::Viewport vp{-32768.0f, -200.0f, 42636.0f, 1.0f, 0.0f, 0.0f};
  const std::vector<kp::ClipVertex> t{
      {{270569799680.0f, 8.271806e-25f, 8.271806e-25f, 10981424.0f}, {}},
      {{270569799680.0f, -0.5f, 0.0f, 0.5f}, {}},
      {{-0.5f, -0.5f, 0.5f, 0.5f}, {}}};
  const ClipReach reach = clip_reach(t, vp, false);
  ASSERT_TRUE(reach.clipped);
  EXPECT_TRUE(reach.snaps); // the 1023 px margin holds
  const double worst = reach.worst;
  // Since the intersection starts from the endpoint nearer the plane (t <= 1/2) the
  // cancellation is gone: the vertex lands on the band (it was 1.26 px beyond).
  EXPECT_LE(worst, kp::kGuardBand + 1.0);
  // The whole scene draws (its vertices snap), whatever the rounding.
  EXPECT_TRUE(draws_without_depth_clip(t, vp, 16));
}

// Found by PipeGeometry.ClipperIsBitIdenticalToTheSpecAlgorithm (its guard band + 1023 px
// check, seed 7893977306015676719 at 3000 cases): with w values of 1e-45 and 2e-11 the
// clipper's rounding leaves x = -4.4e-16 at w = 3.2e-26, window x = -7.0e9, billions of pixels
// beyond the band. Kernel and oracle agree bit for bit (PIPE.CLIP.COMPUTE); the spec's claim
// that the rounding stays far inside the 1023 px margin was wrong, and PIPE.CLIP.SATURATE is
// what keeps such a vertex snappable: it is clamped to the snap range and the scene draws.
// rule: PIPE.CLIP.SATURATE, PIPE.CLIP.GUARD_BAND_SNAP
TEST(PipeRegression, ClippedVertexFarBeyondTheBandUnderATinyW) {
  const kp::Viewport vp{0.0f, 0.0f, 1.0f, 1.0f, 0.0f, 1.0f};
  const std::vector<kp::ClipVertex> t{
      {{-4.0f, 0.0f, 4.0f, 1.4013e-45f}, {}},
      {{-4.0f, -0.5f, 0.5f, 0.5f}, {}},
      {{2.5705014e+15f, 8.271806e-25f, 8.271806e-25f, 2.0259225e-11f}, {}}};
  const ClipReach reach = clip_reach(t, vp, true);
  ASSERT_TRUE(reach.clipped);
  EXPECT_TRUE(reach.snaps); // after PIPE.CLIP.SATURATE
  const double worst = reach.worst;
  EXPECT_GT(worst, 1e9); // far beyond the band: the saturation acts
  EXPECT_TRUE(draws_without_depth_clip(t, vp, 1));
}

// Found by PipeGeometry.ViewportLimitsAreTheSpecRanges: PIPE.VIEWPORT.RANGE requires
// y + height <= 32767; with y = 32767 and height = 1e-45 the exact sum exceeds it, but the
// kernel adds in float32 (fl32(32767 + 1e-45) = 32767) and accepts the viewport. The spec
// writes fl32() where it means float arithmetic (PIPE.VIEWPORT.SCISSOR) and a plain sum here;
// either the spec should say fl32(y + height) or the kernel should compare the exact sum.
// rule: PIPE.VIEWPORT.RANGE
TEST(PipeRegression, ViewportEndIsTheExactSum) {
  const kp::Viewport vp{0.0f, 32767.0f, 8.0f, 1e-45f, 0.0f, 1.0f};
  EXPECT_FALSE(op::viewport_violations(pg::to_oracle(vp)).empty());
  EXPECT_TRUE(kp::check_viewport(vp).has_value())
      << "the kernel accepts y + height = 32767 + 2^-149";
  const kp::Viewport vx{1e-4f, 0.0f, 32767.0f, 8.0f, 0.0f, 1.0f};
  EXPECT_TRUE(kp::check_viewport(vx).has_value()) << "the kernel accepts x + width = 32767.0001";
}

} // namespace

// Found by Scene.FragmentsAgreeWithTheOracle (after the w plane became absolute): a vertex
// behind the eye at w = -3e-45 cut against w >= 2^-126 from the inside endpoint (w = 1e-6) gave
// t = 1 - 1e-32, which rounds to 1 in double, so the new vertex was the outside one with w < 0,
// and its window position NaN. The intersection now starts from the endpoint nearer the plane
// and its w is raised to kWMin when rounding leaves it below (PIPE.CLIP.POLYGON).
// rule: PIPE.CLIP.POLYGON, PIPE.CLIP.COMPUTE, PIPE.CLIP.VOLUME
TEST(PipeRegression, WPlaneCutKeepsWPositive) {
  rastrules::Scene s;
  s.width = 2;
  s.height = 2;
  s.depth = kp::DepthState{};
  s.depth->clip = false;
  rastrules::Primitive p;
  p.pos = {{-1.5e-06f, -1.5e-06f, -1.015625e-07f, 1e-06f},
           {-1.5e-06f, -1.5e-06f, -1.015625e-07f, 1e-06f},
           {-3e-45f, -3e-45f, 3e-45f, -3e-45f}};
  s.primitives.push_back(p);
  const auto r = kp::run_pipeline(s);
  ASSERT_TRUE(std::holds_alternative<kp::PipeResult>(r))
      << std::get<rastrules::SceneError>(r).what();
  const kp::Viewport vp{0, 0, 2, 2, 0, 1};
  const std::vector<kp::ClipVertex> t{{p.pos[0], {}}, {p.pos[1], {}}, {p.pos[2], {}}};
  for (const kp::ClipVertex& v : kp::clip_polygon(t, kp::clip_volume({}, vp, false))) {
    EXPECT_GE(v.pos[3], 0x1p-126f);
    EXPECT_TRUE(std::isfinite(kp::to_window(v.pos, vp).x));
  }
}

// Found by Scene.FragmentsAgreeWithTheOracle at 6000 cases: with slope-scaled bias on a
// triangle whose window depths are near FLT_MAX (depth clipping off), the slope term overflowed
// to an infinity, Zi + Bias became infinite and the interpolated depth non-finite (the oracle
// refused it). Every float32 step of the bias now saturates at +-FLT_MAX (PIPE.DEPTH.BIAS).
// rule: PIPE.DEPTH.BIAS, PIPE.DEPTH.CLAMP
TEST(PipeRegression, HugeSlopeBiasSaturates) {
  const std::array<rastrules::oracle::pipe::Raw2, 3> v{{{0, 0}, {8 * 256, 0}, {0, 8 * 256}}};
  const std::array<float, 3> z{3e38f, -3e38f, 3e38f};
  kp::DepthBias b;
  b.slope_scaled = 10.0f;
  const float got = kp::depth_bias(pg::to_vec2(v), z, b, kp::DepthFormat::kD16);
  const float want = op::depth_bias(v, z, 0, 10.0f, 0.0f, "d16");
  EXPECT_EQ(got, std::numeric_limits<float>::max());
  EXPECT_TRUE(pg::same_bits(got, want)) << "kernel " << got << ", oracle " << want;

  rastrules::Scene s;
  s.width = 8;
  s.height = 8;
  s.depth = kp::DepthState{};
  s.conventions.depth = kp::DepthFormat::kD16;
  s.depth->bias.slope_scaled = 10.0f;
  rastrules::Primitive p;
  p = rastrules::make_triangle(
      {rastrules::FloatPoint{0, 0}, rastrules::FloatPoint{8, 0}, rastrules::FloatPoint{0, 8}});
  p.z = {3e38f, -3e38f, 3e38f};
  s.primitives.push_back(p);
  const auto r = kp::run_pipeline(s);
  ASSERT_TRUE(std::holds_alternative<kp::PipeResult>(r));
  const kp::PipeResult& res = std::get<kp::PipeResult>(r);
  ASSERT_FALSE(res.drawn.empty());
  for (const float zi : res.drawn[0].z)
    EXPECT_TRUE(std::isfinite(zi)) << zi;
  for (const kp::FragmentData& d : res.data)
    for (const kp::DepthValue& dv : d.depth)
      EXPECT_LE(dv.unorm, 65535u);
}

// SPDX-License-Identifier: MIT
// Examples for the geometry stages of the pipeline: transforms, the viewport and its limits,
// the implicit scissor, the clip volume with its guard band, polygon and segment clipping.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "rastrules/pipeline.hpp"
#include "rastrules/snap.hpp"

namespace rastrules::pipe {
namespace {

constexpr Mat4f kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

// rule: PIPE.TRANSFORM.FLOAT32
TEST(PipeTransform, IdentityAndTranslationAreExact) {
  EXPECT_EQ(transform(kIdentity, Vec4f{1.5f, -2.0f, 0.25f, 1.0f}),
            (Vec4f{1.5f, -2.0f, 0.25f, 1.0f}));
  const Mat4f translate = {1, 0, 0, 10, 0, 1, 0, -3, 0, 0, 1, 0.5f, 0, 0, 0, 1};
  EXPECT_EQ(transform(translate, Vec4f{1.0f, 2.0f, 0.0f, 1.0f}), (Vec4f{11.0f, -1.0f, 0.5f, 1.0f}));
}

// rule: PIPE.TRANSFORM.FLOAT32
TEST(PipeTransform, RowsAreSummedLeftToRightInFloat32) {
  // (1 + 1e8) rounds to 1e8 in float32, then - 1e8 gives 0; any other order, or a double
  // accumulator, gives 1.
  const Mat4f m = {1, 1e8f, -1e8f, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  EXPECT_EQ(transform(m, Vec4f{1.0f, 1.0f, 1.0f, 1.0f})[0], 0.0f);
}

// rule: PIPE.VIEWPORT.RANGE
TEST(PipeViewport, LimitsNameTheField) {
  EXPECT_FALSE(check_viewport(Viewport{0, 0, 64, 32, 0, 1}).has_value());
  EXPECT_FALSE(check_viewport(Viewport{-32768, -32768, 65535, 65535, 0.25f, 0.25f}).has_value());
  const auto field = [](const Viewport& vp) {
    const auto r = check_viewport(vp);
    return r ? r->first : std::string("none");
  };
  EXPECT_EQ(field(Viewport{-32769, 0, 10, 10, 0, 1}), "x");
  EXPECT_EQ(field(Viewport{0, 32768, 10, 10, 0, 1}), "y");
  EXPECT_EQ(field(Viewport{0, 0, 0, 10, 0, 1}), "width");
  EXPECT_EQ(field(Viewport{0, 0, 10, -1, 0, 1}), "height");
  EXPECT_EQ(field(Viewport{32000, 0, 768, 10, 0, 1}), "width"); // right edge 32768
  EXPECT_EQ(field(Viewport{0, 0, 10, 10, -0.5f, 1}), "min_depth");
  EXPECT_EQ(field(Viewport{0, 0, 10, 10, 0, 1.5f}), "max_depth");
  EXPECT_EQ(field(Viewport{0, 0, 10, 10, 0.75f, 0.25f}), "min_depth");
  EXPECT_EQ(field(Viewport{std::numeric_limits<float>::quiet_NaN(), 0, 10, 10, 0, 1}), "x");
  EXPECT_EQ(field(Viewport{0, 0, std::numeric_limits<float>::infinity(), 10, 0, 1}), "width");
  const auto r = check_viewport(Viewport{0, 0, 10, 10, 0.75f, 0.25f});
  ASSERT_TRUE(r.has_value());
  EXPECT_NE(r->second.find("PIPE.VIEWPORT.RANGE"), std::string::npos);
}

// rule: PIPE.VIEWPORT.TRANSFORM
TEST(PipeViewport, DivideAndScaleFollowD3D) {
  const Viewport vp{10, 20, 64, 32, 0.25f, 0.75f};
  // NDC (-1, 1) is the top-left corner, (1, -1) the bottom-right; y flips.
  EXPECT_EQ(to_window(Vec4f{-2, 2, 0, 2}, vp), (WindowVertex{10, 20, 0.25f, 2}));
  EXPECT_EQ(to_window(Vec4f{4, -4, 4, 4}, vp), (WindowVertex{74, 52, 0.75f, 4}));
  EXPECT_EQ(to_window(Vec4f{0, 0, 1, 2}, vp), (WindowVertex{42, 36, 0.5f, 2}));
}

// rule: PIPE.VIEWPORT.TRANSFORM
TEST(PipeViewport, EveryOperationIsRoundedToFloat32) {
  const Viewport vp{0, 0, 3, 3, 0, 1};
  const Vec4f p{1.0f, 0.0f, 0.0f, 3.0f};
  const float xn = 1.0f / 3.0f;
  float t = xn + 1.0f;
  t = t * 3.0f;
  t = t * 0.5f;
  EXPECT_EQ(to_window(p, vp).x, t + 0.0f);
}

// rule: PIPE.VIEWPORT.SCISSOR
TEST(PipeViewport, ImplicitScissorRoundsTheExtentsDown) {
  const ScissorRect r = viewport_scissor(Viewport{0.5f, -1.25f, 10.0f, 3.5f, 0, 1});
  EXPECT_EQ(r.x0, 0);
  EXPECT_EQ(r.x1, 10); // floor(10.5)
  EXPECT_EQ(r.y0, -2); // floor(-1.25)
  EXPECT_EQ(r.y1, 2);  // floor(2.25)
  EXPECT_TRUE(r.contains(9, 1));
  EXPECT_FALSE(r.contains(10, 1));
  EXPECT_FALSE(r.contains(0, 2));
}

// rule: PIPE.CLIP.VOLUME
TEST(PipeClip, GuardBandIsTheWindowSquareOf31744Pixels) {
  const Viewport vp{0, 0, 64, 64, 0, 1};
  const ClipVolume vol = clip_volume({Vec4f{0, 0, 0, 1}}, vp, true);
  // Window x = -31744 at xn = (-31744 - 0) * 2 / 64 - 1 = -993.
  EXPECT_EQ(vol.gx_lo, -993.0);
  EXPECT_EQ(vol.gx_hi, 991.0);
  EXPECT_EQ(vol.gy_lo, -991.0);
  EXPECT_EQ(vol.gy_hi, 993.0);
  EXPECT_EQ(vol.w_min, std::ldexp(1.0, -126));
  EXPECT_TRUE(inside(vol, Vec4f{991, -991, 1, 1}));
  EXPECT_FALSE(inside(vol, Vec4f{992, 0, 0.5f, 1}));
  EXPECT_FALSE(inside(vol, Vec4f{0, 0, -0.001f, 1})); // z < 0
  EXPECT_FALSE(inside(vol, Vec4f{0, 0, 1.001f, 1}));  // z > w
  EXPECT_FALSE(inside(vol, Vec4f{0, 0, 0, 0}));       // w = 0
  const ClipVolume no_z = clip_volume({Vec4f{0, 0, 0, 1}}, vp, false);
  EXPECT_TRUE(inside(no_z, Vec4f{0, 0, -5, 1}));
  EXPECT_TRUE(inside(no_z, Vec4f{0, 0, 5, 1}));
}

// rule: PIPE.CLIP.VOLUME
TEST(PipeClip, TheWPlaneIsFloat32sSmallestNormal) {
  const Viewport vp{0, 0, 64, 64, 0, 1};
  const ClipVolume vol = clip_volume({}, vp, true);
  EXPECT_TRUE(inside(vol, Vec4f{0, 0, 0, 0x1p-126f}));
  EXPECT_FALSE(inside(vol, Vec4f{0, 0, 0, 0x1p-127f})); // subnormal w: behind the eye
  EXPECT_TRUE(inside(vol, Vec4f{1e-30f, 0, 1e-30f, 1e-20f}));
}

// rule: PIPE.CLIP.VOLUME, PIPE.CLIP.POLYGON
TEST(PipeClip, AFarVertexDoesNotDiscardTheVisibleTriangle) {
  // (The regression FarVertexMustNotDiscardTheVisibleTriangle of properties/pipe: a w plane
  // relative to the largest coordinate once rose above every vertex's w here.)
  const Viewport vp{0, 0, 8, 8, 0, 1};
  const std::vector<ClipVertex> t{
      {{0x1p41f, 0, 0.5f, 1}, {}}, {{-0.5f, -0.5f, 0.5f, 1}, {}}, {{-0.5f, 0.5f, 0.5f, 1}, {}}};
  const auto poly = clip_polygon(t, clip_volume({}, vp, true));
  EXPECT_EQ(poly.size(), 4u);
}

std::vector<ClipVertex> tri(Vec4f a, Vec4f b, Vec4f c, float ua = 0, float ub = 0, float uc = 0) {
  return {ClipVertex{a, {ua}}, ClipVertex{b, {ub}}, ClipVertex{c, {uc}}};
}

// rule: PIPE.CLIP.UNCLIPPED
TEST(PipeClip, InsideTrianglesPassUnchanged) {
  const Viewport vp{0, 0, 64, 64, 0, 1};
  const auto t = tri({-1, -1, 0.5f, 1}, {1, -1, 0.5f, 1}, {0, 1, 0.5f, 1}, 1, 2, 3);
  std::vector<Vec4f> ps;
  for (const auto& v : t)
    ps.push_back(v.pos);
  EXPECT_EQ(clip_polygon(t, clip_volume(ps, vp, true)), t);
}

// rule: PIPE.CLIP.POLYGON, PIPE.CLIP.COMPUTE
TEST(PipeClip, NearPlaneCutsATriangleIntoAQuadrilateral) {
  const Viewport vp{0, 0, 64, 64, 0, 1};
  // Vertex 0 behind the near plane (z < 0, w > 0); vertices 1 and 2 in front.
  const auto t = tri({0, 0, -1, 1}, {1, 0, 1, 2}, {0, 1, 1, 2}, 0, 10, 20);
  std::vector<Vec4f> ps;
  for (const auto& v : t)
    ps.push_back(v.pos);
  const auto poly = clip_polygon(t, clip_volume(ps, vp, true));
  ASSERT_EQ(poly.size(), 4u);
  // Walk: v0 out, v1 in -> I(v1 -> v0) then v1; v1 in, v2 in -> v2; v2 in, v0 out -> I(v2 -> v0).
  // Edge v0-v1: d(v1) = 1, d(v0) = -1, t = 0.5: (0.5, 0, 0, 1.5), u = 5.
  EXPECT_EQ(poly[0].pos, (Vec4f{0.5f, 0.0f, 0.0f, 1.5f}));
  EXPECT_EQ(poly[0].attr[0], 5.0f);
  EXPECT_EQ(poly[1].pos, t[1].pos);
  EXPECT_EQ(poly[2].pos, t[2].pos);
  EXPECT_EQ(poly[3].pos, (Vec4f{0.0f, 0.5f, 0.0f, 1.5f}));
  EXPECT_EQ(poly[3].attr[0], 10.0f);
}

// rule: PIPE.CLIP.POLYGON
TEST(PipeClip, ASharedEdgeIsCutAtTheSamePointFromBothSides) {
  const Viewport vp{0, 0, 64, 64, 0, 1};
  // Two triangles sharing the edge a-b, which crosses the near plane; they walk it in opposite
  // directions. t = 0.3 / 1.0 is not exact in binary, so a walk-order formula would differ.
  const Vec4f a{0.1f, 0.2f, -0.7f, 1.3f}, b{0.9f, -0.4f, 0.3f, 0.7f};
  const Vec4f c{0.5f, 0.8f, 0.5f, 1.1f}, d{0.4f, -0.9f, 0.6f, 1.7f};
  const auto t1 = tri(a, b, c), t2 = tri(b, a, d);
  std::vector<Vec4f> all = {a, b, c, d};
  const ClipVolume vol = clip_volume(all, vp, true);
  const auto p1 = clip_polygon(t1, vol), p2 = clip_polygon(t2, vol);
  const auto on_plane = [&](const std::vector<ClipVertex>& p) {
    std::vector<Vec4f> r; // the vertices the clipper created
    for (const auto& v : p)
      if (v.pos != a && v.pos != b && v.pos != c && v.pos != d)
        r.push_back(v.pos);
    return r;
  };
  const auto n1 = on_plane(p1), n2 = on_plane(p2);
  ASSERT_FALSE(n1.empty());
  bool shared = false;
  for (const Vec4f& x : n1)
    for (const Vec4f& y : n2)
      shared = shared || x == y;
  EXPECT_TRUE(shared) << "the cut of edge a-b differs between the two triangles";
}

// rule: PIPE.CLIP.POLYGON
TEST(PipeClip, WBehindTheEyeIsClippedAwayAndNothingLeftIsEmpty) {
  const Viewport vp{0, 0, 64, 64, 0, 1};
  const auto behind = tri({0, 0, -1, -1}, {1, 0, -1, -1}, {0, 1, -1, -1});
  std::vector<Vec4f> ps;
  for (const auto& v : behind)
    ps.push_back(v.pos);
  EXPECT_TRUE(clip_polygon(behind, clip_volume(ps, vp, false)).empty());
  // One vertex with w < 0: every vertex of the result has w > 0.
  const auto crossing = tri({0, 0, 0.5f, -1}, {1, 0, 0.5f, 1}, {0, 1, 0.5f, 1});
  ps.clear();
  for (const auto& v : crossing)
    ps.push_back(v.pos);
  const auto poly = clip_polygon(crossing, clip_volume(ps, vp, false));
  ASSERT_GE(poly.size(), 3u);
  for (const auto& v : poly)
    EXPECT_GT(v.pos[3], 0.0f);
}

// rule: PIPE.CLIP.POLYGON, PIPE.CLIP.VOLUME
TEST(PipeClip, GuardBandCutsFarVerticesAndKeepsTheRest) {
  const Viewport vp{0, 0, 64, 64, 0, 1};
  // A vertex at xn = 5000 (window x = 160032) is beyond the guard band (xn <= 991).
  const auto t = tri({-0.5f, -0.5f, 0.5f, 1}, {5000, 0, 0.5f, 1}, {-0.5f, 0.5f, 0.5f, 1});
  std::vector<Vec4f> ps;
  for (const auto& v : t)
    ps.push_back(v.pos);
  const ClipVolume vol = clip_volume(ps, vp, true);
  const auto poly = clip_polygon(t, vol);
  ASSERT_EQ(poly.size(), 4u);
  for (const auto& v : poly) {
    const WindowVertex wv = to_window(v.pos, vp);
    EXPECT_LE(std::fabs(wv.x), kGuardBand + 1.0);
  }
}

// rule: PIPE.CLIP.SATURATE
TEST(PipeClip, WindowPositionsSaturateToTheSnapRange) {
  EXPECT_EQ(saturate_to_snap_range(100.25f), 100.25f);
  EXPECT_EQ(saturate_to_snap_range(31744.5f), 31744.5f);
  EXPECT_EQ(saturate_to_snap_range(40000.0f), 32767.99609375f);
  EXPECT_EQ(saturate_to_snap_range(-1e30f), -32768.0f);
  EXPECT_EQ(saturate_to_snap_range(32767.99609375f), 32767.99609375f);
  // Every vertex the clipper creates at the guard band snaps (here with the widest viewport).
  const Viewport vp{-32768, -32768, 65535, 65535, 0, 1};
  const std::vector<ClipVertex> t{
      {{-0.5f, -0.5f, 0.5f, 1}, {}}, {{5e4f, -0.5f, 0.5f, 1}, {}}, {{-0.5f, 7e4f, 0.5f, 1}, {}}};
  const auto poly = clip_polygon(t, clip_volume({}, vp, true));
  ASSERT_GE(poly.size(), 4u);
  for (const ClipVertex& v : poly) {
    const WindowVertex w = to_window(v.pos, vp);
    EXPECT_EQ(snap_to_subpixel(saturate_to_snap_range(w.x)).status, SnapStatus::kOk);
    EXPECT_EQ(snap_to_subpixel(saturate_to_snap_range(w.y)).status, SnapStatus::kOk);
  }
}

// rule: PIPE.CLIP.LINE
TEST(PipeClip, SegmentsAreCutFromTheInsideEndpoint) {
  const Viewport vp{0, 0, 64, 64, 0, 1};
  const ClipVertex a{{0, 0, -1, 1}, {0}}, b{{0, 0, 1, 1}, {8}};
  const ClipVolume vol = clip_volume({a.pos, b.pos}, vp, true);
  const auto s = clip_segment(a, b, vol);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ((*s)[0].pos, (Vec4f{0, 0, 0, 1}));
  EXPECT_EQ((*s)[0].attr[0], 4.0f);
  EXPECT_EQ((*s)[1].pos, b.pos);
  const auto r = clip_segment(b, a, vol);
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ((*r)[1].pos, (*s)[0].pos); // the same cut from the other direction
  EXPECT_FALSE(clip_segment(ClipVertex{{0, 0, -1, 1}, {0}}, ClipVertex{{0, 0, -2, 1}, {0}}, vol));
}

} // namespace
} // namespace rastrules::pipe

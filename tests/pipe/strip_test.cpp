// SPDX-License-Identifier: MIT
// Examples for line strips in pipeline scenes: each segment is interpolated from its own two
// vertices (barycentrics, attributes, depth) and takes its own provoking vertex, exactly as the
// same segment drawn as a line, clipped or not, in every line mode.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <variant>
#include <vector>

#include "pipe_support.hpp"
#include "rastrules/pipeline.hpp"
#include "strips.hpp"

namespace rastrules::pipe {
namespace {

using test_support::run;

// The scene of the report: a clip-space strip of two segments, a linear and a flat attribute,
// d24 depth with the test always passing.
Scene reported_scene() {
  Scene s;
  s.width = 16;
  s.height = 16;
  s.attributes = {AttributeDecl{"u", Interpolation::kLinear, Location::kCenter},
                  AttributeDecl{"k", Interpolation::kFlat, Location::kCenter}};
  DepthState d;
  d.func = CompareFunc::kAlways;
  s.depth = d;
  Primitive p;
  p.type = PrimitiveType::kLineStrip;
  p.pos = {{-0.9375f, -0.9375f, 0.25f, 1.0f},
           {0.9375f, -0.9375f, 0.5f, 1.0f},
           {0.9375f, 0.9375f, 0.75f, 1.0f}};
  p.attr = {{0, 10}, {1, 20}, {2, 30}};
  s.primitives.push_back(p);
  return s;
}

// Fragment and data keyed by (segment, y, x, sample): a strip's segment is its `seg` or, when
// clipped, its `part`; a line's is its primitive index.
using Key = std::tuple<std::uint32_t, std::int32_t, std::int32_t, std::int64_t>;
std::map<Key, std::pair<Fragment, FragmentData>> by_segment(const PipeResult& r, bool strip) {
  std::map<Key, std::pair<Fragment, FragmentData>> m;
  for (std::size_t i = 0; i < r.fragments.size(); ++i) {
    const Fragment& f = r.fragments[i];
    const FragmentData& d = r.data.at(i);
    const std::uint32_t segment = strip ? (f.seg ? *f.seg : d.part.value_or(0)) : f.prim;
    const bool fresh =
        m.emplace(Key{segment, f.y, f.x, f.sample ? std::int64_t{*f.sample} : -1}, std::pair{f, d})
            .second;
    EXPECT_TRUE(fresh) << "two fragments of one segment at (" << f.x << ", " << f.y << ")";
  }
  return m;
}

// Expects every fragment of the strip scene to equal, apart from prim, seg, part and the drawn
// index, the fragment of the same segment drawn as a line.
void expect_strip_equals_lines(const Scene& strip) {
  const PipeResult a = run(strip), b = run(pipe_gen::strips_as_lines(strip));
  ASSERT_FALSE(a.fragments.empty());
  const auto sa = by_segment(a, true), sb = by_segment(b, false);
  ASSERT_EQ(sa.size(), sb.size());
  for (auto ia = sa.begin(), ib = sb.begin(); ia != sa.end(); ++ia, ++ib) {
    ASSERT_EQ(ia->first, ib->first);
    Fragment fa = ia->second.first, fb = ib->second.first;
    fa.prim = fb.prim = 0;
    fa.seg = fb.seg = std::nullopt;
    EXPECT_EQ(fa, fb) << "segment " << std::get<0>(ia->first) << " at (" << fa.x << ", " << fa.y
                      << ")";
    FragmentData da = ia->second.second, db = ib->second.second;
    da.drawn = db.drawn = 0;
    da.part = db.part = std::nullopt;
    EXPECT_EQ(da, db) << "segment " << std::get<0>(ia->first) << " at (" << fa.x << ", " << fa.y
                      << ")";
  }
  EXPECT_EQ(a.depth_buffer, b.depth_buffer);
}

// rule: PIPE.BARY.LINE, LINE.STRIP.SEQUENCE, PIPE.INTERP.LINEAR, PIPE.DEPTH.INTERP
// The reported defect: every segment of an unclipped strip was interpolated as segment 0.
TEST(PipeStrip, SecondSegmentIsInterpolatedFromItsOwnVertices) {
  const PipeResult r = run(reported_scene());
  bool seen = false;
  for (std::size_t i = 0; i < r.fragments.size(); ++i) {
    const Fragment& f = r.fragments[i];
    if (f.x != 15 || f.y != 1 || f.seg != 1u)
      continue;
    seen = true;
    const FragmentData& d = r.data[i];
    ASSERT_TRUE(d.bary.has_value());
    EXPECT_EQ(d.bary->e, (std::array<std::int64_t, 3>{983040, 13762560, 0}));
    EXPECT_EQ(d.bary->area, 14745600);
    ASSERT_EQ(d.attr.size(), 2u);
    EXPECT_NEAR(d.attr[0], 1.0f + 13762560.0f / 14745600.0f, 1e-6f); // about 1.9333
    EXPECT_EQ(d.attr[1], 20.0f);                                     // segment 1's first vertex
    ASSERT_EQ(d.depth.size(), 1u);
    EXPECT_EQ(d.depth[0].unorm, 12303291u);
    ASSERT_LT(d.drawn, r.drawn.size());
    EXPECT_EQ(r.drawn[d.drawn].seg, 1u);
    EXPECT_EQ(r.drawn[d.drawn].type, PrimitiveType::kLine);
  }
  EXPECT_TRUE(seen) << "no fragment of segment 1 at (15, 1)";
}

// rule: PIPE.INTERP.FLAT, LINE.STRIP.SEQUENCE
TEST(PipeStrip, FlatAttributesTakeEachSegmentsProvokingVertex) {
  for (const Provoking pv : {Provoking::kFirst, Provoking::kLast}) {
    for (const bool clipped : {false, true}) {
      Scene s = reported_scene();
      s.conventions.provoking = pv;
      if (clipped) // the last vertex behind the eye: every segment is clipped (a part each)
        s.primitives[0].pos[2] = {0.9375f, 0.9375f, 0.75f, -1.0f};
      const PipeResult r = run(s);
      ASSERT_FALSE(r.fragments.empty());
      for (std::size_t i = 0; i < r.fragments.size(); ++i) {
        const Fragment& f = r.fragments[i];
        const std::uint32_t segment = f.seg ? *f.seg : r.data[i].part.value_or(0);
        EXPECT_EQ(f.seg.has_value(), !clipped);
        const float want = 10.0f * static_cast<float>(segment + (pv == Provoking::kFirst ? 1 : 2));
        EXPECT_EQ(r.data[i].attr.at(1), want)
            << "segment " << segment << (pv == Provoking::kFirst ? ", first" : ", last")
            << (clipped ? ", clipped" : "");
      }
    }
  }
}

// rule: LINE.STRIP.SEQUENCE, PIPE.BARY.LINE, PIPE.INTERP.PERSPECTIVE, PIPE.INTERP.FLAT
// rule: PIPE.CLIP.LINE
TEST(PipeStrip, EverySegmentEqualsTheSameSegmentDrawnAsALine) {
  for (const LineMode mode : {LineMode::kD3DDiamond, LineMode::kVulkanBresenham,
                              LineMode::kQuadWide, LineMode::kQuadNarrow}) {
    for (const Provoking pv : {Provoking::kFirst, Provoking::kLast}) {
      for (const bool clipped : {false, true}) {
        for (const bool window : {false, true}) {
          Scene s = reported_scene();
          s.conventions.line_mode = mode;
          s.conventions.provoking = pv;
          s.attributes.push_back(
              AttributeDecl{"p", Interpolation::kPerspective, Location::kCenter});
          Primitive& p = s.primitives[0];
          p.pos.push_back({-0.5f, 0.25f, 0.125f, 2.0f});
          p.attr = {{0, 10, 5}, {1, 20, -3}, {2, 30, 7}, {3, 40, 11}};
          if (window) {
            p.v = {{1.5f, 14.5f}, {14.25f, 14.5f}, {14.5f, 1.75f}, {3.0f, 9.0f}};
            p.z = {0.25f, 0.5f, 0.75f, 0.0f};
            p.w = {1.0f, 4.0f, 0.5f, 2.0f};
            p.pos.clear();
            if (clipped) // window space is never clipped: the scissor cuts instead
              s.viewport = Viewport{0.0f, 0.0f, 12.0f, 16.0f, 0.0f, 1.0f};
          } else if (clipped) {
            p.pos[1] = {0.9375f, -0.9375f, -0.5f, 1.0f}; // in front of the near plane
          }
          SCOPED_TRACE(std::string(to_string(mode)) +
                       (pv == Provoking::kFirst ? " first" : " last") +
                       (clipped ? " clipped" : "") + (window ? " window" : " clip"));
          expect_strip_equals_lines(s);
        }
      }
    }
  }
}

// rule: PIPE.BARY.LINE
// The drawn primitives of a strip are its segments, each a line with its own two vertices.
TEST(PipeStrip, DrawnPrimitivesAreTheSegments) {
  const PipeResult r = run(reported_scene());
  ASSERT_EQ(r.drawn.size(), 2u);
  for (std::uint32_t k = 0; k < 2; ++k) {
    const DrawnPrimitive& d = r.drawn[k];
    EXPECT_EQ(d.type, PrimitiveType::kLine);
    EXPECT_EQ(d.seg, k);
    EXPECT_FALSE(d.part.has_value());
    ASSERT_EQ(d.snapped.size(), 2u);
    EXPECT_EQ(d.z[0], 0.25f * static_cast<float>(k + 1)); // z of vertex k: 0.25, then 0.5
    ASSERT_EQ(d.attr.size(), 2u);
    EXPECT_EQ(d.attr[0][0], static_cast<float>(k));
    EXPECT_EQ(d.attr[0][1], static_cast<float>(k + 1));
    EXPECT_EQ(d.flat,
              (std::vector<float>{static_cast<float>(k), 10.0f * static_cast<float>(k + 1)}));
  }
}

} // namespace
} // namespace rastrules::pipe

// SPDX-License-Identifier: MIT
// Examples for whole pipeline scenes: clip-space input equals window-space input, clipped
// fans, the implicit scissor, flat attributes and the provoking vertex, depth test and write,
// the z-fighting winner, effects on demand, and bad input naming its field.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <variant>

#include "pipe_support.hpp"
#include "rastrules/pipeline.hpp"

namespace rastrules::pipe {
namespace {

Scene scene(std::int32_t w, std::int32_t h) {
  Scene s;
  s.width = w;
  s.height = h;
  return s;
}

Primitive clip_tri(Vec4f a, Vec4f b, Vec4f c) {
  Primitive p;
  p.type = PrimitiveType::kTriangle;
  p.pos = {a, b, c};
  return p;
}

Primitive window_tri(FloatPoint a, FloatPoint b, FloatPoint c, std::array<float, 3> z = {}) {
  Primitive p;
  p = make_triangle({a, b, c});
  p.z = {z[0], z[1], z[2]};
  return p;
}

// A fragment with its data, for reading tests (PipeResult keeps them in parallel arrays).
struct Frag : FragmentData {
  Fragment f;
};
std::vector<Frag> frags(const PipeResult& r) {
  std::vector<Frag> v(r.fragments.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    v[i].f = r.fragments[i];
    if (!r.data.empty())
      static_cast<FragmentData&>(v[i]) = r.data[i];
    else
      v[i].passed = r.fragments[i].mask;
  }
  return v;
}

using test_support::run;

SceneError run_error(const Scene& s) {
  auto r = run_pipeline(s);
  if (auto* e = std::get_if<SceneError>(&r))
    return *e;
  ADD_FAILURE() << "expected an error";
  return {};
}

std::set<std::tuple<std::uint32_t, std::int32_t, std::int32_t>> pixels(const PipeResult& r) {
  std::set<std::tuple<std::uint32_t, std::int32_t, std::int32_t>> s;
  for (const auto& f : r.fragments)
    s.insert({f.prim, f.x, f.y});
  return s;
}

// rule: PIPE.CLIP.UNCLIPPED, PIPE.VIEWPORT.TRANSFORM, PIPE.EFFECTS.ON_DEMAND
TEST(Scene, ClipSpaceTriangleCoversWhatItsWindowImageCovers) {
  Scene c = scene(16, 16);
  // NDC (-0.75, 0.75), (0.5, 0.5), (-0.5, -0.875) with w = 2: window (2, 2), (12, 4), (4, 15).
  c.primitives.push_back(clip_tri({-1.5f, 1.5f, 0.5f, 2}, {1, 1, 0.5f, 2}, {-1, -1.75f, 0.5f, 2}));
  Scene w = scene(16, 16);
  w.primitives.push_back(window_tri({2, 2}, {12, 4}, {4, 15}));
  const PipeResult rc = run(c), rw = run(w);
  EXPECT_EQ(pixels(rc), pixels(rw));
  EXPECT_FALSE(rc.fragments.empty());
  EXPECT_TRUE(rc.effects.clip_space);
  EXPECT_TRUE(rw.effects.coverage_only());
  // Coverage-only: the fragments are exactly the kernel's (SCENE.OUTPUT.FRAGMENTS).
  Scene k;
  k.width = 16;
  k.height = 16;
  k.primitives.push_back(make_triangle({FloatPoint{2, 2}, FloatPoint{12, 4}, FloatPoint{4, 15}}));
  const auto kf = std::get<std::vector<Fragment>>(render(k));
  EXPECT_EQ(rw.fragments, kf);
  EXPECT_TRUE(rw.data.empty());
  EXPECT_EQ(rc.data.size(), rc.fragments.size());
}

// rule: PIPE.CLIP.POLYGON
TEST(Scene, NearClippedTriangleBecomesPartsThatCoverEachPixelOnce) {
  Scene s = scene(32, 32);
  s.depth = DepthState{};
  // One vertex behind the near plane (z < 0).
  s.primitives.push_back(
      clip_tri({-0.9f, -0.9f, -0.5f, 1}, {0.9f, -0.8f, 0.5f, 1}, {0, 0.9f, 0.5f, 1}));
  const PipeResult r = run(s);
  std::set<std::pair<std::int32_t, std::int32_t>> seen;
  std::set<std::uint32_t> parts;
  for (const auto& f : frags(r)) {
    ASSERT_TRUE(f.part.has_value());
    parts.insert(*f.part);
    EXPECT_TRUE(seen.insert({f.f.x, f.f.y}).second)
        << "pixel drawn twice: " << f.f.x << "," << f.f.y;
    // Depth stays in the viewport's range and the near plane maps to depth 0.
    ASSERT_EQ(f.depth.size(), 1u);
    EXPECT_LE(f.depth[0].unorm, 16777215u);
  }
  EXPECT_EQ(parts, (std::set<std::uint32_t>{0, 1}));
}

// rule: PIPE.VIEWPORT.SCISSOR
TEST(Scene, NothingIsDrawnOutsideTheViewport) {
  Scene s = scene(32, 32);
  s.viewport = Viewport{8, 4, 8, 8, 0, 1};
  // A triangle much larger than the viewport (NDC -10..10), inside the guard band.
  s.primitives.push_back(clip_tri({-10, -10, 0.5f, 1}, {10, -10, 0.5f, 1}, {0, 10, 0.5f, 1}));
  const PipeResult r = run(s);
  EXPECT_EQ(r.fragments.size(), 64u);
  for (const auto& f : frags(r)) {
    EXPECT_GE(f.f.x, 8);
    EXPECT_LT(f.f.x, 16);
    EXPECT_GE(f.f.y, 4);
    EXPECT_LT(f.f.y, 12);
  }
}

// rule: PIPE.INTERP.FLAT, PIPE.INPUT.ATTRIBUTES
TEST(Scene, FlatAttributesTakeTheProvokingVertex) {
  for (const Provoking pv : {Provoking::kFirst, Provoking::kLast}) {
    Scene s = scene(16, 16);
    s.conventions.provoking = pv;
    s.attributes = {AttributeDecl{"id", Interpolation::kFlat, Location::kCenter},
                    AttributeDecl{"u", Interpolation::kLinear, Location::kCenter}};
    Primitive p = window_tri({1, 1}, {15, 1}, {1, 15});
    p.attr = {{10, 0}, {20, 1}, {30, 2}};
    s.primitives.push_back(p);
    const PipeResult r = run(s);
    ASSERT_FALSE(r.fragments.empty());
    for (const auto& f : frags(r)) {
      ASSERT_EQ(f.attr.size(), 2u);
      EXPECT_EQ(f.attr[0], pv == Provoking::kFirst ? 10.0f : 30.0f);
      EXPECT_GE(f.attr[1], 0.0f);
      EXPECT_LE(f.attr[1], 2.0f);
      ASSERT_TRUE(f.bary.has_value());
      EXPECT_EQ(f.bary->e[0] + f.bary->e[1] + f.bary->e[2], f.bary->area);
    }
  }
}

// rule: PIPE.DEPTH.TEST, PIPE.DEPTH.WRITE
TEST(Scene, ZFightingHasADeterministicWinner) {
  for (const CompareFunc func : {CompareFunc::kLess, CompareFunc::kLessEqual}) {
    Scene s = scene(8, 8);
    s.depth = DepthState{};
    s.depth->func = func;
    // The same triangle twice at the same depth.
    s.primitives.push_back(window_tri({0, 0}, {8, 0}, {0, 8}, {0.5f, 0.25f, 0.75f}));
    s.primitives.push_back(window_tri({0, 0}, {8, 0}, {0, 8}, {0.5f, 0.25f, 0.75f}));
    const PipeResult r = run(s);
    for (const auto& f : frags(r)) {
      if (f.f.prim == 0)
        EXPECT_EQ(f.passed, 1u); // first: passes against the clear value 1.0
      else
        EXPECT_EQ(f.passed, func == CompareFunc::kLess ? 0u : 1u);
    }
  }
}

// rule: PIPE.DEPTH.TEST, PIPE.DEPTH.WRITE, PIPE.DEPTH.FORMAT
TEST(Scene, NearerTriangleWinsAndTheBufferHoldsItsDepth) {
  Scene s = scene(8, 8);
  s.depth = DepthState{};
  s.conventions.depth = DepthFormat::kD16;
  s.primitives.push_back(window_tri({0, 0}, {8, 0}, {0, 8}, {0.25f, 0.25f, 0.25f}));
  s.primitives.push_back(window_tri({0, 0}, {8, 0}, {0, 8}, {0.75f, 0.75f, 0.75f})); // behind
  const PipeResult r = run(s);
  for (const auto& f : frags(r))
    EXPECT_EQ(f.passed, f.f.prim == 0 ? 1u : 0u);
  const std::uint32_t quarter = to_depth_format(0.25, 0, 1, DepthFormat::kD16).unorm;
  EXPECT_EQ(r.depth_buffer[0].unorm, quarter);        // pixel (0, 0)
  EXPECT_EQ(r.depth_buffer[7 * 8 + 7].unorm, 65535u); // pixel (7, 7): clear
  // Without writes the second still fails (the buffer holds the clear value only where the
  // first did not draw), and the buffer keeps the clear value everywhere.
  s.depth->write = false;
  const PipeResult nw = run(s);
  for (const auto& v : nw.depth_buffer)
    EXPECT_EQ(v.unorm, 65535u);
  for (const auto& f : frags(nw))
    EXPECT_EQ(f.passed, 1u);
}

// rule: PIPE.DEPTH.TEST
TEST(Scene, DepthIsTestedPerSample) {
  Scene s = scene(4, 4);
  set_sample_pattern(s, standard_pattern(4));
  s.depth = DepthState{};
  s.conventions.depth = DepthFormat::kD32F;
  // A steep depth ramp along x: within a pixel, samples to the left are nearer.
  s.primitives.push_back(window_tri({0, 0}, {4, 0}, {0, 4}, {0.0f, 1.0f, 0.0f}));
  s.primitives.push_back(window_tri({0, 0}, {4, 0}, {0, 4}, {0.2f, 0.2f, 0.2f}));
  const PipeResult r = run(s);
  bool mixed = false;
  for (const auto& f : frags(r)) {
    // rule: PIPE.DEPTH.KILL
    EXPECT_EQ(f.depth.size(),
              f.passed == 0 ? 0u : static_cast<std::size_t>(std::popcount(f.f.mask)));
    if (f.f.prim == 1 && f.passed != 0 && f.passed != f.f.mask)
      mixed = true;
  }
  EXPECT_TRUE(mixed) << "some pixel should pass the test on some samples only";
}

// rule: PIPE.INTERP.LOCATION
TEST(Scene, SampleLocationNeedsSampleShading) {
  Scene s = scene(4, 4);
  s.attributes = {AttributeDecl{"u", Interpolation::kPerspective, Location::kSample}};
  Primitive p = window_tri({0, 0}, {4, 0}, {0, 4});
  p.attr = {{0}, {1}, {2}};
  s.primitives.push_back(p);
  const SceneError e = run_error(s);
  EXPECT_EQ(e.field, "attributes[0].location");
  set_sample_pattern(s, standard_pattern(4));
  s.msaa.shading = ShadingRate::kSample;
  const PipeResult r = run(s);
  for (const auto& f : frags(r))
    ASSERT_TRUE(f.f.sample.has_value());
}

// rule: PIPE.INPUT.POSITION, PIPE.INPUT.ATTRIBUTES, PIPE.TRANSFORM.FLOAT32
TEST(Scene, BadInputNamesTheField) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  Scene s = scene(8, 8);
  s.primitives.push_back(clip_tri({0, 0, 0, 1}, {1, 0, 0, 1}, {0, nan, 0, 1}));
  EXPECT_EQ(run_error(s).field, "primitives[0].pos[2]");
  s.primitives[0].pos[2] = {0, 1e30f, 0, 1};
  EXPECT_NE(run_error(s).message.find("2^64"), std::string::npos);
  s.primitives[0].pos[2] = {0, 1, 0, 1};
  s.projection = Mat4f{1e30f, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const SceneError after = run_error(s);
  EXPECT_EQ(after.field, "primitives[0].pos[1]");
  EXPECT_NE(after.message.find("after the transform"), std::string::npos);
  s.projection.reset();
  s.attributes = {AttributeDecl{"u", Interpolation::kLinear, Location::kCenter}};
  s.primitives[0].attr = {{0}, {1}};
  EXPECT_EQ(run_error(s).field, "primitives[0].attr");
  s.primitives[0].attr = {{0}, {1}, {std::numeric_limits<float>::infinity()}};
  EXPECT_EQ(run_error(s).field, "primitives[0].attr[2][0]");
  s.primitives[0].attr = {{0}, {1}, {2}};
  s.viewport = Viewport{0, 0, 8, 8, 0.5f, 0.25f};
  EXPECT_EQ(run_error(s).field, "viewport.min_depth");
}

// The one validator: a scene built in code gets from pipe::validate, and from run_pipeline,
// the same field and words a scene file gets (the reader checks syntax and types only).
// rule: SCENE.PIPELINE, PIPE.INPUT.ATTRIBUTES, SCENE.INPUT.ERRORS
TEST(Scene, PerVertexListsAreCheckedByTheKernelWithTheReadersWords) {
  Scene s = scene(8, 8);
  s.primitives.push_back(window_tri({1, 1}, {6, 2}, {2, 6}));
  EXPECT_FALSE(validate(s).has_value());
  const auto expect = [&](const std::string& field, const std::string& message) {
    const std::optional<SceneError> e = validate(s);
    ASSERT_TRUE(e.has_value()) << field;
    EXPECT_EQ(e->what(), field + ": " + message);
    EXPECT_EQ(run_error(s).what(), e->what());
  };
  s.primitives[0].z = {0, 0.5f, 1, 1};
  expect("primitives[0].z", "must have one number per vertex (3), got 4");
  s.primitives[0].z = {0, 0.5f, 1};
  s.primitives[0].w = {1, 2};
  expect("primitives[0].w", "must have one number per vertex (3), got 2");
  s.primitives[0].w.clear();
  s.primitives[0].attr = {{0}, {1}, {2}};
  expect("primitives[0].attr",
         "is given but the scene declares no \"attributes\" (PIPE.INPUT.ATTRIBUTES)");
  s.attributes = {AttributeDecl{"u", Interpolation::kLinear, Location::kCenter},
                  AttributeDecl{"k", Interpolation::kFlat, Location::kCenter}};
  expect("primitives[0].attr[0]", "must have 2 values (one per declared attribute), got 1");
  s.primitives[0].attr = {{0, 1}, {1, 2}};
  expect("primitives[0].attr", "must have one list of attribute values per vertex (3), got 2");
  s.primitives[0].attr.clear();
  expect("primitives[0].attr",
         "is missing: the scene declares 2 attributes (PIPE.INPUT.ATTRIBUTES)");
  s.primitives[0].attr = {{0, 1}, {1, 2}, {2, 3}};
  EXPECT_FALSE(validate(s).has_value());
  s.primitives.push_back(clip_tri({0, 0, 0, 1}, {1, 0, 0, 1}, {0, 1, 0, 1}));
  s.primitives[1].pos.pop_back();
  s.primitives[1].attr = {{0, 1}, {1, 2}};
  expect("primitives[1].pos",
         "a triangle must have exactly 3 vertices [x, y, z] or [x, y, z, w], got 2");
  s.primitives[1].pos.push_back({0, 1, 0, 1});
  s.primitives[1].attr.push_back({2, 3});
  s.primitives[1].z = {0, 0, 0};
  expect("primitives[1].z", "goes with \"v\" only (window space); \"pos\" gives z and w in each "
                            "position");
}

// rule: PIPE.CLIP.LINE
TEST(Scene, PointsOutsideTheVolumeAreDiscardedAndLinesAreCut) {
  Scene s = scene(16, 16);
  Primitive pt;
  pt.type = PrimitiveType::kPoint;
  pt.pos = {{0, 0, -0.5f, 1}}; // in front of the near plane
  s.primitives.push_back(pt);
  Primitive line;
  line.type = PrimitiveType::kLine;
  line.pos = {{-0.5f, 0.05f, -1, 1}, {0.5f, 0.05f, 1, 1}}; // crosses z = 0 half-way
  s.primitives.push_back(line);
  const PipeResult r = run(s);
  for (const auto& f : frags(r)) {
    EXPECT_EQ(f.f.prim, 1u);
    EXPECT_EQ(f.part, std::optional<std::uint32_t>(0));
    EXPECT_GE(f.f.x, 7); // the clipped line starts at the centre, x = 8
  }
  EXPECT_FALSE(r.fragments.empty());
}

// rule: PIPE.DEPTH.BIAS
TEST(Scene, BiasMovesTrianglesButNotPoints) {
  Scene s = scene(8, 8);
  s.depth = DepthState{};
  s.depth->func = CompareFunc::kAlways;
  s.depth->bias.bias = 1000;
  s.primitives.push_back(window_tri({0, 0}, {8, 0}, {0, 8}, {0.5f, 0.5f, 0.5f}));
  Primitive pt;
  pt.type = PrimitiveType::kPoint;
  pt.v = {FloatPoint{5.5f, 5.5f}};
  pt.z = {0.5f};
  s.primitives.push_back(pt);
  const PipeResult r = run(s);
  const std::uint32_t half = to_depth_format(0.5, 0, 1, DepthFormat::kD24).unorm; // 2^23
  for (const auto& f : frags(r)) {
    ASSERT_EQ(f.depth.size(), 1u);
    // r = fl32(1 / (2^24 - 1)) = 2^-24 exactly, so z = 0.5 + 1000 * 2^-24 and
    // floor(z * (2^24 - 1) + 0.5) = 2^23 + 1000 - 1000 * 2^-24 rounds down to 2^23 + 999.
    if (f.f.prim == 0)
      EXPECT_EQ(f.depth[0].unorm, half + 999u);
    else
      EXPECT_EQ(f.depth[0].unorm, half);
  }
}

// rule: PIPE.EFFECTS.ON_DEMAND
TEST(Scene, ResultsDoNotDependOnTheTraversal) {
  Scene s = scene(64, 64);
  s.depth = DepthState{};
  s.attributes = {AttributeDecl{"u", Interpolation::kPerspective, Location::kCenter}};
  Primitive p = clip_tri({-0.9f, -0.9f, 0.1f, 1}, {3, -0.5f, 2, 4}, {0, 0.9f, 0.4f, 0.5f});
  p.attr = {{0}, {1}, {2}};
  s.primitives.push_back(p);
  PipeOptions plain;
  plain.render.traversal = Traversal::kPlain;
  const PipeResult a = run(s), b = run(s, plain);
  EXPECT_EQ(a.fragments, b.fragments);
  EXPECT_EQ(a.data, b.data);
  EXPECT_EQ(a.depth_buffer, b.depth_buffer);
}

// rule: PIPE.DEPTH.KILL, PIPE.OPT.EARLY_Z, PIPE.OPT.HIZ
TEST(Scene, KilledFragmentsKeepTheirCoverageOnly) {
  Scene s = scene(16, 16); // one 16 x 16 tile
  s.depth = DepthState{};
  s.attributes = {AttributeDecl{"u", Interpolation::kLinear, Location::kCenter}};
  // A full-target quad at depth 0.25, then a triangle behind it at 0.5.
  Primitive q0 = window_tri({0, 0}, {16, 0}, {0, 16}, {0.25f, 0.25f, 0.25f});
  Primitive q1 = window_tri({16, 0}, {16, 16}, {0, 16}, {0.25f, 0.25f, 0.25f});
  Primitive back = window_tri({0, 0}, {16, 0}, {0, 16}, {0.5f, 0.5f, 0.5f});
  q0.attr = q1.attr = {{1}, {2}, {3}};
  back.attr = {{4}, {5}, {6}};
  s.primitives = {q0, q1, back};
  for (const bool early : {true, false}) {
    PipeOptions o;
    o.early_z = early;
    const PipeResult r = run(s, o);
    std::size_t killed = 0;
    for (const auto& f : frags(r)) {
      if (f.f.prim == 2) {
        ++killed;
        EXPECT_EQ(f.passed, 0u);
        EXPECT_EQ(f.f.mask, 1u);
        EXPECT_TRUE(f.attr.empty());
        EXPECT_TRUE(f.depth.empty());
        EXPECT_FALSE(f.bary.has_value());
      } else {
        EXPECT_EQ(f.attr.size(), 1u);
      }
    }
    // The 120 pixel centres strictly inside the half square (the 16 on the hypotenuse lie on a
    // right edge, which is not inclusive).
    EXPECT_EQ(killed, 120u);
    // Hi-Z killed the back triangle in its one tile without computing a depth; early-Z
    // interpolated only the quad's attributes.
    EXPECT_EQ(r.stats.hiz_rejected, 1u);
    EXPECT_EQ(r.stats.depth_samples, 256u);
    EXPECT_EQ(r.stats.attributes, early ? 256u : 376u);
    const PipeResult plain = run(s, PipeOptions::plain());
    EXPECT_EQ(plain.stats.hiz_rejected, 0u);
    EXPECT_EQ(plain.stats.depth_samples, 376u);
    EXPECT_EQ(plain.fragments, r.fragments);
    EXPECT_EQ(plain.data, r.data);
    EXPECT_EQ(plain.depth_buffer, r.depth_buffer);
  }
}

// rule: PIPE.OPT.TILES, PIPE.OPT.HIZ, PIPE.OPT.EARLY_Z, PIPE.OPT.FAST_CLEAR, PIPE.OPT.THREADS
TEST(Scene, EveryOptimizationGivesThePlainResult) {
  Scene s = scene(80, 48);
  set_sample_pattern(s, standard_pattern(4));
  s.depth = DepthState{};
  s.conventions.depth = DepthFormat::kD16;
  s.attributes = {AttributeDecl{"u", Interpolation::kPerspective, Location::kCentroid}};
  // Overlapping triangles front to back and back to front, one crossing the near plane.
  const float zs[] = {0.9f, 0.2f, 0.6f, 0.1f, 0.95f};
  for (int i = 0; i < 5; ++i) {
    const float o = static_cast<float>(i) * 0.1f;
    Primitive p = clip_tri({-0.9f + o, -0.8f, zs[i], 1}, {0.9f, -0.7f + o, zs[i] * 0.5f, 1.5f},
                           {o - 0.2f, 0.9f, i == 2 ? -0.4f : zs[i], 1});
    p.attr = {{0}, {static_cast<float>(i)}, {10}};
    s.primitives.push_back(p);
  }
  const PipeResult plain = run(s, PipeOptions::plain());
  for (const CompareFunc f : {CompareFunc::kLess, CompareFunc::kGreaterEqual}) {
    s.depth->func = f;
    const PipeResult ref = run(s, PipeOptions::plain());
    for (int mask = 0; mask < 32; ++mask) {
      PipeOptions o;
      o.binning = (mask & 1) != 0;
      o.hiz = (mask & 2) != 0;
      o.early_z = (mask & 4) != 0;
      o.fast_clear = (mask & 8) != 0;
      o.tile_size = (mask & 16) != 0 ? 32 : 16;
      o.render.threads = (mask & 1) != 0 ? 3 : 1;
      const PipeResult r = run(s, o);
      EXPECT_EQ(r.fragments, ref.fragments) << "options " << mask;
      EXPECT_EQ(r.data, ref.data) << "options " << mask;
      EXPECT_EQ(r.depth_buffer, ref.depth_buffer) << "options " << mask;
    }
  }
  EXPECT_FALSE(plain.fragments.empty());
}

} // namespace
} // namespace rastrules::pipe

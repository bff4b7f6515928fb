// SPDX-License-Identifier: MIT
// The fast traversal through the scene entry points: the default options (the fast traversal
// with the best instruction set) render exactly what Traversal::kPlain renders, for triangles,
// points, quadrilateral lines, multisampled diamond lines, sample masks, centroids and quads,
// with every supported instruction set; the streamed and bounded entry points agree.

#include <gtest/gtest.h>

#include <cstdint>
#include <variant>
#include <vector>

#include "fast_support.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::test {
namespace {

Primitive prim(PrimitiveType type, std::vector<FloatPoint> v, bool aa = false) {
  Primitive p;
  p.type = type;
  p.v = std::move(v);
  p.aa = aa;
  return p;
}

Scene mixed_scene(std::int32_t w, std::int32_t h) {
  Scene s;
  s.width = w;
  s.height = h;
  s.primitives = {
      prim(PrimitiveType::kTriangle, {{1.5f, 2.25f}, {60.0f, 7.0f}, {20.0f, 45.5f}}),
      prim(PrimitiveType::kTriangle, {{60.0f, 7.0f}, {1.5f, 2.25f}, {70.0f, 40.0f}}),
      prim(PrimitiveType::kTriangle, {{-500.0f, -500.0f}, {900.0f, -400.0f}, {-300.0f, 900.0f}}),
      prim(PrimitiveType::kPoint, {{15.5f, 16.0f}}),
      prim(PrimitiveType::kPoint, {{0.0f, 0.0f}}),
      prim(PrimitiveType::kLine, {{2.0f, 3.5f}, {50.25f, 30.0f}}),
      prim(PrimitiveType::kLine, {{31.5f, 0.0f}, {31.5f, 47.0f}}, true),
      prim(PrimitiveType::kLineStrip, {{4.0f, 40.0f}, {33.0f, 17.0f}, {62.0f, 44.0f}}),
  };
  return s;
}

std::vector<Fragment> render_ok(const Scene& s, const RenderOptions& o) {
  auto r = render(s, o);
  if (const auto* err = std::get_if<SceneError>(&r)) {
    ADD_FAILURE() << err->what();
    return {};
  }
  return std::get<std::vector<Fragment>>(r);
}

// The scene's fragments with the plain traversal, the default, and each supported instruction
// set; also primitive by primitive through rasterize_primitive and the streamed entry points.
void expect_traversals_agree(const Scene& s) {
  RenderOptions plain;
  plain.traversal = Traversal::kPlain;
  const std::vector<Fragment> want = render_ok(s, plain);
  EXPECT_EQ(render_ok(s, RenderOptions{}), want);
  const auto d = render(s);
  ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(d));
  EXPECT_EQ(std::get<std::vector<Fragment>>(d), want);
  const auto prepared = prepare(s);
  ASSERT_TRUE(std::holds_alternative<PreparedScene>(prepared));
  const PreparedScene& ps = std::get<PreparedScene>(prepared);
  for (Isa isa : supported_isas()) {
    RenderOptions o;
    o.isa = isa;
    EXPECT_EQ(render_ok(s, o), want) << isa_name(isa);
    for (std::size_t p = 0; p < ps.primitives.size(); ++p) {
      const std::vector<Fragment> pp = rasterize_primitive(ps, p, plain);
      EXPECT_EQ(rasterize_primitive(ps, p, o), pp) << isa_name(isa) << " prim " << p;
      std::vector<Fragment> streamed, bounded;
      for_each_fragment(ps, p, o, [&](const Fragment& f) { streamed.push_back(f); });
      EXPECT_EQ(streamed, pp) << isa_name(isa) << " prim " << p;
      EXPECT_TRUE(for_each_fragment_bounded(ps, p, 1u << 20, o,
                                            [&](const Fragment& f) { bounded.push_back(f); }));
      EXPECT_EQ(bounded, pp) << isa_name(isa) << " prim " << p;
    }
  }
}

// rule: FAST.EQUALS.PLAIN, FAST.ISA.DISPATCH
TEST(FastScene, DefaultOptionsRenderWhatThePlainTraversalRenders) {
  Scene s = mixed_scene(64, 48);
  expect_traversals_agree(s);
  for (LineMode m : {LineMode::kQuadWide, LineMode::kQuadNarrow, LineMode::kVulkanBresenham}) {
    s.conventions.line_mode = m;
    for (auto& p : s.primitives)
      p.aa = false;
    expect_traversals_agree(s);
  }
  // The render without options is the fast traversal with the best instruction set.
  EXPECT_EQ(RenderOptions{}.traversal, Traversal::kFast);
  EXPECT_FALSE(RenderOptions{}.isa.has_value());
}

// rule: FAST.EQUALS.PLAIN, MSAA.LINE.MODE, MSAA.MASK.AND
TEST(FastScene, MultisampledScenesWithMasksCentroidsAndQuads) {
  for (std::uint32_t n : {2u, 4u, 8u, 16u}) {
    Scene s = mixed_scene(64, 48); // diamond lines become quadrilaterals with several samples
    set_sample_pattern(s, standard_pattern(n));
    expect_traversals_agree(s);
    s.msaa.sample_mask = full_mask(n) & 0x5555u;
    s.msaa.has_centroid = true;
    s.conventions.centroid = CentroidRule::kD3D10;
    s.msaa.quads = true;
    s.msaa.derivatives = DerivativeMode::kFine;
    expect_traversals_agree(s);
    s.msaa.shading = ShadingRate::kSample;
    s.msaa.has_centroid = false;
    expect_traversals_agree(s);
  }
  Scene c = mixed_scene(40, 40);
  c.conventions.line_mode = LineMode::kVulkanBresenham;
  for (auto& p : c.primitives)
    p.aa = false;
  set_sample_pattern(c, center_pattern(4));
  expect_traversals_agree(c);
  set_sample_pattern(c, custom_pattern({{-8, -8}, {7, 3}, {2, 7}}));
  c.conventions.line_mode = LineMode::kD3DDiamond;
  expect_traversals_agree(c);
}

// rule: FAST.EQUALS.PLAIN
TEST(FastScene, LargeTargetsAndTheBoundedPath) {
  Scene s;
  s.width = kMaxTargetSide;
  s.height = 300;
  s.primitives = {
      prim(PrimitiveType::kTriangle, {{16000.0f, 10.0f}, {16390.0f, 100.0f}, {16100.0f, 310.0f}}),
      prim(PrimitiveType::kPoint, {{16383.75f, 299.5f}}),
      prim(PrimitiveType::kLine, {{16200.0f, 5.0f}, {16384.0f, 250.0f}}),
  };
  s.conventions.line_mode = LineMode::kQuadWide;
  expect_traversals_agree(s);
  // A bound of zero entries for a collected primitive (the point): both traversals refuse it the
  // same way.
  const PreparedScene ps = std::get<PreparedScene>(prepare(s));
  RenderOptions plain;
  plain.traversal = Traversal::kPlain;
  for (const RenderOptions& o : {plain, RenderOptions{}}) {
    std::size_t n = 0;
    EXPECT_FALSE(for_each_fragment_bounded(ps, 1, 0, o, [&](const Fragment&) { ++n; }));
    EXPECT_EQ(n, 0u);
  }
}

} // namespace
} // namespace rastrules::test

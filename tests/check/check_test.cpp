// SPDX-License-Identifier: MIT
// The checker (check/): the kernel's own fragments agree with the oracle, and every kind of
// tampering with them is found and named, for one-sample, multisampled and pipeline scenes.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "check_support.hpp"
#include "rastrules/check/check.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/pipeline.hpp"
#include "support.hpp"

namespace rastrules::check {
namespace {

Scene mixed_scene() {
  Scene s;
  s.width = 12;
  s.height = 10;
  s.primitives.push_back(
      make_triangle({FloatPoint{0.5f, 0.5f}, FloatPoint{9.5f, 0.5f}, FloatPoint{0.5f, 8.5f}}));
  s.primitives.push_back(test::prim_px(PrimitiveType::kPoint, {{10.5f, 8.5f}}));
  s.primitives.push_back(
      test::prim_px(PrimitiveType::kLineStrip, {{1.0f, 9.0f}, {11.0f, 6.0f}, {6.0f, 1.0f}}));
  return s;
}

struct Rasterized {
  PreparedScene ps;
  std::vector<Fragment> fragments;
};
Rasterized run(const Scene& s) {
  auto prepared = prepare(s);
  EXPECT_TRUE(std::holds_alternative<PreparedScene>(prepared));
  Rasterized r{std::get<PreparedScene>(prepared), {}};
  r.fragments = rasterize(r.ps);
  return r;
}

using test_support::mentions;

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.PRIM.LINE_STRIP, SCENE.PRIM.POINT
TEST(Check, TheKernelAgreesAndTamperingIsNamed) {
  const Scene s = mixed_scene();
  const Rasterized r = run(s);
  const Mismatches ok = check_against_oracle(s, r.ps, r.fragments);
  EXPECT_TRUE(ok.agree()) << (ok.mismatches.empty() ? "" : ok.mismatches.front());
  EXPECT_EQ(ok.oracles,
            (std::vector<std::string>{"triangle oracle (render)", "point oracle (point_covers)",
                                      "line oracle (aliased_line_pixels)"}));

  std::vector<Fragment> missing = r.fragments;
  missing.erase(missing.begin() + 3);
  EXPECT_TRUE(mentions(check_against_oracle(s, r.ps, missing), "only the oracle covers prim 0"));

  std::vector<Fragment> moved = r.fragments;
  moved.back().x += 1;
  const Mismatches m = check_against_oracle(s, r.ps, moved);
  EXPECT_FALSE(m.agree());
  EXPECT_TRUE(mentions(m, "only the kernel covers prim 2"));

  std::vector<Fragment> masked = r.fragments;
  masked.front().mask = 3;
  EXPECT_TRUE(mentions(check_against_oracle(s, r.ps, masked), ": mask 3"));

  std::vector<Fragment> no_seg = r.fragments;
  no_seg.back().seg.reset();
  EXPECT_TRUE(mentions(check_against_oracle(s, r.ps, no_seg), "seg on a non-strip or missing"));

  // At most max_mismatches are kept, all are counted.
  std::vector<Fragment> none;
  const Mismatches capped = check_against_oracle(s, r.ps, none, CheckOptions{2});
  EXPECT_EQ(capped.mismatches.size(), 2u);
  EXPECT_EQ(capped.count, r.fragments.size());
}

// rule: SCENE.OUTPUT.MSAA, MSAA.CENTROID.D3D11, MSAA.RESOLVE.AVERAGE
TEST(Check, MultisampledScenesGoToTheMultisamplingOracle) {
  Scene s = mixed_scene();
  set_sample_pattern(s, standard_pattern(4));
  s.msaa.has_centroid = true;
  ASSERT_TRUE(multisampled(s));
  const Rasterized r = run(s);
  const Mismatches ok = check_against_oracle(s, r.ps, r.fragments);
  EXPECT_TRUE(ok.agree()) << (ok.mismatches.empty() ? "" : ok.mismatches.front());
  EXPECT_EQ(ok.oracles,
            (std::vector<std::string>{"multisampling oracle (msaa::render, msaa::resolve)"}));
  std::vector<Fragment> tampered = r.fragments;
  auto partial = std::find_if(tampered.begin(), tampered.end(),
                              [](const Fragment& f) { return f.mask != 15u && f.centroid; });
  ASSERT_NE(partial, tampered.end());
  partial->centroid->offset = SampleOffset{0, 0};
  EXPECT_TRUE(mentions(check_against_oracle(s, r.ps, tampered), "centroid"));
}

// An antialiased d3d line on a multisampled target without MultisampleEnable keeps its
// coverage (MSAA.LINE.MODE): the pixels and masks against the multisampling oracle, each
// coverage against the antialiased-line oracle; with MultisampleEnable it has none.
// rule: MSAA.LINE.MODE, LINE.AA.FRAGMENT
TEST(Check, MultisampledAntialiasedLinesKeepTheirCoverageWithoutMultisampleEnable) {
  Scene s = mixed_scene();
  s.primitives[2].aa = true;
  set_sample_pattern(s, standard_pattern(4));
  const Rasterized r = run(s);
  const Mismatches ok = check_against_oracle(s, r.ps, r.fragments);
  EXPECT_TRUE(ok.agree()) << (ok.mismatches.empty() ? "" : ok.mismatches.front());
  EXPECT_NE(
      std::find(ok.oracles.begin(), ok.oracles.end(), "AA-line oracle (aa_check within 1/65536)"),
      ok.oracles.end());
  std::vector<Fragment> tampered = r.fragments;
  auto line = std::find_if(tampered.begin(), tampered.end(),
                           [](const Fragment& f) { return f.coverage_q16.has_value(); });
  ASSERT_NE(line, tampered.end());
  *line->coverage_q16 += 2;
  EXPECT_TRUE(mentions(check_against_oracle(s, r.ps, tampered), "coverage"));
  line->coverage_q16.reset();
  EXPECT_TRUE(mentions(check_against_oracle(s, r.ps, tampered), "coverage missing"));
  s.conventions.multisample_enable = true; // quadrilaterals: no coverage
  const Rasterized q = run(s);
  EXPECT_TRUE(std::none_of(q.fragments.begin(), q.fragments.end(),
                           [](const Fragment& f) { return f.coverage_q16.has_value(); }));
  const Mismatches quads = check_against_oracle(s, q.ps, q.fragments);
  EXPECT_TRUE(quads.agree()) << (quads.mismatches.empty() ? "" : quads.mismatches.front());
}

// rule: PIPE.INTERP.BOUND, PIPE.DEPTH.BOUND, PIPE.BARY.SUM
TEST(Check, PipelineValuesWithinTheOraclesBounds) {
  rastrules::Scene s;
  s.width = s.height = 16;
  s.attributes = {
      pipe::AttributeDecl{"u", pipe::Interpolation::kPerspective, pipe::Location::kCenter}};
  s.depth = pipe::DepthState{};
  rastrules::Primitive p;
  p.type = PrimitiveType::kTriangle;
  p.pos = {{-0.9f, -0.9f, 0.2f, 1.0f}, {0.9f, -0.9f, 0.5f, 2.0f}, {-0.9f, 0.9f, 0.8f, 4.0f}};
  p.attr = {{0.0f}, {1.0f}, {2.0f}};
  s.primitives.push_back(p);
  auto out = pipe::run_pipeline(s);
  ASSERT_TRUE(std::holds_alternative<pipe::PipeResult>(out));
  pipe::PipeResult r = std::get<pipe::PipeResult>(out);
  PipelineStats st;
  EXPECT_TRUE(check_pipeline(s, r, {}, &st).agree());
  EXPECT_EQ(st.values_checked, 2 * r.fragments.size()); // one attribute, one depth per fragment
  EXPECT_EQ(st.fragments, r.fragments.size());          // the replay saw every fragment
  EXPECT_GT(st.attr_checks, 0u);
  EXPECT_GT(st.depth_checks, 0u);
  r.data[0].attr[0] += 0.25f;
  EXPECT_TRUE(mentions(check_pipeline(s, r), "attribute u"));
  r.data[1].bary->area += 1;
  EXPECT_TRUE(mentions(check_pipeline(s, r), "PIPE.BARY.SUM"));
}

// The replay from the scene alone trusts nothing the kernel reports: each kind of tampering
// that the value invariants cannot see is found and named by it.
// rule: PIPE.DEPTH.TEST, PIPE.DEPTH.WRITE, PIPE.CLIP.UNCLIPPED, SCENE.OUTPUT.PIPELINE
TEST(Check, ThePipelineReplayFindsWhatTheValuesCannotSee) {
  rastrules::Scene s;
  s.width = s.height = 16;
  s.depth = pipe::DepthState{};
  s.depth->func = pipe::CompareFunc::kLess;
  for (const float z : {0.5f, 0.25f}) { // the second triangle is nearer: it passes everywhere
    rastrules::Primitive p;
    p.type = PrimitiveType::kTriangle;
    p.pos = {{-0.9f, -0.9f, z, 1.0f}, {0.9f, -0.9f, z, 1.0f}, {-0.9f, 0.9f, z, 1.0f}};
    s.primitives.push_back(p);
  }
  auto out = pipe::run_pipeline(s);
  ASSERT_TRUE(std::holds_alternative<pipe::PipeResult>(out));
  const pipe::PipeResult good = std::get<pipe::PipeResult>(out);
  ASSERT_TRUE(check_pipeline(s, good).agree()) << check_pipeline(s, good).mismatches.front();
  ASSERT_GT(good.fragments.size(), 2u);
  const auto tampered = [&](auto&& change) {
    pipe::PipeResult r = good;
    change(r);
    return check_pipeline(s, r);
  };
  // The output order (prim, part, y, x, ...).
  EXPECT_TRUE(mentions(tampered([](pipe::PipeResult& r) {
                         std::swap(r.fragments[0], r.fragments[1]);
                         std::swap(r.data[0], r.data[1]);
                       }),
                       "out of order"));
  // The final depth buffer against the replayed depth test.
  EXPECT_TRUE(mentions(tampered([](pipe::PipeResult& r) { r.depth_buffer[0].unorm ^= 1u; }),
                       "depth buffer sample 0"));
  // The passed mask against the replayed depth test.
  EXPECT_TRUE(mentions(tampered([](pipe::PipeResult& r) { r.data.back().passed = 0; }), "killed"));
  // The drawn primitive against the oracle's transform and snapping.
  EXPECT_TRUE(mentions(tampered([](pipe::PipeResult& r) {
                         r.drawn[0].z[0] = std::nextafter(r.drawn[0].z[0], 1.0f);
                       }),
                       "drawn primitive differs"));
  // A fragment outside the target.
  EXPECT_TRUE(
      mentions(tampered([](pipe::PipeResult& r) { r.fragments.back().x = 16; }), "outside"));
  // Coverage against the window-space render: a fragment missing (without depth, so that no
  // depth buffer tells first).
  s.depth.reset();
  auto plain = pipe::run_pipeline(s);
  ASSERT_TRUE(std::holds_alternative<pipe::PipeResult>(plain));
  pipe::PipeResult r = std::get<pipe::PipeResult>(plain);
  ASSERT_TRUE(check_pipeline(s, r).agree());
  r.fragments.pop_back();
  r.data.pop_back();
  EXPECT_TRUE(mentions(check_pipeline(s, r), "coverage of primitive 1"));
  // And of a strip, and of a clip-space line.
  for (const auto& [type, name] : {std::pair{PrimitiveType::kLineStrip, "coverage of strip 0"},
                                   std::pair{PrimitiveType::kLine, "coverage of line 0"}}) {
    rastrules::Primitive line;
    line.type = type;
    line.pos = {{-0.9f, -0.5f, 0.5f, 1.0f}, {0.9f, 0.5f, 0.5f, 1.0f}};
    if (type == PrimitiveType::kLineStrip)
      line.pos.push_back({-0.5f, 0.9f, 0.5f, 1.0f});
    s.primitives = {line};
    auto drawn = pipe::run_pipeline(s);
    ASSERT_TRUE(std::holds_alternative<pipe::PipeResult>(drawn));
    pipe::PipeResult lr = std::get<pipe::PipeResult>(drawn);
    ASSERT_TRUE(check_pipeline(s, lr).agree()) << name;
    lr.fragments.pop_back();
    lr.data.pop_back();
    EXPECT_TRUE(mentions(check_pipeline(s, lr), name)) << name;
  }
}

} // namespace
} // namespace rastrules::check

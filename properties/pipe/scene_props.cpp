// SPDX-License-Identifier: MIT
// Properties of whole scenes through run_pipeline: random targets, raster and multisample
// states, viewports, transforms, attributes (perspective, linear, flat at the centre, centroid
// or sample), depth states (every format and compare function, writes on and off, clear values,
// depth clipping on and off, viewport depth ranges near the format limits), and primitives given
// in window space or in clip space (inside the view, across the near and far planes, behind the
// eye, across the guard band, w ratios of 1e6 and more). Checked against the oracle fragment by
// fragment (pipe_scene.hpp): barycentrics, attributes and depths within the spec's bounds,
// coverage of every part equal to the window-space path, the depth test replayed, killed
// fragments; and the result is bit-identical across two runs and across every combination of
// the optimizations, traversals and thread counts.
// Implements (properties for): PIPE.CLIP.UNCLIPPED, PIPE.CLIP.POLYGON, PIPE.BARY.EXACT,
//   PIPE.INTERP.LOCATION, PIPE.INTERP.PERSPECTIVE, PIPE.INTERP.LINEAR, PIPE.INTERP.FLAT,
//   PIPE.INTERP.HORIZON, PIPE.INTERP.BOUND, PIPE.DEPTH.INTERP, PIPE.DEPTH.BOUND, PIPE.DEPTH.TEST,
//   PIPE.DEPTH.WRITE, PIPE.DEPTH.KILL, PIPE.VIEWPORT.SCISSOR, PIPE.OPT.TILES, PIPE.OPT.HIZ,
//   PIPE.OPT.EARLY_Z, PIPE.OPT.FAST_CLEAR, PIPE.OPT.THREADS

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "pipe_gen.hpp"
#include "pipe_scene.hpp"

namespace {

namespace pg = rastrules::pipe_gen;
namespace ps = rastrules::pipe_scene;
namespace kp = rastrules::pipe;
using rastrules::CullMode;
using rastrules::FillConvention;
using rastrules::FrontFace;
using rastrules::PrimitiveType;

// A clip-space vertex in or near the view: NDC x, y in [-1.5, 1.5], z/w in [-0.1, 1.1], w from
// 1e-6 to 1e6 (so a triangle's w ratios reach 1e12).
rc::Gen<kp::Vec4f> view_vertex() {
  return rc::gen::exec([] {
    const float w = *rc::gen::element(1.0f, 0.5f, 2.0f, 8.0f, 1e-3f, 1e3f, 1e-6f, 1e6f, 0.3f);
    const auto ndc = [](int lo, int hi) { return static_cast<float>(*rc::gen::inRange(lo, hi + 1)) / 256.0f; };
    return kp::Vec4f{ndc(-384, 384) * w, ndc(-384, 384) * w, ndc(-26, 282) * w, w};
  });
}

rc::Gen<kp::Vec4f> scene_vertex() {
  return rc::gen::weightedOneOf<kp::Vec4f>({{5, view_vertex()}, {1, pg::clip_vertex()}});
}

rc::Gen<kp::PipeScene> pipe_scene(std::int32_t max_side, int max_prims) {
  return rc::gen::exec([max_side, max_prims] {
    kp::PipeScene s;
    s.base.width = *rc::gen::inRange(2, max_side + 1);
    s.base.height = *rc::gen::inRange(2, max_side + 1);
    s.base.state.cull = *rc::gen::weightedElement<CullMode>(
        {{3, CullMode::kNone}, {1, CullMode::kBack}, {1, CullMode::kFront}});
    s.base.state.front_face = *rc::gen::element(FrontFace::kClockwise, FrontFace::kCounterClockwise);
    s.base.state.fill = *rc::gen::element(FillConvention::kTopLeft, FillConvention::kTopRight,
                                          FillConvention::kBottomLeft, FillConvention::kBottomRight);
    const std::uint32_t n = *rc::gen::element(1u, 1u, 4u, 8u);
    s.base.msaa.pattern = rastrules::standard_pattern(n);
    const bool sample_shading = n > 1 && *rc::gen::inRange(0, 4) == 0;
    s.base.msaa.shading = sample_shading ? rastrules::ShadingRate::kSample : rastrules::ShadingRate::kPixel;
    s.base.msaa.centroid_rule = *rc::gen::element(rastrules::CentroidRule::kD3D11, rastrules::CentroidRule::kD3D10);
    const int nattr = *rc::gen::inRange(0, 4);
    for (int k = 0; k < nattr; ++k) {
      kp::AttributeDecl a;
      a.name = "a" + std::to_string(k);
      a.interpolation = *rc::gen::element(kp::Interpolation::kPerspective, kp::Interpolation::kPerspective,
                                          kp::Interpolation::kLinear, kp::Interpolation::kFlat);
      a.location = sample_shading ? *rc::gen::element(kp::Location::kCenter, kp::Location::kSample)
                                  : *rc::gen::element(kp::Location::kCenter, kp::Location::kCentroid);
      s.attributes.push_back(a);
    }
    const int vp_kind = *rc::gen::inRange(0, 10);
    if (vp_kind >= 5) s.viewport = *pg::viewport(s.base.width, s.base.height, vp_kind == 9);
    if (*rc::gen::inRange(0, 10) == 0) s.model = *pg::matrix();
    if (*rc::gen::inRange(0, 10) == 0) s.projection = *pg::matrix();
    if (*rc::gen::inRange(0, 10) < 7) {
      kp::DepthState d;
      d.format = *pg::depth_format();
      d.func = *pg::compare_func();
      d.write = *rc::gen::inRange(0, 4) != 0;
      d.clear = std::min(1.0f, std::fabs(*pg::depth_value()));
      d.clip = *rc::gen::inRange(0, 5) != 0;
      if (*rc::gen::inRange(0, 10) < 3) d.bias = *pg::depth_bias_state();
      s.depth = d;
    }
    s.provoking = *rc::gen::element(kp::Provoking::kFirst, kp::Provoking::kLast);
    const int nprims = *rc::gen::inRange(1, max_prims + 1);
    for (int i = 0; i < nprims; ++i) {
      kp::PipePrimitive p;
      const int kind = *rc::gen::inRange(0, 20);
      p.base.type = kind == 0 ? PrimitiveType::kPoint : (kind == 1 ? PrimitiveType::kLine : PrimitiveType::kTriangle);
      const std::size_t nv = rastrules::required_vertex_count(p.base.type);
      if (*rc::gen::inRange(0, 10) < 3) {
        // Window space, with depths and w.
        const rastrules::gen::GenTriangle t = *rastrules::gen::triangle_near(s.base.width, s.base.height);
        p.base.v.assign(t.v.begin(), t.v.begin() + static_cast<std::ptrdiff_t>(nv));
        const auto z = *pg::depth_triple();
        const auto w = *pg::w_triple();
        if (*rc::gen::inRange(0, 4) != 0) p.z.assign(z.begin(), z.begin() + static_cast<std::ptrdiff_t>(nv));
        if (*rc::gen::arbitrary<bool>()) p.w.assign(w.begin(), w.begin() + static_cast<std::ptrdiff_t>(nv));
      } else {
        for (std::size_t j = 0; j < nv; ++j) {
          kp::Vec4f v = *scene_vertex();
          if (!pg::position_ok(v)) v = {0.0f, 0.0f, 0.5f, 1.0f};
          p.pos.push_back(v);
        }
      }
      for (std::size_t j = 0; j < nv && nattr > 0; ++j) {
        std::vector<float> a;
        for (int k = 0; k < nattr; ++k) a.push_back(*pg::attr_value());
        p.attr.push_back(a);
      }
      s.primitives.push_back(p);
    }
    return s;
  });
}

bool transform_rejected(const kp::PipeScene& s, const rastrules::SceneError& e) {
  if (!s.model && !s.view && !s.projection) return false;
  for (std::size_t i = 0; i < s.primitives.size(); ++i) {
    if (ps::geometry(s, i).transform_error) return e.field.rfind("primitives[", 0) == 0;
  }
  return false;
}

// Runs s; fails on an error unless a transform overflowed (then returns nothing).
std::optional<kp::PipeResult> run(const kp::PipeScene& s, const kp::PipeOptions& o) {
  auto r = kp::run_pipeline(s, o);
  if (const auto* e = std::get_if<rastrules::SceneError>(&r)) {
    if (transform_rejected(s, *e)) return std::nullopt;
    RC_FAIL("run_pipeline rejected a valid scene: " + e->what() + "\n" + ps::show(s));
  }
  return std::move(std::get<kp::PipeResult>(r));
}

// rule: PIPE.CLIP.UNCLIPPED, PIPE.CLIP.POLYGON, PIPE.BARY.EXACT, PIPE.INTERP.LOCATION
// rule: PIPE.INTERP.PERSPECTIVE, PIPE.INTERP.LINEAR, PIPE.INTERP.FLAT, PIPE.INTERP.HORIZON
// rule: PIPE.INTERP.BOUND, PIPE.DEPTH.INTERP, PIPE.DEPTH.BOUND, PIPE.DEPTH.TEST, PIPE.DEPTH.WRITE
// rule: PIPE.DEPTH.KILL, PIPE.VIEWPORT.SCISSOR
RC_GTEST_PROP(PipeScene, FragmentsAgreeWithTheOracle, ()) {
  const kp::PipeScene s = *pg::full_size(pipe_scene(12, 4));
  const auto r = run(s, kp::PipeOptions::plain());
  if (!r) {
    RC_TAG("rejected: transform overflow");
    return;
  }
  ps::CheckStats st;
  const std::string problem = ps::check_result(s, *r, st);
  if (!problem.empty()) RC_FAIL(problem + "\n" + ps::show(s));
  const std::string coverage = ps::check_coverage(s, *r);
  if (!coverage.empty()) RC_FAIL(coverage + "\n" + ps::show(s));
  RC_CLASSIFY(st.clipped_prims > 0, "clipped primitives");
  RC_CLASSIFY(st.killed > 0, "killed fragments");
  RC_CLASSIFY(st.attr_checks > 0, "attributes checked");
  RC_CLASSIFY(st.depth_checks > 0, "depths checked");
  RC_CLASSIFY(st.horizon, "beyond the horizon");
  RC_CLASSIFY(st.fragments == 0, "no fragment");
  if (st.fragments == 0 && std::getenv("PIPE_DEBUG")) std::cerr << ps::show(s) << "\n";
}

std::string first_difference(const kp::PipeResult& a, const kp::PipeResult& b) {
  if (a.fragments.size() != b.fragments.size())
    return std::to_string(a.fragments.size()) + " vs " + std::to_string(b.fragments.size()) + " fragments";
  for (std::size_t i = 0; i < a.fragments.size(); ++i) {
    if (!(a.fragments[i] == b.fragments[i])) return "fragment " + std::to_string(i) + " differs";
  }
  if (a.data.size() != b.data.size()) return "data sizes differ";
  for (std::size_t i = 0; i < a.data.size(); ++i) {
    if (!(a.data[i] == b.data[i])) {
      std::string s = "data of fragment " + std::to_string(i) + " (x " + std::to_string(a.fragments[i].x) +
                      ", y " + std::to_string(a.fragments[i].y) + ") differs: passed " +
                      std::to_string(a.data[i].passed) + " vs " + std::to_string(b.data[i].passed) +
                      ", attr " + pg::fs(a.data[i].attr) + " vs " + pg::fs(b.data[i].attr);
      return s;
    }
  }
  if (a.depth_buffer != b.depth_buffer) return "depth buffers differ";
  return "";
}

rc::Gen<kp::PipeOptions> options() {
  return rc::gen::exec([] {
    kp::PipeOptions o;
    o.render.traversal = *rc::gen::element(rastrules::Traversal::kPlain, rastrules::Traversal::kFast);
    o.render.threads = *rc::gen::element(1u, 3u);
    o.tile_size = *rc::gen::element(16, 32);
    o.binning = *rc::gen::arbitrary<bool>();
    o.hiz = *rc::gen::arbitrary<bool>();
    o.early_z = *rc::gen::arbitrary<bool>();
    o.fast_clear = *rc::gen::arbitrary<bool>();
    return o;
  });
}

std::string describe(const kp::PipeOptions& o) {
  return std::string("traversal ") + (o.render.traversal == rastrules::Traversal::kPlain ? "plain" : "fast") +
         ", threads " + std::to_string(o.render.threads) + ", tile " + std::to_string(o.tile_size) +
         (o.binning ? ", binning" : "") + (o.hiz ? ", hiz" : "") + (o.early_z ? ", early-z" : "") +
         (o.fast_clear ? ", fast clear" : "");
}

// rule: PIPE.OPT.TILES, PIPE.OPT.HIZ, PIPE.OPT.EARLY_Z, PIPE.OPT.FAST_CLEAR, PIPE.OPT.THREADS
// rule: FAST.EQUALS.PLAIN, FAST.THREADS.DETERMINISTIC
RC_GTEST_PROP(PipeScene, OptimizationsTraversalsAndThreadsChangeNothing, ()) {
  // Larger targets than above, so that scenes span several 16 and 32 px tiles.
  const kp::PipeScene s = *pg::full_size(pipe_scene(70, 6));
  const auto plain = run(s, kp::PipeOptions::plain());
  if (!plain) return;
  const auto again = run(s, kp::PipeOptions::plain());
  const std::string d0 = first_difference(*plain, *again);
  if (!d0.empty()) RC_FAIL("two plain runs differ: " + d0 + "\n" + ps::show(s));
  const kp::PipeOptions defaults;
  const auto fast = run(s, defaults);
  const std::string d1 = first_difference(*plain, *fast);
  if (!d1.empty()) RC_FAIL("default options (" + describe(defaults) + ") differ from plain: " + d1 + "\n" + ps::show(s));
  const kp::PipeOptions o = *options();
  const auto other = run(s, o);
  const std::string d2 = first_difference(*plain, *other);
  if (!d2.empty()) RC_FAIL("options (" + describe(o) + ") differ from plain: " + d2 + "\n" + ps::show(s));
  RC_CLASSIFY(fast->stats.hiz_rejected > 0, "Hi-Z rejected something");
  RC_CLASSIFY(s.base.width > 32 || s.base.height > 32, "several 32 px tiles");
}

}  // namespace

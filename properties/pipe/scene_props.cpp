// SPDX-License-Identifier: MIT
// Properties of whole scenes through run_pipeline: random targets, raster and multisample
// states (partial sample masks, 2x2 quads with helper lanes and derivatives, every line mode),
// viewports, transforms, attributes (perspective, linear, flat at the centre, centroid or
// sample; centroid also under sample shading), depth states (every format and compare
// function, writes on and off, clear values, depth clipping on and off, viewport depth ranges
// near the format limits), and triangles, points, lines and line strips given in window space
// or in clip space (inside the view, across the near and far planes, behind the eye, across the
// guard band, w ratios of 1e6 and more). Checked against the oracle fragment by fragment
// (check::check_pipeline): barycentrics, attributes and depths within the spec's bounds (each strip
// segment from its own vertices), coverage of every part equal to the window-space path, the
// depth test replayed, killed fragments; each strip segment equals the same segment drawn as a
// line; and the result is bit-identical across two runs and across every combination of the
// optimizations, traversals and thread counts.
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
#include <tuple>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "pipe_gen.hpp"
#include "pipe_scene.hpp"
#include "rastrules/check/check.hpp"
#include "strips.hpp"

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
    const auto ndc = [](int lo, int hi) {
      return static_cast<float>(*rc::gen::inRange(lo, hi + 1)) / 256.0f;
    };
    return kp::Vec4f{ndc(-384, 384) * w, ndc(-384, 384) * w, ndc(-26, 282) * w, w};
  });
}

rc::Gen<kp::Vec4f> scene_vertex() {
  return rc::gen::weightedOneOf<kp::Vec4f>({{5, view_vertex()}, {1, pg::clip_vertex()}});
}

// A primitive of the given type for scene s (its target, line mode and attributes): in window
// space with depths and w (a strip's vertices from several triangles) or in clip space; strips
// have 2 to 5 vertices; lines are sometimes antialiased where the line mode allows it.
rc::Gen<rastrules::Primitive> primitive(const rastrules::Scene& scene, PrimitiveType type) {
  // By value: RapidCheck calls this again while shrinking, after the scene is gone.
  struct State {
    std::int32_t width, height;
    rastrules::LineMode line_mode;
    std::size_t nattr;
  };
  const State s{scene.width, scene.height, scene.conventions.line_mode, scene.attributes.size()};
  return rc::gen::exec([s, type] {
    rastrules::Primitive p;
    p.type = type;
    p.v.clear(); // a default Primitive is a triangle with three vertices
    const bool linelike = type == PrimitiveType::kLine || type == PrimitiveType::kLineStrip;
    p.aa =
        linelike && s.line_mode == rastrules::LineMode::kD3DDiamond && *rc::gen::inRange(0, 6) == 0;
    const std::size_t nv = type == PrimitiveType::kLineStrip
                               ? static_cast<std::size_t>(*rc::gen::inRange(2, 6))
                               : rastrules::required_vertex_count(type);
    if (*rc::gen::inRange(0, 10) < 3) {
      const bool with_z = *rc::gen::inRange(0, 4) != 0, with_w = *rc::gen::arbitrary<bool>();
      while (p.v.size() < nv) {
        const rastrules::gen::GenTriangle t = *rastrules::gen::triangle_near(s.width, s.height);
        const auto z = *pg::depth_triple();
        const auto w = *pg::w_triple();
        for (std::size_t j = 0; j < 3 && p.v.size() < nv; ++j) {
          p.v.push_back(t.v[j]);
          if (with_z)
            p.z.push_back(z[j]);
          if (with_w)
            p.w.push_back(w[j]);
        }
      }
    } else {
      for (std::size_t j = 0; j < nv; ++j) {
        kp::Vec4f v = *scene_vertex();
        if (!pg::position_ok(v))
          v = {0.0f, 0.0f, 0.5f, 1.0f};
        p.pos.push_back(v);
      }
    }
    for (std::size_t j = 0; j < nv && s.nattr > 0; ++j) {
      std::vector<float> a;
      for (std::size_t k = 0; k < s.nattr; ++k)
        a.push_back(*pg::attr_value());
      p.attr.push_back(a);
    }
    return p;
  });
}

rc::Gen<rastrules::Scene> pipe_scene(std::int32_t max_side, int max_prims) {
  return rc::gen::exec([max_side, max_prims] {
    rastrules::Scene s;
    s.width = *rc::gen::inRange(2, max_side + 1);
    s.height = *rc::gen::inRange(2, max_side + 1);
    s.cull = *rc::gen::weightedElement<CullMode>(
        {{3, CullMode::kNone}, {1, CullMode::kBack}, {1, CullMode::kFront}});
    s.conventions.front_face =
        *rc::gen::element(FrontFace::kClockwise, FrontFace::kCounterClockwise);
    s.conventions.fill =
        *rc::gen::element(FillConvention::kTopLeft, FillConvention::kTopRight,
                          FillConvention::kBottomLeft, FillConvention::kBottomRight);
    const std::uint32_t n = *rc::gen::element(1u, 1u, 4u, 8u);
    set_sample_pattern(s, rastrules::standard_pattern(n));
    const bool sample_shading = n > 1 && *rc::gen::inRange(0, 4) == 0;
    s.msaa.shading =
        sample_shading ? rastrules::ShadingRate::kSample : rastrules::ShadingRate::kPixel;
    s.conventions.centroid =
        *rc::gen::element(rastrules::CentroidRule::kD3D11, rastrules::CentroidRule::kD3D10);
    // Partial sample masks (MSAA.MASK.AND), and 2x2 quads with helper lanes, with or without the
    // derivatives that need them (MSAA.QUAD.HELPER, MSAA.QUAD.DERIVATIVES): helper lanes carry
    // the attributes a shader's derivatives are formed from.
    if (n > 1 && *rc::gen::inRange(0, 4) == 0)
      s.msaa.sample_mask = *rc::gen::inRange<std::uint32_t>(0, 1u << n);
    const int quads = *rc::gen::inRange(0, 8);
    s.msaa.quads = quads == 0;
    s.msaa.derivatives = quads == 1   ? rastrules::DerivativeMode::kFine
                         : quads == 2 ? rastrules::DerivativeMode::kCoarse
                                      : rastrules::DerivativeMode::kNone;
    const int nattr = *rc::gen::inRange(0, 4);
    for (int k = 0; k < nattr; ++k) {
      kp::AttributeDecl a;
      a.name = "a" + std::to_string(k);
      a.interpolation =
          *rc::gen::element(kp::Interpolation::kPerspective, kp::Interpolation::kPerspective,
                            kp::Interpolation::kLinear, kp::Interpolation::kFlat);
      // Centroid under sample shading too (PIPE.INTERP.LOCATION).
      a.location = sample_shading
                       ? *rc::gen::element(kp::Location::kCenter, kp::Location::kSample,
                                           kp::Location::kCentroid)
                       : *rc::gen::element(kp::Location::kCenter, kp::Location::kCentroid);
      s.attributes.push_back(a);
    }
    const int vp_kind = *rc::gen::inRange(0, 10);
    if (vp_kind >= 5)
      s.viewport = *pg::viewport(s.width, s.height, vp_kind == 9);
    if (*rc::gen::inRange(0, 10) == 0)
      s.model = *pg::matrix();
    if (*rc::gen::inRange(0, 10) == 0)
      s.projection = *pg::matrix();
    if (*rc::gen::inRange(0, 10) < 7) {
      kp::DepthState d;
      s.conventions.depth = *pg::depth_format();
      d.func = *pg::compare_func();
      d.write = *rc::gen::inRange(0, 4) != 0;
      d.clear = std::min(1.0f, std::fabs(*pg::depth_value()));
      d.clip = *rc::gen::inRange(0, 5) != 0;
      if (*rc::gen::inRange(0, 10) < 3)
        d.bias = *pg::depth_bias_state();
      s.depth = d;
    }
    s.conventions.provoking = *rc::gen::element(kp::Provoking::kFirst, kp::Provoking::kLast);
    // Vulkan's Bresenham lines have no sample shading (MSAA.SHADING.SAMPLE).
    s.conventions.line_mode =
        sample_shading
            ? *rc::gen::element(rastrules::LineMode::kD3DDiamond, rastrules::LineMode::kQuadWide,
                                rastrules::LineMode::kQuadNarrow)
            : *rc::gen::element(rastrules::LineMode::kD3DDiamond,
                                rastrules::LineMode::kVulkanBresenham,
                                rastrules::LineMode::kQuadWide, rastrules::LineMode::kQuadNarrow);
    const int nprims = *rc::gen::inRange(1, max_prims + 1);
    for (int i = 0; i < nprims; ++i) {
      // Points, lines and strips (LINE.STRIP.SEQUENCE, PIPE.BARY.LINE) besides triangles.
      const int kind = *rc::gen::inRange(0, 20);
      const PrimitiveType type = kind == 0   ? PrimitiveType::kPoint
                                 : kind == 1 ? PrimitiveType::kLine
                                 : kind <= 3 ? PrimitiveType::kLineStrip
                                             : PrimitiveType::kTriangle;
      s.primitives.push_back(*primitive(s, type));
    }
    return s;
  });
}

bool transform_rejected(const rastrules::Scene& s, const rastrules::SceneError& e) {
  if (!s.model && !s.view && !s.projection)
    return false;
  for (std::size_t i = 0; i < s.primitives.size(); ++i) {
    if (rastrules::check::transform_overflows(s, i))
      return e.field.rfind("primitives[", 0) == 0;
  }
  return false;
}

// Runs s; fails on an error unless a transform overflowed (then returns nothing).
std::optional<kp::PipeResult> run(const rastrules::Scene& s, const kp::PipeOptions& o) {
  auto r = kp::run_pipeline(s, o);
  if (const auto* e = std::get_if<rastrules::SceneError>(&r)) {
    if (transform_rejected(s, *e))
      return std::nullopt;
    RC_FAIL("run_pipeline rejected a valid scene: " + e->what() + "\n" + ps::show(s));
  }
  return std::move(std::get<kp::PipeResult>(r));
}

// rule: PIPE.CLIP.UNCLIPPED, PIPE.CLIP.POLYGON, PIPE.BARY.EXACT, PIPE.INTERP.LOCATION
// rule: PIPE.INTERP.PERSPECTIVE, PIPE.INTERP.LINEAR, PIPE.INTERP.FLAT, PIPE.INTERP.HORIZON
// rule: PIPE.INTERP.BOUND, PIPE.DEPTH.INTERP, PIPE.DEPTH.BOUND, PIPE.DEPTH.TEST, PIPE.DEPTH.WRITE
// rule: PIPE.DEPTH.KILL, PIPE.VIEWPORT.SCISSOR, PIPE.BARY.LINE, LINE.STRIP.SEQUENCE
// rule: MSAA.QUAD.HELPER, MSAA.MASK.AND
RC_GTEST_PROP(Scene, FragmentsAgreeWithTheOracle, ()) {
  const rastrules::Scene s = *pg::full_size(pipe_scene(12, 4));
  const auto r = run(s, kp::PipeOptions::plain());
  if (!r) {
    RC_TAG("rejected: transform overflow");
    return;
  }
  rastrules::check::PipelineStats st;
  const rastrules::check::Mismatches m = rastrules::check::check_pipeline(s, *r, {}, &st);
  if (!m.agree())
    RC_FAIL(m.mismatches.front() + "\n" + ps::show(s));
  RC_CLASSIFY(st.clipped_prims > 0, "clipped primitives");
  RC_CLASSIFY(st.killed > 0, "killed fragments");
  RC_CLASSIFY(st.attr_checks > 0, "attributes checked");
  RC_CLASSIFY(st.depth_checks > 0, "depths checked");
  RC_CLASSIFY(st.horizon, "beyond the horizon");
  RC_CLASSIFY(st.fragments == 0, "no fragment");
  RC_CLASSIFY(std::any_of(r->fragments.begin(), r->fragments.end(),
                          [](const rastrules::Fragment& f) { return f.helper; }),
              "helper lanes");
  RC_CLASSIFY((s.msaa.sample_mask & rastrules::full_mask(s.msaa.count())) !=
                  rastrules::full_mask(s.msaa.count()),
              "partial sample mask");
  RC_CLASSIFY(std::any_of(s.primitives.begin(), s.primitives.end(),
                          [](const rastrules::Primitive& p) {
                            return p.type == PrimitiveType::kLineStrip;
                          }),
              "line strips");
  RC_CLASSIFY(s.msaa.shading == rastrules::ShadingRate::kSample &&
                  std::any_of(s.attributes.begin(), s.attributes.end(),
                              [](const kp::AttributeDecl& a) {
                                return a.location == kp::Location::kCentroid;
                              }),
              "centroid under sample shading");
  if (st.fragments == 0 && std::getenv("PIPE_DEBUG"))
    std::cerr << ps::show(s) << "\n";
}

std::string first_difference(const kp::PipeResult& a, const kp::PipeResult& b) {
  if (a.fragments.size() != b.fragments.size())
    return std::to_string(a.fragments.size()) + " vs " + std::to_string(b.fragments.size()) +
           " fragments";
  for (std::size_t i = 0; i < a.fragments.size(); ++i) {
    if (!(a.fragments[i] == b.fragments[i]))
      return "fragment " + std::to_string(i) + " differs";
  }
  if (a.data.size() != b.data.size())
    return "data sizes differ";
  for (std::size_t i = 0; i < a.data.size(); ++i) {
    if (!(a.data[i] == b.data[i])) {
      std::string s = "data of fragment " + std::to_string(i) + " (x " +
                      std::to_string(a.fragments[i].x) + ", y " + std::to_string(a.fragments[i].y) +
                      ") differs: passed " + std::to_string(a.data[i].passed) + " vs " +
                      std::to_string(b.data[i].passed) + ", attr " + pg::fs(a.data[i].attr) +
                      " vs " + pg::fs(b.data[i].attr);
      return s;
    }
  }
  if (a.depth_buffer != b.depth_buffer)
    return "depth buffers differ";
  return "";
}

rc::Gen<kp::PipeOptions> options() {
  return rc::gen::exec([] {
    kp::PipeOptions o;
    o.render.traversal =
        *rc::gen::element(rastrules::Traversal::kPlain, rastrules::Traversal::kFast);
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
  return std::string("traversal ") +
         (o.render.traversal == rastrules::Traversal::kPlain ? "plain" : "fast") + ", threads " +
         std::to_string(o.render.threads) + ", tile " + std::to_string(o.tile_size) +
         (o.binning ? ", binning" : "") + (o.hiz ? ", hiz" : "") + (o.early_z ? ", early-z" : "") +
         (o.fast_clear ? ", fast clear" : "");
}

// rule: PIPE.OPT.TILES, PIPE.OPT.HIZ, PIPE.OPT.EARLY_Z, PIPE.OPT.FAST_CLEAR, PIPE.OPT.THREADS
// rule: FAST.EQUALS.PLAIN, FAST.THREADS.DETERMINISTIC
RC_GTEST_PROP(Scene, OptimizationsTraversalsAndThreadsChangeNothing, ()) {
  // Larger targets than above, so that scenes span several 16 and 32 px tiles.
  const rastrules::Scene s = *pg::full_size(pipe_scene(70, 6));
  const auto plain = run(s, kp::PipeOptions::plain());
  if (!plain)
    return;
  const auto again = run(s, kp::PipeOptions::plain());
  const std::string d0 = first_difference(*plain, *again);
  if (!d0.empty())
    RC_FAIL("two plain runs differ: " + d0 + "\n" + ps::show(s));
  const kp::PipeOptions defaults;
  const auto fast = run(s, defaults);
  const std::string d1 = first_difference(*plain, *fast);
  if (!d1.empty())
    RC_FAIL("default options (" + describe(defaults) + ") differ from plain: " + d1 + "\n" +
            ps::show(s));
  const kp::PipeOptions o = *options();
  const auto other = run(s, o);
  const std::string d2 = first_difference(*plain, *other);
  if (!d2.empty())
    RC_FAIL("options (" + describe(o) + ") differ from plain: " + d2 + "\n" + ps::show(s));
  RC_CLASSIFY(fast->stats.hiz_rejected > 0, "Hi-Z rejected something");
  RC_CLASSIFY(s.width > 32 || s.height > 32, "several 32 px tiles");
}

// rule: LINE.STRIP.SEQUENCE, PIPE.BARY.LINE, PIPE.INTERP.FLAT, PIPE.CLIP.LINE
// Each segment of a strip gives, fragment for fragment, what the same segment drawn as a line
// gives: coverage, barycentrics, attributes (flat ones from the segment's provoking vertex),
// depths and the depth test, clipped or not, in every line mode, with either provoking vertex.
RC_GTEST_PROP(PipeStrip, EachSegmentEqualsTheSameSegmentDrawnAsALine, ()) {
  rastrules::Scene s = *pg::full_size(pipe_scene(16, 1));
  s.primitives = {*primitive(s, PrimitiveType::kLineStrip)};
  const rastrules::Scene lines = pg::strips_as_lines(s);
  const auto a = run(s, kp::PipeOptions::plain());
  const auto b = run(lines, kp::PipeOptions::plain());
  if (!a || !b) {
    RC_TAG("rejected: transform overflow");
    return;
  }
  // Both sorted by (segment, y, x, sample): a strip's segment is its seg, or its part when
  // clipped; a line's is its primitive index.
  const auto order = [](const kp::PipeResult& r, bool strip) {
    std::vector<std::tuple<std::uint32_t, std::int32_t, std::int32_t, std::int64_t, std::size_t>> v;
    for (std::size_t i = 0; i < r.fragments.size(); ++i) {
      const rastrules::Fragment& f = r.fragments[i];
      const std::uint32_t segment =
          strip ? (f.seg ? *f.seg : (r.data.empty() ? 0 : r.data[i].part.value_or(0))) : f.prim;
      v.emplace_back(segment, f.y, f.x, f.sample ? std::int64_t{*f.sample} : -1, i);
    }
    std::sort(v.begin(), v.end());
    return v;
  };
  const auto oa = order(*a, true), ob = order(*b, false);
  if (oa.size() != ob.size())
    RC_FAIL("strip " + std::to_string(oa.size()) + " fragments, lines " +
            std::to_string(ob.size()) + "\n" + ps::show(s));
  const bool clipped =
      std::any_of(a->data.begin(), a->data.end(), [](const kp::FragmentData& d) { return d.part; });
  for (std::size_t j = 0; j < oa.size(); ++j) {
    const std::size_t ia = std::get<4>(oa[j]), ib = std::get<4>(ob[j]);
    rastrules::Fragment fa = a->fragments[ia], fb = b->fragments[ib];
    const std::string at = "segment " + std::to_string(std::get<0>(oa[j])) + " at (" +
                           std::to_string(fa.x) + ", " + std::to_string(fa.y) + ")";
    fa.prim = fb.prim = 0;
    fa.seg = fb.seg = std::nullopt;
    if (std::get<0>(oa[j]) != std::get<0>(ob[j]) || !(fa == fb))
      RC_FAIL(at + ": the strip's fragment differs from the line's\n" + ps::show(s));
    if (a->data.empty() != b->data.empty())
      RC_FAIL("one run has fragment data, the other not\n" + ps::show(s));
    if (a->data.empty())
      continue;
    kp::FragmentData da = a->data[ia], db = b->data[ib];
    da.drawn = db.drawn = 0;
    da.part = db.part = std::nullopt;
    if (!(da == db))
      RC_FAIL(at + ": values differ: strip attr " + pg::fs(da.attr) + ", line attr " +
              pg::fs(db.attr) +
              (da.bary && db.bary
                   ? ", strip bary e1 " + std::to_string(da.bary->e[1]) + "/" +
                         std::to_string(da.bary->area) + ", line " + std::to_string(db.bary->e[1]) +
                         "/" + std::to_string(db.bary->area)
                   : std::string()) +
              "\n" + ps::show(s));
  }
  if (a->depth_buffer != b->depth_buffer)
    RC_FAIL("depth buffers differ\n" + ps::show(s));
  RC_CLASSIFY(clipped, "clipped");
  RC_CLASSIFY(s.primitives[0].pos.empty(), "window space");
  RC_CLASSIFY(!s.attributes.empty(), "attributes");
  RC_CLASSIFY(s.depth.has_value(), "depth");
  RC_CLASSIFY(oa.empty(), "no fragment");
  RC_TAG(std::string(to_string(s.conventions.line_mode)));
}

} // namespace

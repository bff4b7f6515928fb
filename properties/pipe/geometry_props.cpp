// SPDX-License-Identifier: MIT
// Properties: the kernel's float stages are bit-identical to the oracle's evaluation of the
// spec's formulas (each operation an exact rational rounded once): the transform, the divide
// and viewport transform, the implicit scissor, the clip volume, the inside test and the
// Sutherland-Hodgman clipper (positions and attributes) and the segment clipper; every clipped
// vertex lands within the guard band + 1023 px (PIPE.CLIP.GUARD_BAND_SNAP's margin);
// viewports are accepted exactly within the spec's limits; and the guard band bound: a triangle
// clipped at the guard band covers every pixel centre farther than 1/64 px from the edges of
// the exactly projected and snapped unclipped triangle exactly when that triangle does, each at
// most once across its fan.
// Implements (properties for): PIPE.TRANSFORM.FLOAT32, PIPE.VIEWPORT.TRANSFORM,
//   PIPE.VIEWPORT.SCISSOR, PIPE.CLIP.VOLUME, PIPE.CLIP.POLYGON, PIPE.CLIP.COMPUTE,
//   PIPE.CLIP.UNCLIPPED, PIPE.CLIP.GUARD_BAND_BOUND, PIPE.CLIP.GUARD_BAND_SNAP, PIPE.CLIP.LINE,
//   PIPE.VIEWPORT.RANGE

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "pipe_gen.hpp"

namespace {

namespace pg = rastrules::pipe_gen;
namespace op = rastrules::oracle::pipe;
namespace kp = rastrules::pipe;

std::string vps(const kp::Viewport& v) {
  return "viewport {" + pg::fs(v.x) + ", " + pg::fs(v.y) + ", " + pg::fs(v.width) + ", " +
         pg::fs(v.height) + ", " + pg::fs(v.min_depth) + ", " + pg::fs(v.max_depth) + "}";
}

// rule: PIPE.TRANSFORM.FLOAT32
RC_GTEST_PROP(PipeGeometry, TransformIsBitIdenticalToTheSpecFormula, ()) {
  const kp::Mat4f m = *pg::matrix();
  const kp::Vec4f v = *pg::clip_vertex();
  RC_PRE(pg::position_ok(v));
  const kp::Vec4f got = kp::transform(m, v);
  const op::Vec4 want = op::transform(m, v);
  for (std::size_t r = 0; r < 4; ++r) {
    if (!pg::same_bits(got[r], want[r])) {
      RC_FAIL("matrix " + pg::fs(m) + ", v " + pg::fs(v) + ": row " + std::to_string(r) +
              " kernel " + pg::fs(got[r]) + ", oracle " + pg::fs(want[r]));
    }
  }
}

// rule: PIPE.VIEWPORT.TRANSFORM
RC_GTEST_PROP(PipeGeometry, ToWindowIsBitIdenticalToTheSpecFormula, ()) {
  const std::int32_t w = *rc::gen::inRange(1, 64), h = *rc::gen::inRange(1, 64);
  const kp::Viewport vp = *pg::viewport(w, h);
  kp::Vec4f p = *pg::clip_vertex();
  RC_PRE(pg::position_ok(p));
  p[3] = std::fabs(p[3]);
  RC_PRE(p[3] > 0.0f);
  const kp::WindowVertex got = kp::to_window(p, vp);
  const op::WindowVertex want = op::to_window(p, pg::to_oracle(vp));
  const std::array<float, 4> g{got.x, got.y, got.z, got.w}, o{want.x, want.y, want.z, want.w};
  for (std::size_t i = 0; i < 4; ++i) {
    if (!pg::same_bits(g[i], o[i])) {
      RC_FAIL("p " + pg::fs(p) + ", " + vps(vp) + ": kernel " + pg::fs(g) + ", oracle " +
              pg::fs(o));
    }
  }
}

// rule: PIPE.VIEWPORT.SCISSOR
RC_GTEST_PROP(PipeGeometry, ScissorIsTheSpecRectangle, ()) {
  const std::int32_t w = *rc::gen::inRange(1, 64), h = *rc::gen::inRange(1, 64);
  const kp::Viewport vp = *pg::viewport(w, h);
  const kp::ScissorRect got = kp::viewport_scissor(vp);
  const op::Rect want = op::viewport_scissor(pg::to_oracle(vp));
  RC_ASSERT(got.x0 == want.x0);
  RC_ASSERT(got.y0 == want.y0);
  RC_ASSERT(got.x1 == want.x1);
  RC_ASSERT(got.y1 == want.y1);
}

// A triangle of clip-space vertices (each within the position limit) with n attributes.
std::vector<kp::ClipVertex> clip_triangle(std::size_t nattr) {
  std::vector<kp::ClipVertex> t(3);
  for (kp::ClipVertex& v : t) {
    v.pos = *pg::clip_vertex();
    RC_PRE(pg::position_ok(v.pos));
    for (std::size_t k = 0; k < nattr; ++k)
      v.attr.push_back(*pg::attr_value());
  }
  // Sometimes two vertices share coordinates (an edge on a plane, a repeated vertex).
  if (*rc::gen::inRange(0, 6) == 0) {
    const auto c = static_cast<std::size_t>(*rc::gen::inRange(0, 4));
    t[1].pos[c] = t[0].pos[c];
  }
  return t;
}

std::string show(const std::vector<kp::ClipVertex>& vs) {
  std::string s;
  for (const auto& v : vs)
    s += "  pos " + pg::fs(v.pos) + " attr " + pg::fs(v.attr) + "\n";
  return s;
}
std::string show(const std::vector<op::ClipVertex>& vs) {
  std::string s;
  for (const auto& v : vs)
    s += "  pos " + pg::fs(v.pos) + " attr " + pg::fs(v.attr) + "\n";
  return s;
}

// rule: PIPE.CLIP.VOLUME, PIPE.CLIP.POLYGON, PIPE.CLIP.COMPUTE, PIPE.CLIP.UNCLIPPED
// rule: PIPE.CLIP.GUARD_BAND_SNAP
RC_GTEST_PROP(PipeGeometry, ClipperIsBitIdenticalToTheSpecAlgorithm, ()) {
  const std::int32_t w = *rc::gen::inRange(1, 64), h = *rc::gen::inRange(1, 64);
  const kp::Viewport vp = *pg::viewport(w, h);
  const bool depth_clip = *rc::gen::inRange(0, 4) != 0;
  const std::vector<kp::ClipVertex> t =
      clip_triangle(static_cast<std::size_t>(*rc::gen::inRange(0, 3)));
  std::vector<kp::Vec4f> pos;
  for (const auto& v : t)
    pos.push_back(v.pos);
  const kp::ClipVolume vol = kp::clip_volume(pos, vp, depth_clip);
  const op::Volume ovol = op::clip_volume(pos, pg::to_oracle(vp), depth_clip);
  const std::string where =
      vps(vp) + (depth_clip ? ", depth clip" : ", no depth clip") + ", triangle\n" + show(t);
  const std::array<double, 5> kv{vol.w_min, vol.gx_lo, vol.gx_hi, vol.gy_lo, vol.gy_hi};
  const std::array<double, 5> ov{ovol.w_min, ovol.gx_lo, ovol.gx_hi, ovol.gy_lo, ovol.gy_hi};
  for (std::size_t i = 0; i < 5; ++i) {
    if (!pg::same_bits(kv[i], ov[i])) {
      RC_FAIL(where + "clip volume field " + std::to_string(i) +
              " (w_min, gx_lo, gx_hi, gy_lo, "
              "gy_hi): kernel " +
              pg::fs(kv[i]) + ", oracle " + pg::fs(ov[i]));
    }
  }
  RC_ASSERT(vol.depth_clip == depth_clip);
  for (const auto& v : t) {
    if (kp::inside(vol, v.pos) != op::inside(ovol, v.pos))
      RC_FAIL(where + "inside() differs for " + pg::fs(v.pos));
  }
  const std::vector<kp::ClipVertex> got = kp::clip_polygon(t, vol);
  const std::vector<op::ClipVertex> want = op::clip_polygon(pg::to_oracle(t), ovol);
  bool same = got.size() == want.size();
  for (std::size_t i = 0; same && i < got.size(); ++i) {
    for (std::size_t c = 0; c < 4; ++c)
      same = same && pg::same_bits(got[i].pos[c], want[i].pos[c]);
    same = same && got[i].attr.size() == want[i].attr.size();
    for (std::size_t a = 0; same && a < got[i].attr.size(); ++a)
      same = same && pg::same_bits(got[i].attr[a], want[i].attr[a]);
  }
  if (!same)
    RC_FAIL(where + "kernel clip_polygon:\n" + show(got) + "oracle:\n" + show(want));
  // PIPE.CLIP.GUARD_BAND_SNAP, PIPE.CLIP.SATURATE: a clipped vertex lies on the guard band up
  // to the clipper's rounding, usually far inside the 1023 px margin that keeps it snappable;
  // under cancellation with w near w_min it can land anywhere (7e9 px has been seen:
  // regression ClippedVertexFarBeyondTheBandUnderATinyW), and the saturation to the snap range
  // keeps it snappable whatever the rounding. That is what is promised, and checked here.
  bool beyond_margin = false;
  for (const kp::ClipVertex& v : got) {
    const kp::WindowVertex wv = kp::to_window(v.pos, vp);
    const double g = kp::kGuardBand + 1023.0;
    beyond_margin = beyond_margin || !(std::fabs(static_cast<double>(wv.x)) <= g &&
                                       std::fabs(static_cast<double>(wv.y)) <= g);
    const float sx = kp::saturate_to_snap_range(wv.x), sy = kp::saturate_to_snap_range(wv.y);
    if (!rastrules::oracle::snap(sx) || !rastrules::oracle::snap(sy))
      RC_FAIL(where + "clipped vertex " + pg::fs(v.pos) + " lands at window (" + pg::fs(wv.x) +
              ", " + pg::fs(wv.y) + "), which does not snap after PIPE.CLIP.SATURATE");
  }
  RC_CLASSIFY(beyond_margin, "a clipped vertex beyond the guard band + 1023 px (saturated)");
  const bool all_inside =
      op::inside(ovol, t[0].pos) && op::inside(ovol, t[1].pos) && op::inside(ovol, t[2].pos);
  if (all_inside)
    RC_ASSERT(got == t); // PIPE.CLIP.UNCLIPPED
  RC_CLASSIFY(all_inside, "unclipped");
  RC_CLASSIFY(got.empty(), "clipped away");
  RC_CLASSIFY(!all_inside && !got.empty(), "clipped");
  RC_CLASSIFY(got.size() > 5, "more than 5 vertices");
}

// rule: PIPE.CLIP.LINE, PIPE.CLIP.COMPUTE
RC_GTEST_PROP(PipeGeometry, SegmentClipperIsBitIdenticalToTheSpecAlgorithm, ()) {
  const std::int32_t w = *rc::gen::inRange(1, 64), h = *rc::gen::inRange(1, 64);
  const kp::Viewport vp = *pg::viewport(w, h);
  const bool depth_clip = *rc::gen::inRange(0, 4) != 0;
  const std::vector<kp::ClipVertex> t =
      clip_triangle(static_cast<std::size_t>(*rc::gen::inRange(0, 3)));
  const kp::ClipVolume vol = kp::clip_volume({t[0].pos, t[1].pos}, vp, depth_clip);
  const op::Volume ovol = op::clip_volume({t[0].pos, t[1].pos}, pg::to_oracle(vp), depth_clip);
  const auto got = kp::clip_segment(t[0], t[1], vol);
  const auto want = op::clip_segment(op::ClipVertex{t[0].pos, t[0].attr},
                                     op::ClipVertex{t[1].pos, t[1].attr}, ovol);
  const std::string where = vps(vp) + (depth_clip ? ", depth clip" : ", no depth clip") +
                            ", segment\n" + show(std::vector<kp::ClipVertex>{t[0], t[1]});
  if (got.has_value() != want.has_value())
    RC_FAIL(where + (got ? "kernel keeps it, the oracle discards it"
                         : "kernel discards it, the oracle keeps it"));
  if (got) {
    bool same = true;
    for (std::size_t i = 0; i < 2; ++i) {
      for (std::size_t c = 0; c < 4; ++c)
        same = same && pg::same_bits((*got)[i].pos[c], (*want)[i].pos[c]);
      same = same && (*got)[i].attr.size() == (*want)[i].attr.size();
      for (std::size_t a = 0; same && a < (*got)[i].attr.size(); ++a)
        same = pg::same_bits((*got)[i].attr[a], (*want)[i].attr[a]);
    }
    if (!same) {
      RC_FAIL(where + "kernel:\n" + show(std::vector<kp::ClipVertex>{(*got)[0], (*got)[1]}) +
              "oracle:\n" + show(std::vector<op::ClipVertex>{(*want)[0], (*want)[1]}));
    }
  }
  RC_CLASSIFY(!got, "discarded");
  RC_CLASSIFY(got && !((*got)[0] == t[0] && (*got)[1] == t[1]), "cut");
}

// Viewports near and beyond every limit: in range, at it, one float step past it, not finite.
rc::Gen<kp::Viewport> any_viewport() {
  return rc::gen::exec([] {
    const auto coord = [] {
      return *rc::gen::weightedOneOf<float>({
          {3, rc::gen::map(rc::gen::inRange(-40000, 40001),
                           [](int k) { return static_cast<float>(k); })},
          {2, rc::gen::element(-32768.0f, 32767.0f, std::nextafter(-32768.0f, -1e9f),
                               std::nextafter(32767.0f, 1e9f), 0.0f, -0.0f, 0.5f, 1e-4f)},
          {1, rc::gen::element(std::numeric_limits<float>::quiet_NaN(),
                               std::numeric_limits<float>::infinity(),
                               -std::numeric_limits<float>::infinity())},
          {1, pg::attr_value()},
      });
    };
    const auto depth = [] {
      return *rc::gen::weightedOneOf<float>({
          {3, pg::depth_value()},
          {1, rc::gen::element(-0.0f, std::nextafter(1.0f, 2.0f), std::nextafter(0.0f, -1.0f), 2.0f,
                               std::numeric_limits<float>::quiet_NaN())},
      });
    };
    kp::Viewport v;
    v.x = coord();
    v.y = coord();
    v.width = std::fabs(coord()) * (*rc::gen::inRange(0, 8) == 0 ? -1.0f : 1.0f);
    v.height = std::fabs(coord()) * (*rc::gen::inRange(0, 8) == 0 ? -1.0f : 1.0f);
    v.min_depth = depth();
    v.max_depth = depth();
    return v;
  });
}

// rule: PIPE.VIEWPORT.RANGE
RC_GTEST_PROP(PipeGeometry, ViewportLimitsAreTheSpecRanges, ()) {
  const kp::Viewport vp = *any_viewport();
  const auto got = kp::check_viewport(vp);
  const std::vector<std::string> want = op::viewport_violations(pg::to_oracle(vp));
  if (got.has_value() == want.empty()) {
    std::string fields;
    for (const auto& f : want)
      fields += " " + f;
    RC_FAIL(vps(vp) + ": kernel " +
            (got ? "rejects it (" + got->first + ": " + got->second + ")" : "accepts it") +
            ", oracle violations:" + (fields.empty() ? " none" : fields));
  }
  if (got && std::find(want.begin(), want.end(), got->first) == want.end())
    RC_FAIL(vps(vp) + ": kernel names " + got->first + ", which is within its limits");
  RC_CLASSIFY(!got, "valid");
}

// A clip-space vertex with 0 <= z <= w and w > 0 (no w or depth clipping) whose x/w or y/w may
// lie far outside the guard band.
rc::Gen<kp::Vec4f> guard_band_vertex() {
  return rc::gen::exec([] {
    const float w = *rc::gen::element(1.0f, 0.5f, 2.0f, 3.0f, 0.125f);
    const auto ndc = [] {
      if (*rc::gen::inRange(0, 2) == 0)
        return static_cast<float>(*rc::gen::inRange(-512, 513)) / 256.0f;
      const float m = static_cast<float>(*rc::gen::inRange(1 << 10, 1 << 14)) / 1024.0f;
      // Mostly just beyond the band; sometimes far: m < 16 = 2^4 and e <= 58 keep |ndc| below
      // 2^62 and |ndc * w| (w <= 3) below the position limit 2^64 (PIPE.INPUT.POSITION; e up
      // to 60 once generated 1.8447307e19 > 2^64, which the kernel rightly rejected).
      const int e =
          *rc::gen::inRange(0, 5) == 0 ? *rc::gen::inRange(23, 59) : *rc::gen::inRange(11, 23);
      return std::ldexp(m, e) * (*rc::gen::arbitrary<bool>() ? 1.0f : -1.0f);
    };
    const float z = static_cast<float>(*rc::gen::inRange(0, 257)) / 256.0f * w;
    return kp::Vec4f{ndc() * w, ndc() * w, z, w};
  });
}

// rule: PIPE.CLIP.GUARD_BAND_BOUND, PIPE.CLIP.POLYGON, PIPE.CLIP.UNCLIPPED
RC_GTEST_PROP(PipeGeometry, GuardBandClippingKeepsCoverageAwayFromEdges, ()) {
  const std::int32_t w = *rc::gen::inRange(1, 17), h = *rc::gen::inRange(1, 17);
  const kp::Viewport vp = *pg::viewport(w, h);
  const std::array<kp::Vec4f, 3> tri{*guard_band_vertex(), *guard_band_vertex(),
                                     *guard_band_vertex()};
  rastrules::Scene s;
  s.width = w;
  s.height = h;
  s.viewport = vp;
  rastrules::Primitive p;
  p.pos = {tri[0], tri[1], tri[2]};
  s.primitives.push_back(p);
  const auto res = kp::run_pipeline(s);
  std::string where = vps(vp) + ", target " + std::to_string(w) + "x" + std::to_string(h) +
                      ", clip-space triangle " + pg::fs(tri[0]) + " " + pg::fs(tri[1]) + " " +
                      pg::fs(tri[2]);
  if (const auto* e = std::get_if<rastrules::SceneError>(&res))
    RC_FAIL(where + ": " + e->what());
  const kp::PipeResult& r = std::get<kp::PipeResult>(res);
  std::map<std::pair<std::int32_t, std::int32_t>, int> count;
  bool clipped = false;
  RC_ASSERT(r.data.size() == r.fragments.size()); // clip-space input: data for every fragment
  for (std::size_t i = 0; i < r.fragments.size(); ++i) {
    ++count[{r.fragments[i].x, r.fragments[i].y}];
    clipped = clipped || r.data[i].part.has_value();
  }
  const op::ExactRegion exact = op::ExactRegion::unclipped_triangle(tri, pg::to_oracle(vp));
  const op::Rect sc = op::viewport_scissor(pg::to_oracle(vp));
  int near = 0;
  for (std::int32_t y = 0; y < h; ++y) {
    for (std::int32_t x = 0; x < w; ++x) {
      const int n = count.count({x, y}) ? count.at({x, y}) : 0;
      if (n > 1)
        RC_FAIL(where + ": pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") covered " +
                std::to_string(n) + " times by the fan");
      const bool in_scissor = x >= sc.x0 && x < sc.x1 && y >= sc.y0 && y < sc.y1;
      if (!in_scissor) {
        RC_ASSERT(n == 0);
        continue;
      }
      const auto side =
          exact.classify({256 * std::int64_t{x} + 128, 256 * std::int64_t{y} + 128}, 4);
      if (side == op::ExactRegion::Side::kNear) {
        ++near;
        continue;
      }
      const bool want = side == op::ExactRegion::Side::kInside;
      if (want != (n == 1)) {
        std::string verts;
        for (const auto& v : exact.vertices_px())
          verts += " (" + pg::fs(v[0]) + ", " + pg::fs(v[1]) + ")";
        RC_FAIL(where + ": pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") " +
                (want ? "inside" : "outside") + " the exact unclipped triangle" + verts +
                " (farther than 1/64 px from its edges) but covered " + std::to_string(n) +
                " times");
      }
    }
  }
  RC_CLASSIFY(clipped, "clipped at the guard band");
  RC_CLASSIFY(!r.fragments.empty(), "covers pixels");
  RC_CLASSIFY(near > 0, "pixel centres within 1/64 px of an edge");
}

} // namespace

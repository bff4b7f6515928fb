// SPDX-License-Identifier: MIT
// Stage 2 of run_pipeline: each primitive's vertices through the transform, the clip volume,
// the divide and the viewport, into the internal window-space scene whose primitives the rest
// of the kernel rasterizes; each remembers its source (primitive, part, window vertices with
// depth and w, attributes, per-segment flat values).
// Implements: PIPE.INPUT.POSITION, PIPE.INPUT.ATTRIBUTES, PIPE.TRANSFORM.FLOAT32,
//   PIPE.CLIP.UNCLIPPED, PIPE.CLIP.POLYGON, PIPE.CLIP.LINE, PIPE.CLIP.SATURATE,
//   PIPE.INTERP.FLAT
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "stages.hpp"

namespace rastrules::pipe::detail {

namespace {

// Validates the finite, bounded position p (PIPE.INPUT.POSITION).
std::optional<SceneError> check_position(const Vec4f& p, const std::string& field,
                                         const char* when) {
  for (std::size_t c = 0; c < 4; ++c) {
    const float v = p[c];
    if (std::isnan(v))
      return err(field, std::string("is NaN") + when + " (PIPE.INPUT.POSITION)");
    if (std::isinf(v))
      return err(field, std::string("is infinite") + when + " (PIPE.INPUT.POSITION)");
    if (std::fabs(static_cast<double>(v)) > kMaxPosition)
      return err(field,
                 std::string("has a coordinate beyond 2^64") + when + " (PIPE.INPUT.POSITION)");
  }
  return std::nullopt;
}

} // namespace

// Replaces the primitive index of a field "primitives[N]..." of the internal scene with the
// index of its source primitive.
SceneError remap(SceneError e, const std::vector<Source>& sources) {
  const std::string head = "primitives[";
  if (e.field.rfind(head, 0) != 0)
    return e;
  const std::size_t close = e.field.find(']');
  if (close == std::string::npos)
    return e;
  const std::size_t n = std::stoul(e.field.substr(head.size(), close - head.size()));
  if (n < sources.size())
    e.field = head + std::to_string(sources[n].prim) + e.field.substr(close);
  return e;
}

std::size_t segments_of(PrimitiveType t, std::size_t nv) {
  return t == PrimitiveType::kLineStrip && nv >= 2 ? nv - 1 : 1;
}

namespace {

// Builds the internal window-space scene one source primitive at a time.
class Assembler {
public:
  Assembler(const Scene& s, const Viewport& vp) : s_(s), vp_(vp), nattr_(s.attributes.size()) {
    out_.ws = target_of(s);
    out_.ws.primitives.reserve(s.primitives.size());
    out_.sources.reserve(s.primitives.size());
    // An attribute at the centroid makes every fragment carry its centroid
    // (PIPE.INTERP.LOCATION).
    if (std::any_of(s.attributes.begin(), s.attributes.end(),
                    [](const AttributeDecl& a) { return a.location == Location::kCentroid; }))
      out_.ws.msaa.has_centroid = true;
  }

  // Adds primitive i (window or clip space), or returns its first error.
  std::optional<SceneError> add_primitive(std::size_t i) {
    i_ = i;
    const Primitive& pp = s_.primitives[i];
    return pp.pos.empty() ? add_window_space(pp) : add_clip_space(pp);
  }

  Assembled take() { return std::move(out_); }

private:
  [[nodiscard]] std::string field() const { return idx("primitives", i_); }
  [[nodiscard]] static std::size_t vertex_count(const Primitive& pp) {
    return pp.pos.empty() ? pp.v.size() : pp.pos.size();
  }
  [[nodiscard]] std::vector<float> vertex_attr(const Primitive& pp, std::size_t j) const {
    return nattr_ == 0 ? std::vector<float>{} : pp.attr[j];
  }

  // rule: PIPE.INTERP.FLAT
  // The provoking vertex of each segment: a strip's segment k runs from vertex k to k + 1 and
  // is an independent line (LINE.STRIP.SEQUENCE); any other primitive is one segment.
  [[nodiscard]] std::vector<float> flat_of(const Primitive& pp, std::size_t segment) const {
    if (nattr_ == 0)
      return {};
    const bool strip = pp.type == PrimitiveType::kLineStrip;
    const std::size_t first = strip ? segment : 0,
                      last = strip ? segment + 1 : vertex_count(pp) - 1;
    return pp.attr[s_.conventions.provoking == Provoking::kFirst ? first : last];
  }

  // Adds a coverage primitive; segment: the strip segment a clipped line was cut from.
  void add(const Primitive& pp, const Primitive& prim, std::optional<std::uint32_t> part,
           std::vector<WindowVertex> v, std::vector<std::vector<float>> attr,
           std::size_t segment = 0) {
    std::vector<std::vector<float>> flat;
    const std::size_t n = segments_of(prim.type, v.size());
    for (std::size_t k = 0; k < n; ++k)
      flat.push_back(flat_of(pp, segment + k));
    out_.ws.primitives.push_back(prim);
    out_.sources.push_back(Source{i_, part, std::move(v), std::move(attr), std::move(flat)});
  }

  // Adds a drawn primitive of type t from clip-space vertices: divide and viewport.
  void add_window(const Primitive& pp, PrimitiveType t, std::optional<std::uint32_t> part,
                  const std::vector<ClipVertex>& vs, std::size_t segment = 0) {
    Primitive p = coverage_of(pp);
    p.type = t;
    p.v.clear();
    std::vector<WindowVertex> w;
    std::vector<std::vector<float>> attr;
    for (const ClipVertex& c : vs) {
      w.push_back(to_window(c.pos, vp_));
      // rule: PIPE.CLIP.SATURATE
      // Rounding in the clipper can carry a created vertex a little beyond the guard band;
      // D3D's saturating conversion keeps it snappable (a no-op for every other vertex).
      w.back().x = saturate_to_snap_range(w.back().x);
      w.back().y = saturate_to_snap_range(w.back().y);
      p.v.push_back(FloatPoint{w.back().x, w.back().y});
      attr.push_back(c.attr);
    }
    add(pp, p, part, std::move(w), std::move(attr), segment);
  }

  // Window space: v as given, z and w optional.
  std::optional<SceneError> add_window_space(const Primitive& pp) {
    const std::string pf = field();
    const std::size_t nv = vertex_count(pp);
    std::vector<WindowVertex> v(nv);
    for (std::size_t j = 0; j < nv; ++j) {
      v[j].x = pp.v[j][0];
      v[j].y = pp.v[j][1];
      if (!pp.z.empty()) {
        if (!std::isfinite(pp.z[j]))
          return err(pf + ".z[" + std::to_string(j) + "]", "is not finite (PIPE.DEPTH.INTERP)");
        v[j].z = pp.z[j];
      }
      if (!pp.w.empty()) {
        if (!(std::isfinite(pp.w[j]) && pp.w[j] > 0.0f))
          return err(pf + ".w[" + std::to_string(j) + "]",
                     "must be finite and greater than 0 (PIPE.INTERP.PERSPECTIVE)");
        v[j].w = pp.w[j];
      }
    }
    std::vector<std::vector<float>> attr;
    for (std::size_t j = 0; j < nv; ++j)
      attr.push_back(vertex_attr(pp, j));
    add(pp, coverage_of(pp), std::nullopt, std::move(v), std::move(attr));
    return std::nullopt;
  }

  // Clip space: the transform, then the clip volume (PIPE.CLIP.*).
  std::optional<SceneError> add_clip_space(const Primitive& pp) {
    const std::string pf = field();
    const std::size_t nv = vertex_count(pp);
    const bool has_transform = s_.model || s_.view || s_.projection;
    std::vector<ClipVertex> cv(nv);
    for (std::size_t j = 0; j < nv; ++j) {
      const std::string vf = pf + ".pos[" + std::to_string(j) + "]";
      if (auto bad = check_position(pp.pos[j], vf, ""))
        return bad;
      Vec4f p = pp.pos[j];
      if (has_transform) {
        if (s_.model)
          p = transform(*s_.model, p);
        if (s_.view)
          p = transform(*s_.view, p);
        if (s_.projection)
          p = transform(*s_.projection, p);
        if (auto bad = check_position(p, vf, " after the transform"))
          return bad;
      }
      cv[j].pos = p;
      cv[j].attr = vertex_attr(pp, j);
    }
    std::vector<Vec4f> clip_pos;
    for (const ClipVertex& c : cv)
      clip_pos.push_back(c.pos);
    const bool depth_clip = !s_.depth || s_.depth->clip;
    const ClipVolume vol = clip_volume(clip_pos, vp_, depth_clip);
    switch (pp.type) {
    case PrimitiveType::kTriangle: {
      // rule: PIPE.CLIP.POLYGON, PIPE.CLIP.UNCLIPPED
      const std::vector<ClipVertex> poly = clip_polygon(cv, vol);
      const bool clipped = poly != cv;
      for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
        add_window(pp, PrimitiveType::kTriangle,
                   clipped ? std::optional<std::uint32_t>(static_cast<std::uint32_t>(k - 1))
                           : std::nullopt,
                   {poly[0], poly[k], poly[k + 1]});
      }
      break;
    }
    case PrimitiveType::kPoint: {
      // rule: PIPE.CLIP.LINE
      if (inside(vol, cv[0].pos))
        add_window(pp, PrimitiveType::kPoint, std::nullopt, cv);
      break;
    }
    case PrimitiveType::kLine:
    case PrimitiveType::kLineStrip: {
      // rule: PIPE.CLIP.LINE
      const bool all_in = std::all_of(cv.begin(), cv.end(),
                                      [&](const ClipVertex& c) { return inside(vol, c.pos); });
      if (all_in) {
        add_window(pp, pp.type, std::nullopt, cv);
        break;
      }
      for (std::size_t k = 0; k + 1 < cv.size(); ++k) {
        const auto seg = clip_segment(cv[k], cv[k + 1], vol);
        if (seg)
          add_window(pp, PrimitiveType::kLine, static_cast<std::uint32_t>(k),
                     {(*seg)[0], (*seg)[1]}, k);
      }
      break;
    }
    case PrimitiveType::kPath:
      break; // never here: pipe::validate refuses paths in pipeline scenes (SCENE.PRIM.PATH)
    }
    return std::nullopt;
  }

  const Scene& s_;
  const Viewport& vp_;
  const std::size_t nattr_;
  std::size_t i_ = 0;
  Assembled out_;
};

} // namespace

std::variant<Assembled, SceneError> assemble(const Scene& s, const Viewport& vp) {
  Assembler a(s, vp);
  for (std::size_t i = 0; i < s.primitives.size(); ++i)
    if (auto bad = a.add_primitive(i))
      return *bad;
  return a.take();
}

} // namespace rastrules::pipe::detail

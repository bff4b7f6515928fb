// SPDX-License-Identifier: MIT
// run_pipeline(): a pipeline scene through validation, transform, clipping, divide and viewport,
// the coverage rules of the rest of the kernel, barycentrics, interpolation and depth
// (spec/rules/pipe.md). Only the stages the scene needs run (PIPE.EFFECTS.ON_DEMAND).
#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "rastrules/msaa.hpp"
#include "rastrules/parallel.hpp"
#include "rastrules/pipeline.hpp"

namespace rastrules::pipe {

namespace {

std::string idx(const char* name, std::size_t i) {
  return std::string(name) + "[" + std::to_string(i) + "]";
}

SceneError err(std::string field, std::string message) {
  return SceneError{std::move(field), std::move(message)};
}

// What a drawn (window-space) primitive came from.
struct Source {
  std::size_t prim = 0;
  std::optional<std::uint32_t> part;
  std::vector<WindowVertex> v;          // window x, y (unsnapped), depth z, clip w
  std::vector<std::vector<float>> attr; // per vertex
  // Per segment (one entry for a triangle, point or line; one per segment of a strip): per
  // attribute, the provoking vertex's value (PIPE.INTERP.FLAT).
  std::vector<std::vector<float>> flat;
};

// The number of drawn primitives (PipeResult::drawn) a coverage primitive of type t with nv
// vertices stands for: one per segment of a strip (LINE.STRIP.SEQUENCE), else one.
std::size_t segments_of(PrimitiveType t, std::size_t nv) {
  return t == PrimitiveType::kLineStrip && nv >= 2 ? nv - 1 : 1;
}

struct Stop {
  SceneError error;
};

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

// rule: PIPE.BARY.LINE
// Returns the barycentrics of evaluation point s for a drawn primitive with snapped vertices v:
// the triangle's (PIPE.BARY.EXACT); for a line the exact projection parameter t = num / den
// as (den - num, num, 0) / den; for a point (1, 0, 0) / 1.
Barycentrics eval_bary(PrimitiveType type, const std::vector<Vec2>& v, Vec2 s) {
  if (type == PrimitiveType::kTriangle)
    return barycentrics({v[0], v[1], v[2]}, s);
  Barycentrics b;
  if (type == PrimitiveType::kPoint || v.size() < 2) {
    b.e = {1, 0, 0};
    b.area = 1;
    return b;
  }
  const std::int64_t dx = v[1].x.raw() - v[0].x.raw(), dy = v[1].y.raw() - v[0].y.raw();
  const std::int64_t px = s.x.raw() - v[0].x.raw(), py = s.y.raw() - v[0].y.raw();
  const std::int64_t den = dx * dx + dy * dy; // < 2^49
  const std::int64_t num = px * dx + py * dy; // |.| < 2^49
  b.e = {den - num, num, 0};
  b.area = den;
  return b;
}

} // namespace

// rule: PIPE.EFFECTS.ON_DEMAND
Effects effects_of(const PipeScene& s) {
  Effects e;
  e.clip_space = std::any_of(s.primitives.begin(), s.primitives.end(),
                             [](const PipePrimitive& p) { return !p.pos.empty(); });
  e.depth = s.depth.has_value();
  e.attributes = !s.attributes.empty();
  e.barycentrics = e.depth || e.attributes;
  return e;
}

std::variant<PipeResult, SceneError> run_pipeline(const PipeScene& s, const PipeOptions& o) {
  PipeResult result;
  result.effects = effects_of(s);
  const Effects& fx = result.effects;

  // ---- validation of the pipeline state (the base scene is checked by prepare())
  Viewport vp{0.0f, 0.0f, static_cast<float>(s.base.width), static_cast<float>(s.base.height),
              0.0f, 1.0f};
  if (s.viewport) {
    vp = *s.viewport;
    if (auto bad = check_viewport(vp))
      return err("viewport." + bad->first, bad->second);
  }
  const std::pair<const char*, const std::optional<Mat4f>*> mats[] = {
      {"model", &s.model}, {"view", &s.view}, {"projection", &s.projection}};
  for (const auto& [name, m] : mats) {
    if (!m->has_value())
      continue;
    for (std::size_t k = 0; k < 16; ++k)
      if (!std::isfinite((**m)[k]))
        return err("transform." + idx(name, k), "is not finite (PIPE.TRANSFORM.FLOAT32)");
  }
  if (o.tile_size != 16 && o.tile_size != 32)
    return err("options.tile_size", "must be 16 or 32 (PIPE.OPT.TILES)");
  if (s.attributes.size() > kMaxAttributes)
    return err("attributes", "has more than 16 entries (limit PIPE.INPUT.ATTRIBUTES)");
  bool any_centroid = false;
  for (std::size_t a = 0; a < s.attributes.size(); ++a) {
    const AttributeDecl& d = s.attributes[a];
    if (d.location == Location::kSample && s.base.msaa.shading != ShadingRate::kSample)
      return err(idx("attributes", a) + ".location",
                 "\"sample\" needs sample-frequency shading (PIPE.INTERP.LOCATION)");
    any_centroid = any_centroid || d.location == Location::kCentroid;
  }
  if (s.depth) {
    const DepthState& d = *s.depth;
    if (!(d.clear >= 0.0f && d.clear <= 1.0f))
      return err("depth.clear", "must lie in [0, 1] (PIPE.DEPTH.FORMAT)");
    if (!std::isfinite(d.bias.slope_scaled))
      return err("depth.slope_scaled_bias", "is not finite (PIPE.DEPTH.BIAS)");
    if (!std::isfinite(d.bias.clamp))
      return err("depth.bias_clamp", "is not finite (PIPE.DEPTH.BIAS)");
  }
  const std::uint32_t nsamples = s.base.msaa.count();
  if (s.depth) {
    const std::uint64_t total = static_cast<std::uint64_t>(std::max(s.base.width, 0)) *
                                static_cast<std::uint64_t>(std::max(s.base.height, 0)) * nsamples;
    if (total > static_cast<std::uint64_t>(kMaxResolveSamples))
      return err("depth", "the depth buffer (width * height * samples) exceeds 2^26 samples "
                          "(limit SCENE.INPUT.LIMITS)");
  }

  // ---- vertices: transform, clip, divide and viewport; the internal window-space scene
  Scene ws = s.base;
  ws.primitives.clear();
  ws.primitives.reserve(s.primitives.size());
  if (any_centroid)
    ws.msaa.has_centroid = true;
  std::vector<Source> sources;
  sources.reserve(s.primitives.size());
  const std::size_t nattr = s.attributes.size();
  const bool has_transform = s.model || s.view || s.projection;

  for (std::size_t i = 0; i < s.primitives.size(); ++i) {
    const PipePrimitive& pp = s.primitives[i];
    const std::string pf = idx("primitives", i);
    const std::size_t nv = pp.pos.empty() ? pp.base.v.size() : pp.pos.size();
    // rule: PIPE.INPUT.ATTRIBUTES
    if (nattr > 0 && pp.attr.size() != nv)
      return err(pf + ".attr",
                 "needs one entry per vertex (" + std::to_string(nv) + ") (PIPE.INPUT.ATTRIBUTES)");
    if (nattr == 0 && !pp.attr.empty())
      return err(pf + ".attr",
                 "is given but the scene declares no attributes (PIPE.INPUT.ATTRIBUTES)");
    for (std::size_t j = 0; j < pp.attr.size(); ++j) {
      if (pp.attr[j].size() != nattr)
        return err(pf + ".attr" + "[" + std::to_string(j) + "]",
                   "needs one value per declared attribute (" + std::to_string(nattr) +
                       ") (PIPE.INPUT.ATTRIBUTES)");
      for (std::size_t k = 0; k < nattr; ++k)
        if (!std::isfinite(pp.attr[j][k]))
          return err(pf + ".attr[" + std::to_string(j) + "][" + std::to_string(k) + "]",
                     std::string(std::isnan(pp.attr[j][k]) ? "is NaN" : "is infinite") +
                         " (PIPE.INPUT.ATTRIBUTES)");
    }
    const std::size_t required = required_vertex_count(pp.base.type);
    if ((required != 0 && nv != required) || (required == 0 && nv < 2))
      return err(pf + (pp.pos.empty() ? ".v" : ".pos"),
                 "a " + std::string(to_string(pp.base.type)) + " needs " +
                     (required == 0 ? std::string("at least 2") : std::to_string(required)) +
                     " vertices");
    const auto vertex_attr = [&](std::size_t j) {
      return nattr == 0 ? std::vector<float>{} : pp.attr[j];
    };
    // rule: PIPE.INTERP.FLAT
    // The provoking vertex of each segment: a strip's segment k runs from vertex k to k + 1
    // and is an independent line (LINE.STRIP.SEQUENCE); any other primitive is one segment.
    const auto flat_of = [&](std::size_t segment) {
      if (nattr == 0)
        return std::vector<float>{};
      const bool strip = pp.base.type == PrimitiveType::kLineStrip;
      const std::size_t first = strip ? segment : 0, last = strip ? segment + 1 : nv - 1;
      return pp.attr[s.provoking == Provoking::kFirst ? first : last];
    };
    // Adds a coverage primitive; segment: the strip segment a clipped line was cut from.
    const auto add = [&](const Primitive& prim, std::optional<std::uint32_t> part,
                         std::vector<WindowVertex> v, std::vector<std::vector<float>> attr,
                         std::size_t segment = 0) {
      std::vector<std::vector<float>> flat;
      const std::size_t n = segments_of(prim.type, v.size());
      for (std::size_t k = 0; k < n; ++k)
        flat.push_back(flat_of(segment + k));
      ws.primitives.push_back(prim);
      sources.push_back(Source{i, part, std::move(v), std::move(attr), std::move(flat)});
    };
    // Adds a drawn primitive of type t from window vertices (the clip-space paths).
    const auto add_window = [&](PrimitiveType t, std::optional<std::uint32_t> part,
                                const std::vector<ClipVertex>& vs, std::size_t segment = 0) {
      Primitive p = pp.base;
      p.type = t;
      p.v.clear();
      std::vector<WindowVertex> w;
      std::vector<std::vector<float>> attr;
      for (const ClipVertex& c : vs) {
        w.push_back(to_window(c.pos, vp));
        // rule: PIPE.CLIP.SATURATE
        // Rounding in the clipper can carry a created vertex a little beyond the guard band;
        // D3D's saturating conversion keeps it snappable (a no-op for every other vertex).
        w.back().x = saturate_to_snap_range(w.back().x);
        w.back().y = saturate_to_snap_range(w.back().y);
        p.v.push_back(FloatPoint{w.back().x, w.back().y});
        attr.push_back(c.attr);
      }
      add(p, part, std::move(w), std::move(attr), segment);
    };

    if (pp.pos.empty()) {
      // Window space: v as given, z and w optional.
      if (!pp.z.empty() && pp.z.size() != nv)
        return err(pf + ".z", "needs one value per vertex");
      if (!pp.w.empty() && pp.w.size() != nv)
        return err(pf + ".w", "needs one value per vertex");
      std::vector<WindowVertex> v(nv);
      for (std::size_t j = 0; j < nv; ++j) {
        v[j].x = pp.base.v[j][0];
        v[j].y = pp.base.v[j][1];
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
        attr.push_back(vertex_attr(j));
      add(pp.base, std::nullopt, std::move(v), std::move(attr));
      continue;
    }

    // Clip space (after the transform).
    std::vector<ClipVertex> cv(nv);
    for (std::size_t j = 0; j < nv; ++j) {
      const std::string vf = pf + ".pos[" + std::to_string(j) + "]";
      if (auto bad = check_position(pp.pos[j], vf, ""))
        return *bad;
      Vec4f p = pp.pos[j];
      if (has_transform) {
        if (s.model)
          p = transform(*s.model, p);
        if (s.view)
          p = transform(*s.view, p);
        if (s.projection)
          p = transform(*s.projection, p);
        if (auto bad = check_position(p, vf, " after the transform"))
          return *bad;
      }
      cv[j].pos = p;
      cv[j].attr = vertex_attr(j);
    }
    std::vector<Vec4f> clip_pos;
    for (const ClipVertex& c : cv)
      clip_pos.push_back(c.pos);
    const bool depth_clip = !s.depth || s.depth->clip;
    const ClipVolume vol = clip_volume(clip_pos, vp, depth_clip);
    switch (pp.base.type) {
    case PrimitiveType::kTriangle: {
      // rule: PIPE.CLIP.POLYGON, PIPE.CLIP.UNCLIPPED
      const std::vector<ClipVertex> poly = clip_polygon(cv, vol);
      const bool clipped = poly != cv;
      for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
        add_window(PrimitiveType::kTriangle,
                   clipped ? std::optional<std::uint32_t>(static_cast<std::uint32_t>(k - 1))
                           : std::nullopt,
                   {poly[0], poly[k], poly[k + 1]});
      }
      break;
    }
    case PrimitiveType::kPoint: {
      // rule: PIPE.CLIP.LINE
      if (inside(vol, cv[0].pos))
        add_window(PrimitiveType::kPoint, std::nullopt, cv);
      break;
    }
    case PrimitiveType::kLine:
    case PrimitiveType::kLineStrip: {
      // rule: PIPE.CLIP.LINE
      const bool all_in = std::all_of(cv.begin(), cv.end(),
                                      [&](const ClipVertex& c) { return inside(vol, c.pos); });
      if (all_in) {
        add_window(pp.base.type, std::nullopt, cv);
        break;
      }
      for (std::size_t k = 0; k + 1 < cv.size(); ++k) {
        const auto seg = clip_segment(cv[k], cv[k + 1], vol);
        if (seg)
          add_window(PrimitiveType::kLine, static_cast<std::uint32_t>(k), {(*seg)[0], (*seg)[1]},
                     k);
      }
      break;
    }
    }
  }

  // ---- snapping and setup: every rule of the rest of the kernel
  auto prepared_or = prepare(ws);
  if (auto* e = std::get_if<SceneError>(&prepared_or))
    return remap(*e, sources);
  const PreparedScene& ps = std::get<PreparedScene>(prepared_or);

  // rule: PIPE.VIEWPORT.SCISSOR
  const PixelRect scissor = viewport_scissor(vp);

  // ---- phase 1: coverage, in (prim, part, y, x, seg, sample) order, straight into the result
  std::vector<Fragment>& cover = result.fragments; // f.prim: the drawn primitive's index in ps
  for (std::size_t p = 0; p < ps.primitives.size(); ++p) {
    const auto emit = [&](const Fragment& f) {
      if (!scissor.contains(f.x, f.y))
        return;
      if (cover.size() >= o.max_fragments)
        throw Stop{err(idx("primitives", sources[p].prim),
                       "the scene produces more than " + std::to_string(o.max_fragments) +
                           " fragments (limit SCENE.INPUT.LIMITS)")};
      cover.push_back(f);
    };
    try {
      if (!for_each_fragment_bounded(ps, p, o.max_fragments, o.render, emit))
        return err(idx("primitives", sources[p].prim),
                   "touches more than " + std::to_string(o.max_fragments) +
                       " pixels or fragments that must be held to be sorted (limit "
                       "SCENE.INPUT.LIMITS)");
    } catch (Stop& stop) {
      return stop.error;
    }
  }
  // rule: PIPE.EFFECTS.ON_DEMAND
  // Window-space primitives are drawn one to one, so without clip space the drawn index is
  // the scene's; without depth and attributes nothing else is computed.
  if (fx.coverage_only())
    return result;
  // Drawn primitives: one per coverage primitive, one per segment of a strip, so that a strip's
  // segment k is interpolated from its own vertices k and k + 1 (LINE.STRIP.SEQUENCE).
  std::vector<std::size_t> first_drawn(ps.primitives.size() + 1, 0);
  for (std::size_t p = 0; p < ps.primitives.size(); ++p)
    first_drawn[p + 1] = first_drawn[p] + sources[p].flat.size();
  std::vector<std::uint32_t> drawn_of(cover.size());
  result.data.resize(cover.size());
  for (std::size_t i = 0; i < cover.size(); ++i) {
    Fragment& f = cover[i];
    const Source& src = sources[f.prim];
    const std::size_t segment = f.seg && *f.seg < src.flat.size() ? *f.seg : 0;
    drawn_of[i] = static_cast<std::uint32_t>(first_drawn[f.prim] + segment);
    result.data[i].drawn = drawn_of[i];
    f.prim = static_cast<std::uint32_t>(src.prim);
    result.data[i].part = src.part;
    result.data[i].passed = f.mask;
  }
  if (!fx.barycentrics)
    return result;

  // ---- per drawn primitive: window depths (after bias), w and attribute values
  const SamplePattern& pattern = ps.msaa.pattern;
  const DepthFormat fmt = s.depth ? s.depth->format : DepthFormat::kD24;
  const bool less_like =
      s.depth && (s.depth->func == CompareFunc::kLess || s.depth->func == CompareFunc::kLessEqual);
  const bool greater_like = s.depth && (s.depth->func == CompareFunc::kGreater ||
                                        s.depth->func == CompareFunc::kGreaterEqual);
  struct Drawn {
    PrimitiveType type = PrimitiveType::kTriangle;
    std::vector<Vec2> v; // snapped vertices: 3, 2 or 1
    std::array<float, 3> z{}, w{1.0f, 1.0f, 1.0f};
    std::vector<std::array<float, 3>> a;
    DepthValue lo, hi; // conservative bounds of every sample's stored depth (triangles, points)
    bool bounded = false;
  };
  std::vector<Drawn> drawn(first_drawn.back());
  for (std::size_t q = 0; q < drawn.size(); ++q) {
    // q is segment `segment` of coverage primitive p.
    const std::size_t p = static_cast<std::size_t>(
        std::upper_bound(first_drawn.begin(), first_drawn.end(), q) - first_drawn.begin() - 1);
    const std::size_t segment = q - first_drawn[p];
    const PreparedPrimitive& pr = ps.primitives[p];
    const Source& src = sources[p];
    Drawn& d = drawn[q];
    const bool strip = pr.type == PrimitiveType::kLineStrip;
    d.type = strip ? PrimitiveType::kLine : pr.type;
    const std::size_t first = strip ? segment : 0; // the segment's first vertex
    const std::size_t nv = strip ? 2 : std::min<std::size_t>(src.v.size(), 3);
    if (strip)
      d.v = {pr.v[segment], pr.v[segment + 1]};
    else
      d.v = pr.v;
    for (std::size_t j = 0; j < nv; ++j) {
      d.z[j] = src.v[first + j].z;
      d.w[j] = src.v[first + j].w;
    }
    // rule: PIPE.DEPTH.BIAS
    if (s.depth && pr.type == PrimitiveType::kTriangle &&
        (s.depth->bias.bias != 0 || s.depth->bias.slope_scaled != 0.0f)) {
      const float b = depth_bias({pr.v[0], pr.v[1], pr.v[2]}, d.z, s.depth->bias, fmt);
      for (float& zi : d.z) {
        zi = zi + b;
        if (std::isinf(zi)) // saturates like every float32 step of the bias (PIPE.DEPTH.BIAS)
          zi = std::copysign(std::numeric_limits<float>::max(), zi);
      }
    }
    for (std::size_t a = 0; a < nattr; ++a) {
      std::array<float, 3> v{};
      for (std::size_t j = 0; j < nv; ++j)
        v[j] = src.attr[first + j][a];
      d.a.push_back(v);
    }
    // rule: PIPE.OPT.HIZ
    // A covered sample of a triangle is a convex combination of its vertices, so its depth lies
    // in [min Zi, max Zi] up to the rounding of PIPE.DEPTH.INTERP (relative 2^-50 of the largest
    // |Zi|); the monotone conversion keeps the bounds. Lines extrapolate at their ends: none.
    if (s.depth && (pr.type == PrimitiveType::kTriangle || pr.type == PrimitiveType::kPoint)) {
      const std::size_t k = pr.type == PrimitiveType::kPoint ? 1 : 3;
      double zlo = d.z[0], zhi = d.z[0], zabs = 0.0;
      for (std::size_t j = 0; j < k; ++j) {
        zlo = std::min(zlo, static_cast<double>(d.z[j]));
        zhi = std::max(zhi, static_cast<double>(d.z[j]));
        zabs = std::max(zabs, std::fabs(static_cast<double>(d.z[j])));
      }
      const double margin = std::ldexp(zabs, -46) + std::ldexp(1.0, -1000);
      d.lo = to_depth_format(zlo - margin, vp.min_depth, vp.max_depth, fmt);
      d.hi = to_depth_format(zhi + margin, vp.min_depth, vp.max_depth, fmt);
      d.bounded = true;
    }
  }

  result.drawn.reserve(drawn.size());
  for (std::size_t p = 0; p < ps.primitives.size(); ++p) {
    const Source& src = sources[p];
    const bool strip = ps.primitives[p].type == PrimitiveType::kLineStrip;
    for (std::size_t k = 0; k < src.flat.size(); ++k) {
      const Drawn& d = drawn[first_drawn[p] + k];
      result.drawn.push_back(DrawnPrimitive{
          d.type, static_cast<std::uint32_t>(src.prim), src.part,
          strip ? std::optional<std::uint32_t>(static_cast<std::uint32_t>(k)) : std::nullopt, d.v,
          d.z, d.w, d.a, src.flat[k]});
    }
  }

  // ---- the depth target: tiles, fast clear, Hi-Z (PIPE.OPT.*)
  const std::int64_t T = o.tile_size;
  const std::int64_t tiles_x = (s.base.width + T - 1) / T, tiles_y = (s.base.height + T - 1) / T;
  const std::size_t ntiles = static_cast<std::size_t>(tiles_x * tiles_y);
  const DepthValue clear =
      s.depth ? to_depth_format(s.depth->clear, 0.0f, 1.0f, fmt) : DepthValue{};
  std::vector<std::uint8_t> cleared;  // fast clear: the tile still holds only the clear value
  std::vector<std::uint8_t> dirty;    // Hi-Z: the tile's bound must be recomputed
  std::vector<DepthValue> bound;      // Hi-Z: max (less-like) or min (greater-like) of the tile
  std::vector<std::size_t> checked;   // Hi-Z: drawn primitive last checked in the tile, + 1
  std::vector<std::uint8_t> rejected; // Hi-Z: whether that primitive was rejected there
  const bool use_hiz = o.hiz && (less_like || greater_like);
  std::atomic<std::uint64_t> n_hiz{0}, n_depth{0}, n_attr{0}; // PipeStats
  if (s.depth) {
    if (o.fast_clear) {
      result.depth_buffer.resize(static_cast<std::size_t>(s.base.width) *
                                 static_cast<std::size_t>(s.base.height) * nsamples);
      cleared.assign(ntiles, 1);
    } else {
      result.depth_buffer.assign(static_cast<std::size_t>(s.base.width) *
                                     static_cast<std::size_t>(s.base.height) * nsamples,
                                 clear);
    }
    if (use_hiz) {
      dirty.assign(ntiles, 0);
      bound.assign(ntiles, clear);
      checked.assign(ntiles, 0);
      rejected.assign(ntiles, 0);
    }
  }
  const auto tile_of = [&](std::int64_t x, std::int64_t y) {
    return static_cast<std::size_t>((y / T) * tiles_x + x / T);
  };
  const auto sample_index = [&](std::int64_t x, std::int64_t y, std::uint32_t k) {
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(s.base.width) +
            static_cast<std::size_t>(x)) *
               nsamples +
           k;
  };
  // Calls fn(index) for each sample of tile t.
  const auto for_tile = [&](std::size_t t, auto&& fn) {
    const std::int64_t tx = static_cast<std::int64_t>(t) % tiles_x,
                       ty = static_cast<std::int64_t>(t) / tiles_x;
    for (std::int64_t y = ty * T; y < std::min<std::int64_t>((ty + 1) * T, s.base.height); ++y)
      for (std::int64_t x = tx * T; x < std::min<std::int64_t>((tx + 1) * T, s.base.width); ++x)
        for (std::uint32_t k = 0; k < nsamples; ++k)
          fn(sample_index(x, y, k));
  };
  // rule: PIPE.OPT.FAST_CLEAR
  const auto materialize = [&](std::size_t t) {
    if (!cleared.empty() && cleared[t]) {
      for_tile(t, [&](std::size_t i) { result.depth_buffer[i] = clear; });
      cleared[t] = 0;
    }
  };
  const auto stored_less = [&](const DepthValue& a, const DepthValue& b) {
    return fmt == DepthFormat::kD32F ? a.f < b.f : a.unorm < b.unorm;
  };
  // rule: PIPE.OPT.HIZ
  // Whether every covered sample of drawn primitive p in tile t fails the test.
  const auto hiz_rejects = [&](std::size_t p, std::size_t t) {
    if (checked[t] == p + 1)
      return rejected[t] != 0;
    if (dirty[t]) {
      bool first = true;
      DepthValue b = clear;
      if (cleared.empty() || !cleared[t]) {
        for_tile(t, [&](std::size_t i) {
          const DepthValue& v = result.depth_buffer[i];
          if (first || (less_like ? stored_less(b, v) : stored_less(v, b)))
            b = v;
          first = false;
        });
      }
      bound[t] = b;
      dirty[t] = 0;
    }
    const Drawn& d = drawn[p];
    bool reject = false;
    if (d.bounded) {
      const CompareFunc f = s.depth->func;
      // less: new < old fails for all when lo >= max; less_equal: when lo > max.
      if (f == CompareFunc::kLess)
        reject = !stored_less(d.lo, bound[t]);
      if (f == CompareFunc::kLessEqual)
        reject = stored_less(bound[t], d.lo);
      if (f == CompareFunc::kGreater)
        reject = !stored_less(bound[t], d.hi);
      if (f == CompareFunc::kGreaterEqual)
        reject = stored_less(d.hi, bound[t]);
    }
    checked[t] = p + 1;
    rejected[t] = reject ? 1 : 0;
    if (reject)
      n_hiz.fetch_add(1, std::memory_order_relaxed);
    return reject;
  };

  // ---- phase 2: depth and attributes of fragment i
  const auto shade = [&](std::size_t i) {
    const Fragment& f = cover[i];
    const std::size_t p = drawn_of[i];
    const Drawn& d = drawn[p];
    const std::vector<float>& flat = result.drawn[p].flat;
    FragmentData& out = result.data[i];
    const Vec2 centre = pixel_center(f.x, f.y);
    const auto point_of = [&](Location l) {
      if (l == Location::kCentroid && f.centroid)
        return sample_position(f.x, f.y, f.centroid->offset);
      if (l == Location::kSample && f.sample)
        return sample_position(f.x, f.y, pattern.positions[*f.sample]);
      return centre;
    };
    // rule: PIPE.INTERP.LOCATION
    const Location first = nattr > 0 ? s.attributes[0].location : Location::kCenter;
    const auto interpolate = [&]() {
      out.bary = eval_bary(d.type, d.v, point_of(first));
      n_attr.fetch_add(nattr, std::memory_order_relaxed);
      out.attr.reserve(nattr);
      for (std::size_t a = 0; a < nattr; ++a) {
        const AttributeDecl& decl = s.attributes[a];
        const Barycentrics b =
            decl.location == first ? *out.bary : eval_bary(d.type, d.v, point_of(decl.location));
        switch (decl.interpolation) {
        case Interpolation::kPerspective:
          out.attr.push_back(interpolate_perspective(b, d.a[a], d.w, flat[a]));
          break;
        case Interpolation::kLinear:
          out.attr.push_back(interpolate_linear(b, d.a[a]));
          break;
        case Interpolation::kFlat:
          out.attr.push_back(flat[a]);
          break;
        }
      }
    };
    // rule: PIPE.OPT.EARLY_Z
    if (!o.early_z)
      interpolate(); // late: attributes first, dropped below if the fragment is killed
    if (s.depth && !f.helper) {
      // rule: PIPE.DEPTH.INTERP, PIPE.DEPTH.TEST, PIPE.DEPTH.WRITE
      const std::size_t t = tile_of(f.x, f.y);
      out.passed = 0;
      if (!(use_hiz && hiz_rejects(p, t))) {
        for (std::uint32_t k = 0; k < nsamples; ++k) {
          if ((f.mask & (1u << k)) == 0)
            continue;
          n_depth.fetch_add(1, std::memory_order_relaxed);
          const Barycentrics b =
              eval_bary(d.type, d.v, sample_position(f.x, f.y, pattern.positions[k]));
          const DepthValue dv =
              to_depth_format(interpolate_depth(b, d.z), vp.min_depth, vp.max_depth, fmt);
          out.depth.push_back(dv);
          const std::size_t si = sample_index(f.x, f.y, k);
          const DepthValue old = (!cleared.empty() && cleared[t]) ? clear : result.depth_buffer[si];
          if (depth_test(s.depth->func, dv, old, fmt)) {
            out.passed |= 1u << k;
            if (s.depth->write) {
              materialize(t);
              result.depth_buffer[si] = dv;
              if (use_hiz)
                dirty[t] = 1;
            }
          }
        }
      }
      // rule: PIPE.DEPTH.KILL
      if (out.passed == 0) {
        out.depth.clear();
        out.attr.clear();
        out.bary.reset();
        return;
      }
    }
    if (o.early_z)
      interpolate();
  };

  // rule: PIPE.OPT.TILES, PIPE.OPT.THREADS
  if (o.binning && s.depth) {
    // Bin the fragments by tile (each bin in fragment order), then shade tile by tile; tiles
    // share no sample, so they may run on several threads.
    std::vector<std::vector<std::size_t>> bins(ntiles);
    for (std::size_t i = 0; i < cover.size(); ++i)
      bins[tile_of(cover[i].x, cover[i].y)].push_back(i);
    run_units(ntiles, std::max(1u, o.render.threads), [&](std::size_t t) {
      for (const std::size_t i : bins[t])
        shade(i);
    });
  } else {
    for (std::size_t i = 0; i < cover.size(); ++i)
      shade(i);
  }
  if (!cleared.empty())
    for (std::size_t t = 0; t < ntiles; ++t) {
      result.stats.tiles_never_written += cleared[t];
      materialize(t);
    }
  result.stats.hiz_rejected = n_hiz.load();
  result.stats.depth_samples = n_depth.load();
  result.stats.attributes = n_attr.load();
  return result;
}

} // namespace rastrules::pipe

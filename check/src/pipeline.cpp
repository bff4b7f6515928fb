// SPDX-License-Identifier: MIT
// Pipeline results against the oracle (check.hpp, check_pipeline): the value invariants and each
// value against the oracle from the fragment's drawn primitive, then a replay from the scene
// alone: the oracle's account of each primitive (its transform, clip volume, clipped polygon,
// fan, window vertices and snapped positions, all from oracle/pipe.hpp), sample positions from
// the oracle's own pattern tables, barycentrics, attributes and depths within the spec's bounds
// at each evaluation point, the depth test replayed sample by sample, killed fragments, the
// scissor, the output order, and the coverage of every part equal to the window-space path.
// Implements (checks for): PIPE.CLIP.UNCLIPPED, PIPE.CLIP.POLYGON, PIPE.BARY.EXACT,
//   PIPE.INTERP.LOCATION, PIPE.INTERP.PERSPECTIVE, PIPE.INTERP.LINEAR, PIPE.INTERP.FLAT,
//   PIPE.INTERP.BOUND, PIPE.DEPTH.INTERP, PIPE.DEPTH.BOUND, PIPE.DEPTH.TEST, PIPE.DEPTH.WRITE,
//   PIPE.DEPTH.KILL, PIPE.VIEWPORT.SCISSOR
#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <variant>
#include <vector>

#include "checker.hpp"
#include "rastrules/check/check.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/names.hpp"
#include "rastrules/oracle/msaa.hpp"
#include "rastrules/oracle/pipe.hpp"
#include "rastrules/oracle/triangle.hpp"
#include "rastrules/pipeline.hpp"

namespace rastrules::check {

namespace {

using detail::centre_raw;
using detail::Checker;
namespace om = rastrules::oracle::msaa;
using Raw2 = rastrules::oracle::pipe::Raw2;

// ---------------------------------------------------------------------------------------------
// The adapter's words for messages and for the oracle

// A float as its shortest round-trip text (NaN and infinities spelled out).
std::string float_text(float v) {
  if (std::isnan(v))
    return "NaN";
  if (std::isinf(v))
    return v > 0 ? "Infinity" : "-Infinity";
  std::array<char, 64> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  return std::string(buf.data(), r.ptr);
}
template <class Floats> std::string float_text(const Floats& a) {
  std::string s = "[";
  for (std::size_t i = 0; i < a.size(); ++i)
    s += (i ? ", " : "") + float_text(a[i]);
  return s + "]";
}
std::string raw_text(const Raw2& r) {
  return "(" + std::to_string(r[0]) + ", " + std::to_string(r[1]) + ")";
}
std::string raw_text(const std::array<Raw2, 3>& t) {
  return raw_text(t[0]) + " " + raw_text(t[1]) + " " + raw_text(t[2]);
}

bool same_bits(float a, float b) {
  return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b) ||
         (std::isnan(a) && std::isnan(b));
}

// Whether every coordinate is finite with magnitude <= 2^64 (PIPE.INPUT.POSITION).
bool position_ok(const pipe::Vec4f& p) {
  return std::all_of(p.begin(), p.end(), [](float c) {
    return std::isfinite(c) && std::fabs(static_cast<double>(c)) <= pipe::kMaxPosition;
  });
}

oracle::pipe::Bary to_oracle(const pipe::Barycentrics& b) {
  return oracle::pipe::Bary{b.e, b.area};
}
oracle::pipe::Viewport to_oracle(const pipe::Viewport& v) {
  return oracle::pipe::Viewport{v.x, v.y, v.width, v.height, v.min_depth, v.max_depth};
}
oracle::pipe::Stored to_oracle(const pipe::DepthValue& d) {
  return oracle::pipe::Stored{d.unorm, d.f};
}
std::string compare_name(pipe::CompareFunc f) {
  return std::string(pipe::to_string(f));
}

namespace kp = rastrules::pipe;
namespace op = rastrules::oracle::pipe;

std::string where(const Fragment& f) {
  return "prim " + std::to_string(f.prim) + " pixel (" + std::to_string(f.x) + ", " +
         std::to_string(f.y) + ")";
}

op::Raw2 raw(Vec2 v) {
  return {v.x.raw(), v.y.raw()};
}

// The barycentrics of PIPE.BARY.LINE, written from the spec: the exact projection parameter
// t = num / den of s onto the segment as (den - num, num, 0) / den; a point's are (1, 0, 0) / 1
// (a point is a segment whose ends are its vertex), a zero-length line's (0, 0, 0) / 0.
// rule: PIPE.BARY.LINE
op::Bary line_bary(const std::array<Raw2, 2>& v, const Raw2& s, bool point) {
  if (point)
    return op::Bary{{1, 0, 0}, 1};
  const std::int64_t dx = v[1][0] - v[0][0], dy = v[1][1] - v[0][1];
  const std::int64_t den = dx * dx + dy * dy;
  const std::int64_t num = (s[0] - v[0][0]) * dx + (s[1] - v[0][1]) * dy;
  return op::Bary{{den - num, num, 0}, den};
}

// The oracle's barycentrics of drawn primitive d at s: a triangle's exact edge values, a line's
// projection parameter (as in the kernel's output, SCENE.OUTPUT.PIPELINE), a point's (1, 0, 0).
op::Bary bary_of(const kp::DrawnPrimitive& d, Vec2 s) {
  if (d.type == PrimitiveType::kTriangle)
    return op::barycentrics({raw(d.snapped[0]), raw(d.snapped[1]), raw(d.snapped[2])}, raw(s));
  if (d.type == PrimitiveType::kPoint || d.snapped.size() < 2)
    return line_bary({raw(s), raw(s)}, raw(s), true);
  return line_bary({raw(d.snapped[0]), raw(d.snapped[1])}, raw(s), false);
}

std::string format_name(kp::DepthFormat f) {
  return std::string(kp::to_string(f));
}

double stored_as_double(const kp::DepthValue& v, kp::DepthFormat f) {
  return f == kp::DepthFormat::kD32F ? static_cast<double>(v.f) : static_cast<double>(v.unorm);
}

// The value invariants and the values against the oracle from each fragment's drawn primitive;
// returns how many values it compared with the oracle.
std::size_t check_values(const Scene& scene, const kp::PipeResult& result, Checker& out) {
  const kp::Viewport vp = scene.viewport.value_or(
      kp::Viewport{0, 0, static_cast<float>(scene.width), static_cast<float>(scene.height), 0, 1});
  const SamplePattern& pattern = scene.msaa.pattern;
  const kp::DepthFormat fmt = scene.depth ? scene.conventions.depth : kp::DepthFormat::kD24;
  const kp::DepthValue lo = kp::to_depth_format(vp.min_depth, 0, 1, fmt);
  const kp::DepthValue hi = kp::to_depth_format(vp.max_depth, 0, 1, fmt);
  const auto report = [&](const std::string& m) { out.note(m); };
  std::size_t checks = 0;
  for (std::size_t i = 0; i < result.data.size(); ++i) {
    const Fragment& f = result.fragments[i];
    const kp::FragmentData& d = result.data[i];
    if (d.bary && d.bary->e[0] + d.bary->e[1] + d.bary->e[2] != d.bary->area)
      report(where(f) + ": barycentrics do not sum to the area (PIPE.BARY.SUM)");
    for (const float a : d.attr)
      if (!std::isfinite(a))
        report(where(f) + ": an attribute is not finite (PIPE.INTERP.HORIZON)");
    for (const kp::DepthValue& z : d.depth)
      if (stored_as_double(z, fmt) < stored_as_double(lo, fmt) ||
          stored_as_double(z, fmt) > stored_as_double(hi, fmt) ||
          (fmt == kp::DepthFormat::kD32F && !std::isfinite(z.f)))
        report(where(f) + ": a stored depth lies outside the viewport's range (PIPE.DEPTH.CLAMP)");
    if (result.drawn.empty())
      continue;
    const kp::DrawnPrimitive& dp = result.drawn[d.drawn];
    // Attributes against the exact oracle (PIPE.INTERP.BOUND).
    for (std::size_t a = 0; a < d.attr.size(); ++a) {
      const kp::AttributeDecl& decl = scene.attributes[a];
      Vec2 at = pixel_center(f.x, f.y);
      if (decl.location == kp::Location::kCentroid && f.centroid)
        at = sample_position(f.x, f.y, f.centroid->offset);
      if (decl.location == kp::Location::kSample && f.sample)
        at = sample_position(f.x, f.y, pattern.positions[*f.sample]);
      const op::Bary b = bary_of(dp, at);
      ++checks;
      if (decl.interpolation == kp::Interpolation::kFlat) {
        if (d.attr[a] != dp.flat[a])
          report(where(f) + ": flat attribute " + decl.name + " is not the provoking vertex's");
        continue;
      }
      if (b.area == 0)
        continue; // a zero-length line: the flat value (PIPE.INTERP.HORIZON)
      const op::InterpCheck c =
          decl.interpolation == kp::Interpolation::kPerspective
              ? op::check_perspective(b, dp.attr[a], dp.w, dp.flat[a], d.attr[a])
              : op::check_linear(b, dp.attr[a], d.attr[a]);
      if (!c.ok)
        report(where(f) + ": attribute " + decl.name + ": " + c.describe());
    }
    // Depths against the exact oracle (PIPE.DEPTH.BOUND).
    std::size_t n = 0;
    for (std::uint32_t k = 0; k < pattern.count() && n < d.depth.size(); ++k) {
      if ((f.mask & (1u << k)) == 0)
        continue;
      const op::Bary b = bary_of(dp, sample_position(f.x, f.y, pattern.positions[k]));
      const kp::DepthValue& got = d.depth[n++];
      ++checks;
      if (b.area == 0)
        continue;
      const op::DepthCheck c = op::check_depth_stored(
          b, dp.z, vp.min_depth, vp.max_depth, format_name(fmt), op::Stored{got.unorm, got.f});
      if (!c.ok)
        report(where(f) + ": sample " + std::to_string(k) + ": " + c.describe(format_name(fmt)));
    }
  }
  return checks;
}

op::Viewport viewport_of(const rastrules::Scene& s) {
  if (s.viewport)
    return to_oracle(*s.viewport);
  return op::Viewport{0.0f, 0.0f, static_cast<float>(s.width), static_cast<float>(s.height),
                      0.0f, 1.0f};
}

// One fan triangle (or the unclipped triangle) in window space.
struct Part {
  std::array<op::WindowVertex, 3> wv{};
  std::array<Raw2, 3> raw{};
  std::array<std::vector<float>, 3> attr; // per vertex, one per attribute
};

// One segment of a line or line strip (a point: both ends its vertex) in window space.
struct Seg {
  std::array<op::WindowVertex, 2> wv{};
  std::array<Raw2, 2> raw{};
  std::array<std::vector<float>, 2> attr; // per end, one per attribute
  std::vector<float> flat;                // per attribute: the segment's provoking vertex
};

struct PrimGeometry {
  bool transform_error = false; // a clip-space position beyond the limit after the transform
  bool clipped = false;
  std::vector<Part> parts;
  std::vector<float> flat; // per attribute
  std::string problem;     // a window vertex that does not snap (the guard band's promise)
  // A clip-space point or line: its window vertices after clipping (empty: discarded).
  std::vector<op::WindowVertex> other;
  // Points, lines and strips: one entry per segment (a point or line: one), empty where the
  // clipper discarded the segment (PIPE.CLIP.LINE, LINE.STRIP.SEQUENCE, PIPE.INTERP.FLAT).
  std::vector<std::optional<Seg>> segs;
};

std::optional<Raw2> snap2(float x, float y) {
  const auto rx = oracle::snap(x), ry = oracle::snap(y);
  if (!rx || !ry)
    return std::nullopt;
  return Raw2{*rx, *ry};
}

// Appends segment k of primitive prim with window ends wv and their attributes; its flat value
// is that of the segment's provoking vertex (PIPE.INTERP.FLAT: of each segment of a strip).
void add_segment(PrimGeometry& g, const rastrules::Scene& s, std::size_t prim,
                 const std::array<op::WindowVertex, 2>& wv,
                 const std::array<std::vector<float>, 2>& attr, std::size_t k) {
  const rastrules::Primitive& p = s.primitives[prim];
  const std::size_t nv = p.pos.empty() ? p.v.size() : p.pos.size();
  const bool strip = p.type == PrimitiveType::kLineStrip;
  const std::size_t provoking =
      s.conventions.provoking == kp::Provoking::kFirst ? (strip ? k : 0) : (strip ? k + 1 : nv - 1);
  Seg seg;
  seg.wv = wv;
  seg.attr = attr;
  for (std::size_t a = 0; a < s.attributes.size(); ++a)
    seg.flat.push_back(p.attr.at(provoking).at(a));
  for (std::size_t i = 0; i < 2; ++i) {
    const auto r = snap2(wv[i].x, wv[i].y);
    if (!r) {
      g.problem = "window vertex (" + float_text(wv[i].x) + ", " + float_text(wv[i].y) +
                  ") of primitive " + std::to_string(prim) + " does not snap";
      return;
    }
    seg.raw[i] = *r;
  }
  g.segs.emplace_back(std::move(seg));
}

PrimGeometry geometry(const rastrules::Scene& s, std::size_t prim) {
  const rastrules::Primitive& p = s.primitives[prim];
  const op::Viewport vp = viewport_of(s);
  PrimGeometry g;
  const std::size_t nv = p.pos.empty() ? p.v.size() : p.pos.size();
  const std::size_t nattr = s.attributes.size();
  for (std::size_t k = 0; k < nattr; ++k) {
    std::vector<float> values;
    for (std::size_t j = 0; j < nv; ++j)
      values.push_back(p.attr.at(j).at(k));
    g.flat.push_back(op::flat_value(
        values, s.conventions.provoking == kp::Provoking::kFirst ? "first" : "last"));
  }
  const auto vertex_attr = [&](std::size_t j) {
    return nattr == 0 ? std::vector<float>{} : p.attr.at(j);
  };
  std::vector<op::WindowVertex> wv;
  std::vector<std::vector<float>> attrs;
  if (p.pos.empty()) {
    for (std::size_t j = 0; j < nv; ++j) {
      op::WindowVertex v;
      v.x = p.v[j][0];
      v.y = p.v[j][1];
      v.z = p.z.empty() ? 0.0f : p.z[j];
      v.w = p.w.empty() ? 1.0f : p.w[j];
      wv.push_back(v);
      attrs.push_back(vertex_attr(j));
    }
  } else {
    std::vector<op::ClipVertex> cv;
    std::vector<op::Vec4> pos;
    for (std::size_t j = 0; j < nv; ++j) {
      op::Vec4 c = p.pos[j];
      if (s.model)
        c = op::transform(*s.model, c);
      if (s.view)
        c = op::transform(*s.view, c);
      if (s.projection)
        c = op::transform(*s.projection, c);
      if (!position_ok(c))
        g.transform_error = true;
      cv.push_back(op::ClipVertex{c, vertex_attr(j)});
      pos.push_back(c);
    }
    if (g.transform_error)
      return g;
    const bool depth_clip = !s.depth || s.depth->clip;
    const op::Volume vol = op::clip_volume(pos, vp, depth_clip);
    // PIPE.CLIP.SATURATE: clip-space window positions are clamped to the snap range.
    const auto window = [&](const op::Vec4& q) {
      op::WindowVertex w = op::to_window(q, vp);
      w.x = std::clamp(w.x, -32768.0f, 32767.99609375f);
      w.y = std::clamp(w.y, -32768.0f, 32767.99609375f);
      return w;
    };
    // PIPE.CLIP.LINE: a point outside the volume is discarded, a line cut like an edge; a strip
    // with every vertex inside stays whole, otherwise each segment is cut on its own (a part).
    if (p.type == PrimitiveType::kPoint) {
      if (op::inside(vol, pos[0])) {
        g.other.push_back(window(pos[0]));
        add_segment(g, s, prim, {g.other[0], g.other[0]}, {cv[0].attr, cv[0].attr}, 0);
      } else {
        g.segs.emplace_back();
      }
      return g;
    }
    if (p.type == PrimitiveType::kLine || p.type == PrimitiveType::kLineStrip) {
      const bool all_in = std::all_of(pos.begin(), pos.end(),
                                      [&](const op::Vec4& c) { return op::inside(vol, c); });
      g.clipped = !all_in;
      for (std::size_t k = 0; k + 1 < nv; ++k) {
        if (all_in) {
          add_segment(g, s, prim, {window(pos[k]), window(pos[k + 1])},
                      {cv[k].attr, cv[k + 1].attr}, k);
        } else if (const auto seg = op::clip_segment(cv[k], cv[k + 1], vol)) {
          add_segment(g, s, prim, {window((*seg)[0].pos), window((*seg)[1].pos)},
                      {(*seg)[0].attr, (*seg)[1].attr}, k);
        } else {
          g.segs.emplace_back();
        }
        if (!g.problem.empty())
          return g;
      }
      if (p.type == PrimitiveType::kLine && g.segs[0])
        g.other = {g.segs[0]->wv[0], g.segs[0]->wv[1]};
      // A line inside the volume is not clipped (no part), like an unclipped strip.
      return g;
    }
    const std::vector<op::ClipVertex> poly = op::clip_polygon(cv, vol);
    bool same = poly.size() == cv.size();
    for (std::size_t j = 0; same && j < poly.size(); ++j) {
      for (std::size_t c = 0; c < 4; ++c)
        same = same && same_bits(poly[j].pos[c], cv[j].pos[c]);
    }
    g.clipped = !same;
    for (const op::ClipVertex& c : poly) {
      wv.push_back(window(c.pos));
      attrs.push_back(c.attr);
    }
  }
  if (p.type != PrimitiveType::kTriangle) {
    // Window space: a point is one segment of no length, a line or strip one per segment.
    for (std::size_t k = 0; k == 0 || k + 1 < nv; ++k) {
      const std::size_t k1 = std::min(k + 1, nv - 1);
      add_segment(g, s, prim, {wv[k], wv[k1]}, {attrs[k], attrs[k1]}, k);
      if (!g.problem.empty())
        return g;
    }
    return g;
  }
  for (std::size_t k = 1; k + 1 < wv.size(); ++k) {
    Part part;
    const std::array<std::size_t, 3> idx{0, k, k + 1};
    for (std::size_t i = 0; i < 3; ++i) {
      part.wv[i] = wv[idx[i]];
      part.attr[i] = attrs[idx[i]];
      const auto r = snap2(part.wv[i].x, part.wv[i].y);
      if (!r) {
        g.problem = "window vertex (" + float_text(part.wv[i].x) + ", " + float_text(part.wv[i].y) +
                    ") of primitive " + std::to_string(prim) + " does not snap";
        return g;
      }
      part.raw[i] = *r;
    }
    // PIPE.DEPTH.BIAS: each fan triangle from its own snapped vertices and depths.
    if (s.depth && s.depth->bias.enabled()) {
      const kp::DepthBias& b = s.depth->bias;
      const float bias =
          op::depth_bias(part.raw, {part.wv[0].z, part.wv[1].z, part.wv[2].z}, b.bias,
                         b.slope_scaled, b.clamp, format_name(s.conventions.depth));
      for (op::WindowVertex& v : part.wv)
        v.z = op::sat32(op::fl32_add(v.z, bias));
    }
    g.parts.push_back(part);
  }
  return g;
}

// ---------------------------------------------------------------------------------------------
// Sample positions, from the oracle's pattern tables

std::vector<om::Offset> pattern_of(const rastrules::Scene& s) {
  return om::standard_pattern(s.msaa.count());
}
Raw2 offset_raw(std::int32_t x, std::int32_t y, const om::Offset& o) {
  const Raw2 c = centre_raw(x, y);
  return {c[0] + 16 * std::int64_t{o.x}, c[1] + 16 * std::int64_t{o.y}};
}

// ---------------------------------------------------------------------------------------------
// Checking one run

// Which stored values of the allowed range [lo, hi] fail the test against old: whether some
// value in the range fails (a killed sample is then consistent).
bool some_value_fails(const std::string& func, const op::Stored& lo, const op::Stored& hi,
                      const op::Stored& old, const std::string& format) {
  const bool d32f = format == "d32f";
  const auto lt = [&](const op::Stored& a, const op::Stored& b) {
    return d32f ? a.f < b.f : a.unorm < b.unorm;
  };
  const auto eq = [&](const op::Stored& a, const op::Stored& b) { return !lt(a, b) && !lt(b, a); };
  if (func == "never")
    return true;
  if (func == "always")
    return false;
  if (func == "less")
    return !lt(hi, old); // some v >= old
  if (func == "less_equal")
    return lt(old, hi); // some v > old
  if (func == "greater")
    return !lt(old, lo); // some v <= old
  if (func == "greater_equal")
    return lt(lo, old); // some v < old
  if (func == "equal")
    return !(eq(lo, old) && eq(hi, old));
  if (func == "not_equal")
    return !lt(old, lo) && !lt(hi, old); // old in [lo, hi]
  return false;
}

// The scene-wide state of a replay: the oracle's viewport, scissor and pattern, the depth
// format and test, each primitive's geometry and the replayed depth buffer.
struct Replay {
  const rastrules::Scene& s;
  const kp::PipeResult& r;
  PipelineStats& st;
  op::Viewport vp{};
  op::Rect sc{};
  std::uint32_t n = 1;
  std::vector<om::Offset> pattern{};
  bool has_depth = false;
  std::string fmt{}, func{};
  std::int64_t W = 0, H = 0;
  std::vector<op::Stored> buffer{};
  std::vector<PrimGeometry> geo{};
};

// One fragment being replayed: its data, its name in messages, and the oracle's part or
// segment that drew it (set by locate).
struct FragmentReplay {
  const Fragment& f;
  const kp::FragmentData* d;
  std::string at;
  const Part* part = nullptr;
  const Seg* seg = nullptr; // points, lines, strip segments (PIPE.BARY.LINE)
  std::size_t seg_index = 0;
  bool point = false, strip = false;
  bool killed = false; // set by replay_depth

  // Finds the oracle's part (a triangle) or segment (a point, line or strip segment) that drew
  // the fragment, as its part and seg say; returns the first problem, or "".
  std::string locate(const Replay& R);
  // The drawn primitive the kernel reports equals the oracle's part or segment, bit for bit.
  [[nodiscard]] std::string check_drawn(const Replay& R) const;
  // The depth test replayed sample by sample into the oracle's depth buffer: each stored
  // depth within its bound, a killed fragment one whose every allowed depth fails, the passed
  // mask.
  std::string replay_depth(Replay& R);
  // Barycentrics and attributes at each evaluation point, within the spec's bounds of the
  // exact values of the oracle's part or segment.
  [[nodiscard]] std::string check_values(Replay& R) const;
};

std::string FragmentReplay::locate(const Replay& R) {
  const rastrules::Scene& s = R.s;
  const std::vector<PrimGeometry>& geo = R.geo;
  if (f.prim >= s.primitives.size())
    return at + ": no such primitive";
  const rastrules::Primitive& pp = s.primitives[f.prim];
  const PrimGeometry& g = geo[f.prim];
  if (g.transform_error)
    return at + ": the scene should have been rejected (transform)";
  const bool triangle = pp.type == PrimitiveType::kTriangle;
  strip = pp.type == PrimitiveType::kLineStrip;
  point = pp.type == PrimitiveType::kPoint;
  if (!triangle) {
    if (d && d->part.has_value() != g.clipped)
      return at + ": part " + (d->part ? "present" : "absent") + " but the oracle's clipper " +
             (g.clipped ? "clips" : "does not clip");
    if (strip && f.seg.has_value() == g.clipped)
      return at + ": seg " + (f.seg ? "present" : "absent") + " on a strip the oracle " +
             (g.clipped ? "clips into lines" : "draws whole");
    seg_index = d && d->part ? *d->part : (f.seg ? *f.seg : 0);
    if (seg_index >= g.segs.size() || !g.segs[seg_index])
      return at + ": segment " + std::to_string(seg_index) + " the oracle's clipper discards";
    seg = &*g.segs[seg_index];
  }
  if (triangle) {
    const std::size_t k = d && d->part ? *d->part : 0;
    if (d && d->part.has_value() != g.clipped)
      return at + ": part " + (d->part ? "present" : "absent") + " but the oracle's clipper " +
             (g.clipped ? "clips" : "does not clip");
    if (k >= g.parts.size())
      return at + ": part " + std::to_string(k) + " of " + std::to_string(g.parts.size());
    part = &g.parts[k];
  }
  return "";
}

std::string FragmentReplay::check_drawn(const Replay& R) const {
  const rastrules::Scene& s = R.s;
  const kp::PipeResult& r = R.r;
  const rastrules::Primitive& pp = R.s.primitives[f.prim];
  const PrimGeometry& g = R.geo[f.prim];
  if (d && !r.drawn.empty()) {
    if (d->drawn >= r.drawn.size())
      return at + ": no drawn primitive " + std::to_string(d->drawn);
    const kp::DrawnPrimitive& dp = r.drawn[d->drawn];
    const PrimitiveType drawn_type = strip ? PrimitiveType::kLine : pp.type;
    const std::int64_t drawn_seg = strip && !g.clipped ? static_cast<std::int64_t>(seg_index) : -1;
    if (dp.prim != f.prim || dp.part != d->part || dp.type != drawn_type ||
        (dp.seg ? std::int64_t{*dp.seg} : -1) != drawn_seg)
      return at + ": its drawn primitive names another primitive, part, segment or type";
    if (seg) {
      const std::size_t ends = pp.type == PrimitiveType::kPoint ? 1 : 2;
      bool same = dp.snapped.size() == ends && dp.attr.size() == s.attributes.size() &&
                  dp.flat.size() == seg->flat.size();
      for (std::size_t j = 0; same && j < ends; ++j) {
        same = dp.snapped[j].x.raw() == seg->raw[j][0] && dp.snapped[j].y.raw() == seg->raw[j][1] &&
               same_bits(dp.z[j], seg->wv[j].z) && same_bits(dp.w[j], seg->wv[j].w);
        for (std::size_t k = 0; same && k < s.attributes.size(); ++k)
          same = same_bits(dp.attr[k][j], seg->attr[j].at(k));
      }
      for (std::size_t k = 0; same && k < seg->flat.size(); ++k)
        same = same_bits(dp.flat[k], seg->flat[k]);
      if (!same)
        return at + ": drawn " + std::string(to_string(drawn_type)) + " (segment " +
               std::to_string(seg_index) + ") differs from the oracle's: oracle ends " +
               raw_text(seg->raw[0]) + " " + raw_text(seg->raw[1]) + " z " +
               float_text(std::array<float, 2>{seg->wv[0].z, seg->wv[1].z}) + " w " +
               float_text(std::array<float, 2>{seg->wv[0].w, seg->wv[1].w}) + ", kernel z " +
               float_text(dp.z) + " w " + float_text(dp.w);
    }
    if (part) {
      bool same = dp.snapped.size() == 3 && dp.attr.size() == s.attributes.size() &&
                  dp.flat.size() == g.flat.size();
      for (std::size_t j = 0; same && j < 3; ++j) {
        same = dp.snapped[j].x.raw() == part->raw[j][0] &&
               dp.snapped[j].y.raw() == part->raw[j][1] && same_bits(dp.z[j], part->wv[j].z) &&
               same_bits(dp.w[j], part->wv[j].w);
        for (std::size_t k = 0; same && k < s.attributes.size(); ++k)
          same = same_bits(dp.attr[k][j], part->attr[j].at(k));
      }
      for (std::size_t k = 0; same && k < g.flat.size(); ++k)
        same = same_bits(dp.flat[k], g.flat[k]);
      if (!same) {
        std::string got;
        for (const Vec2& v : dp.snapped)
          got += " (" + std::to_string(v.x.raw()) + ", " + std::to_string(v.y.raw()) + ")";
        return at + ": drawn primitive differs from the oracle's: kernel snapped" + got + " z " +
               float_text(dp.z) + " w " + float_text(dp.w) + "; oracle " + raw_text(part->raw) +
               " z " +
               float_text(std::array<float, 3>{part->wv[0].z, part->wv[1].z, part->wv[2].z}) +
               " w " +
               float_text(std::array<float, 3>{part->wv[0].w, part->wv[1].w, part->wv[2].w});
      }
    }
  }
  return "";
}

std::string FragmentReplay::replay_depth(Replay& R) {
  const rastrules::Scene& s = R.s;
  PipelineStats& st = R.st;
  const op::Viewport& vp = R.vp;
  const std::uint32_t n = R.n;
  const std::vector<om::Offset>& pattern = R.pattern;
  const bool has_depth = R.has_depth;
  const std::string& fmt = R.fmt;
  const std::string& func = R.func;
  const std::int64_t W = R.W;
  std::vector<op::Stored>& buffer = R.buffer;
  killed = has_depth && d->passed == 0 && !f.helper;
  std::uint32_t passed = 0;
  if (has_depth && !f.helper) {
    if (!killed && d->depth.size() != static_cast<std::size_t>(std::popcount(f.mask)))
      return at + ": " + std::to_string(d->depth.size()) + " depth values";
    if (killed && (!d->depth.empty() || !d->attr.empty() || d->bary))
      return at + ": killed but carries depth, attributes or barycentrics";
    std::size_t j = 0;
    for (std::uint32_t smp = 0; smp < n; ++smp) {
      if ((f.mask & (1u << smp)) == 0)
        continue;
      const std::size_t idx = static_cast<std::size_t>((f.y * W + f.x) * n + smp);
      const Raw2 pos = offset_raw(f.x, f.y, pattern[smp]);
      // The exact barycentrics and vertex depths of the sample (PIPE.BARY.EXACT, PIPE.BARY.LINE).
      std::optional<std::pair<op::Bary, std::array<float, 3>>> exact;
      if (part)
        exact = {op::barycentrics(part->raw, pos), {part->wv[0].z, part->wv[1].z, part->wv[2].z}};
      if (seg)
        exact = {line_bary(seg->raw, pos, point), {seg->wv[0].z, seg->wv[1].z, 0.0f}};
      if (exact && exact->first.area == 0)
        exact.reset(); // a zero-length line: vertex 0's depth
      if (killed) {
        if (exact) {
          const op::DepthCheck c = op::check_depth_stored(exact->first, exact->second, vp.min_depth,
                                                          vp.max_depth, fmt, op::Stored{});
          if (!some_value_fails(func, c.lo, c.hi, buffer[idx], fmt))
            return at + ": killed, but sample " + std::to_string(smp) +
                   " passes for every allowed depth: " + c.describe(fmt);
        }
        continue;
      }
      const op::Stored now = to_oracle(d->depth[j++]);
      if (exact) {
        op::DepthCheck c = op::check_depth_stored(exact->first, exact->second, vp.min_depth,
                                                  vp.max_depth, fmt, now);
        ++st.depth_checks;
        if (!c.ok)
          return at + ": depth of sample " + std::to_string(smp) + ": " + c.describe(fmt);
      }
      if (op::depth_test(func, now, buffer[idx], fmt)) {
        passed |= 1u << smp;
        if (s.depth->write)
          buffer[idx] = now;
      }
    }
    if (killed)
      ++st.killed;
    if (!killed && passed != d->passed)
      return at + ": passed " + std::to_string(d->passed) + ", the replayed test gives " +
             std::to_string(passed);
  } else if (d && d->passed != f.mask) {
    return at + ": passed " + std::to_string(d->passed) + " without a depth test";
  }
  return "";
}

std::string FragmentReplay::check_values(Replay& R) const {
  const rastrules::Scene& s = R.s;
  PipelineStats& st = R.st;
  const std::uint32_t n = R.n;
  const std::vector<om::Offset>& pattern = R.pattern;
  const bool has_depth = R.has_depth;
  const PrimGeometry& g = R.geo[f.prim];
  const std::vector<float>& flat = seg ? seg->flat : g.flat;
  // The exact barycentrics at an evaluation point, and the vertex values they weigh.
  const auto bary_at = [&](const Raw2& q) {
    return part ? op::barycentrics(part->raw, q) : line_bary(seg->raw, q, point);
  };
  const auto vertex_values = [&](std::size_t k) {
    return part
               ? std::array<float, 3>{part->attr[0].at(k), part->attr[1].at(k), part->attr[2].at(k)}
               : std::array<float, 3>{seg->attr[0].at(k), seg->attr[1].at(k), 0.0f};
  };
  const std::array<float, 3> vertex_w =
      part ? std::array<float, 3>{part->wv[0].w, part->wv[1].w, part->wv[2].w}
           : std::array<float, 3>{seg->wv[0].w, seg->wv[1].w, 1.0f};
  const std::string vertices =
      part ? raw_text(part->raw) : raw_text(seg->raw[0]) + " " + raw_text(seg->raw[1]);
  // Barycentrics and attributes.
  const auto location_raw = [&](kp::Location l) -> std::optional<Raw2> {
    switch (l) {
    case kp::Location::kCenter:
      return centre_raw(f.x, f.y);
    case kp::Location::kSample:
      if (!f.sample)
        return std::nullopt;
      return offset_raw(f.x, f.y, pattern.at(*f.sample));
    case kp::Location::kCentroid: {
      // The fragment's own centroid: coverage_problem compares it with rastrules::render's,
      // whose centroids the MSAA properties check against the oracle (with partial masks,
      // helper lanes and sample shading, where the pixel's coverage before the mask is not
      // in the fragment). Here, where the fragment determines it, against the oracle too.
      const std::string rule = s.conventions.centroid == CentroidRule::kD3D11 ? "d3d11" : "d3d10";
      const bool determined = !f.helper && s.msaa.shading == ShadingRate::kPixel &&
                              (s.msaa.sample_mask & full_mask(n)) == full_mask(n);
      if (!f.centroid)
        return std::nullopt;
      const om::Offset o{f.centroid->offset.x, f.centroid->offset.y};
      if (determined && !(om::centroid(rule, f.mask, 0xFFFFFFFFu, pattern).offset == o))
        return std::nullopt;
      return offset_raw(f.x, f.y, o);
    }
    }
    return std::nullopt;
  };
  const bool want_bary = has_depth || !s.attributes.empty();
  if (want_bary != d->bary.has_value())
    return at + ": barycentrics " + (d->bary ? "present" : "absent");
  if (d->bary) {
    const auto loc =
        location_raw(s.attributes.empty() ? kp::Location::kCenter : s.attributes[0].location);
    if (loc && to_oracle(*d->bary) != bary_at(*loc))
      return at + ": barycentrics differ from the exact ones at " + raw_text(*loc) + " of " +
             vertices;
  }
  if (d->attr.size() != s.attributes.size())
    return at + ": " + std::to_string(d->attr.size()) + " attributes";
  for (std::size_t k = 0; k < s.attributes.size(); ++k) {
    const kp::AttributeDecl& a = s.attributes[k];
    const float got = d->attr[k];
    if (a.interpolation == kp::Interpolation::kFlat) {
      if (!same_bits(got, flat[k]))
        return at + ": flat attribute " + std::to_string(k) + " " + float_text(got) + ", want " +
               float_text(flat[k]);
      continue;
    }
    const auto loc = location_raw(a.location);
    if (!loc)
      return at + ": attribute " + std::to_string(k) +
             " at a sample or centroid the fragment lacks, or a centroid " +
             "other than the oracle's";
    const op::Bary b = bary_at(*loc);
    const std::array<float, 3> av = vertex_values(k);
    if (b.area == 0) {
      // A zero-length line (PIPE.BARY.LINE): vertex 0's value, or the flat one in perspective.
      const float want = a.interpolation == kp::Interpolation::kPerspective ? flat[k] : av[0];
      if (!same_bits(got, want))
        return at + ": attribute " + std::to_string(k) + " of a zero-length line " +
               float_text(got) + ", want " + float_text(want);
      continue;
    }
    const op::InterpCheck c = a.interpolation == kp::Interpolation::kPerspective
                                  ? op::check_perspective(b, av, vertex_w, flat[k], got)
                                  : op::check_linear(b, av, got);
    ++st.attr_checks;
    st.horizon = st.horizon || c.horizon;
    st.saturated = st.saturated || c.saturated;
    if (!c.ok)
      return at + ": attribute " + std::to_string(k) + " (" +
             std::string(to_string(a.interpolation)) + ") at " + raw_text(*loc) + ", vertices " +
             vertices + ", values " + float_text(av) + ", w " + float_text(vertex_w) + ": " +
             c.describe();
  }
  return "";
}

// The final depth buffer equals the replayed one.
std::string check_depth_buffer(const Replay& R) {
  const kp::PipeResult& r = R.r;
  const bool has_depth = R.has_depth;
  const std::vector<op::Stored>& buffer = R.buffer;
  if (has_depth) {
    if (r.depth_buffer.size() != buffer.size())
      return "depth buffer of " + std::to_string(r.depth_buffer.size()) + " samples";
    for (std::size_t i = 0; i < buffer.size(); ++i) {
      if (!(to_oracle(r.depth_buffer[i]) == buffer[i]))
        return "depth buffer sample " + std::to_string(i) + ": kernel (" +
               std::to_string(r.depth_buffer[i].unorm) + ", " + float_text(r.depth_buffer[i].f) +
               "), replay (" + std::to_string(buffer[i].unorm) + ", " + float_text(buffer[i].f) +
               ")";
    }
  } else if (!r.depth_buffer.empty()) {
    return "a depth buffer without depth";
  }
  return "";
}

// Returns "" when r is consistent with the oracle, else a description of the first problem.
// Checks every primitive: triangles against their parts, points, lines and each segment of a
// strip against their own segment (PIPE.BARY.LINE).
std::string replay(const rastrules::Scene& s, const kp::PipeResult& r, PipelineStats& st) {
  Replay R{s, r, st};
  R.vp = viewport_of(s);
  R.sc = op::viewport_scissor(R.vp);
  R.n = s.msaa.count();
  R.pattern = pattern_of(s);
  R.has_depth = s.depth.has_value();
  const bool need_data = R.has_depth || !s.attributes.empty() ||
                         std::any_of(s.primitives.begin(), s.primitives.end(),
                                     [](const rastrules::Primitive& p) { return !p.pos.empty(); });
  if (need_data ? r.data.size() != r.fragments.size() : !r.data.empty()) {
    return "data has " + std::to_string(r.data.size()) + " entries for " +
           std::to_string(r.fragments.size()) + " fragments";
  }
  R.fmt = R.has_depth ? format_name(s.conventions.depth) : "";
  R.func = R.has_depth ? compare_name(s.depth->func) : "";
  R.W = s.width;
  R.H = s.height;
  if (R.has_depth) {
    const op::Stored clear =
        op::store_exact(static_cast<double>(s.depth->clear), 0.0f, 1.0f, R.fmt);
    R.buffer.assign(static_cast<std::size_t>(R.W * R.H * R.n), clear);
  }
  for (std::size_t i = 0; i < s.primitives.size(); ++i) {
    R.geo.push_back(geometry(s, i));
    if (!R.geo.back().problem.empty())
      return R.geo.back().problem;
    if (R.geo.back().clipped)
      ++st.clipped_prims;
  }
  std::tuple<std::uint32_t, std::int64_t, std::int32_t, std::int32_t, std::int64_t, std::int64_t>
      last{0, -1, -1, -1, -1, -1};
  for (std::size_t i = 0; i < r.fragments.size(); ++i) {
    const Fragment& f = r.fragments[i];
    const kp::FragmentData* d = need_data ? &r.data[i] : nullptr;
    const std::string at = "fragment " + std::to_string(i) + " (prim " + std::to_string(f.prim) +
                           ", part " + (d && d->part ? std::to_string(*d->part) : "-") + ", x " +
                           std::to_string(f.x) + ", y " + std::to_string(f.y) + ", mask " +
                           std::to_string(f.mask) + ")";
    ++st.fragments;
    // Order (prim, part, y, x, seg, sample) and position.
    const std::tuple<std::uint32_t, std::int64_t, std::int32_t, std::int32_t, std::int64_t,
                     std::int64_t>
        key{f.prim,
            d && d->part ? std::int64_t{*d->part} : -1,
            f.y,
            f.x,
            f.seg ? std::int64_t{*f.seg} : -1,
            f.sample ? std::int64_t{*f.sample} : -1};
    if (i > 0 && !(last < key))
      return at + ": out of order";
    last = key;
    if (f.x < 0 || f.y < 0 || f.x >= R.W || f.y >= R.H)
      return at + ": outside the target";
    if (f.x < R.sc.x0 || f.x >= R.sc.x1 || f.y < R.sc.y0 || f.y >= R.sc.y1)
      return at + ": outside the viewport scissor";
    FragmentReplay x{f, d, at};
    if (std::string problem = x.locate(R); !problem.empty())
      return problem;
    if (std::string problem = x.check_drawn(R); !problem.empty())
      return problem;
    if (std::string problem = x.replay_depth(R); !problem.empty())
      return problem;
    if ((!x.part && !x.seg) || x.killed || d == nullptr)
      continue;
    if (std::string problem = x.check_values(R); !problem.empty())
      return problem;
  }
  return check_depth_buffer(R);
}

// The coverage of each part equals the window-space path (rastrules::render of that part with
// the scene's raster and multisample state), cut to the viewport scissor.
class CoverageReplay {
public:
  CoverageReplay(const rastrules::Scene& s, const kp::PipeResult& r)
      : s_(s), sc_(op::viewport_scissor(viewport_of(s))),
        any_centroid_(
            std::any_of(s.attributes.begin(), s.attributes.end(), [](const kp::AttributeDecl& a) {
              return a.location == kp::Location::kCentroid;
            })) {
    const bool has_data = !r.data.empty();
    for (std::size_t i = 0; i < r.fragments.size(); ++i) {
      Fragment f = r.fragments[i];
      const std::int64_t part = has_data && r.data[i].part ? std::int64_t{*r.data[i].part} : -1;
      const std::uint32_t prim = f.prim;
      f.prim = 0;
      got_[{prim, part}].push_back(f);
    }
  }

  std::string run() {
    for (std::size_t p = 0; p < s_.primitives.size(); ++p) {
      const rastrules::Primitive& pp = s_.primitives[p];
      const PrimGeometry g = geometry(s_, p);
      if (g.transform_error)
        continue;
      const bool point_or_line =
          pp.type == PrimitiveType::kPoint || pp.type == PrimitiveType::kLine;
      std::string problem;
      if (point_or_line && !pp.pos.empty())
        problem = clip_space_point_or_line(p, g);
      else if (pp.type == PrimitiveType::kLineStrip)
        problem = strip(p, g);
      else if (pp.type == PrimitiveType::kTriangle)
        problem = triangle(p, g);
      if (!problem.empty())
        return problem;
    }
    for (const auto& [key, frags] : got_) {
      if (s_.primitives[key.first].type == PrimitiveType::kTriangle && !frags.empty())
        return "primitive " + std::to_string(key.first) + " part " + std::to_string(key.second) +
               ": fragments of a part the oracle does not have";
    }
    return "";
  }

private:
  // The window-space render of one primitive with the scene's target and sample state, cut to
  // the scissor, or render's error.
  std::variant<std::vector<Fragment>, std::string> render_one(const Primitive& prim) const {
    Scene ws = rastrules::target_of(s_);
    if (any_centroid_)
      ws.msaa.has_centroid = true;
    ws.primitives = {prim};
    const auto rendered = render(ws);
    if (const auto* e = std::get_if<SceneError>(&rendered))
      return e->what();
    std::vector<Fragment> want;
    for (const Fragment& f : std::get<std::vector<Fragment>>(rendered)) {
      if (f.x >= sc_.x0 && f.x < sc_.x1 && f.y >= sc_.y0 && f.y < sc_.y1)
        want.push_back(f);
    }
    return want;
  }

  // Takes the pipeline's fragments of primitive p, part key (none: empty).
  std::vector<Fragment> take(std::size_t p, std::int64_t key) {
    const auto it = got_.find({static_cast<std::uint32_t>(p), key});
    if (it == got_.end())
      return {};
    std::vector<Fragment> have = std::move(it->second);
    got_.erase(it);
    return have;
  }

  // A clip-space point or line: all its fragments (whatever their part) against the coverage
  // kernel's for its clipped window-space vertices.
  std::string clip_space_point_or_line(std::size_t p, const PrimGeometry& g) {
    const rastrules::Primitive& pp = s_.primitives[p];
    std::vector<Fragment> have;
    for (auto it = got_.begin(); it != got_.end();) {
      if (it->first.first == p) {
        have.insert(have.end(), it->second.begin(), it->second.end());
        it = got_.erase(it);
      } else {
        ++it;
      }
    }
    std::vector<Fragment> want;
    if (!g.other.empty()) {
      Primitive prim = rastrules::coverage_of(pp);
      prim.v.clear();
      for (const op::WindowVertex& v : g.other)
        prim.v.push_back(FloatPoint{v.x, v.y});
      auto rendered = render_one(prim);
      if (const auto* e = std::get_if<std::string>(&rendered))
        return "render of primitive " + std::to_string(p) + ": " + *e;
      want = std::get<std::vector<Fragment>>(rendered);
    }
    if (have != want)
      return "coverage of " + std::string(to_string(pp.type)) + " " + std::to_string(p) +
             ": pipeline " + std::to_string(have.size()) + " fragments, window-space render " +
             std::to_string(want.size());
    return "";
  }

  // rule: PIPE.CLIP.LINE, LINE.STRIP.SEQUENCE
  // A strip inside the volume (or in window space) covers what the coverage kernel draws for
  // the strip of its window vertices; a clipped one, segment by segment, what it draws for
  // each cut segment as a line (part = segment).
  std::string strip(std::size_t p, const PrimGeometry& g) {
    const rastrules::Primitive& pp = s_.primitives[p];
    std::vector<std::pair<std::int64_t, Primitive>> units;
    Primitive whole = rastrules::coverage_of(pp);
    whole.v.clear();
    for (std::size_t k = 0; k < g.segs.size(); ++k) {
      if (!g.segs[k])
        continue;
      const Seg& sg = *g.segs[k];
      if (g.clipped) {
        Primitive line = rastrules::coverage_of(pp);
        line.type = PrimitiveType::kLine;
        line.v = {FloatPoint{sg.wv[0].x, sg.wv[0].y}, FloatPoint{sg.wv[1].x, sg.wv[1].y}};
        units.emplace_back(static_cast<std::int64_t>(k), line);
      } else {
        if (k == 0)
          whole.v.push_back(FloatPoint{sg.wv[0].x, sg.wv[0].y});
        whole.v.push_back(FloatPoint{sg.wv[1].x, sg.wv[1].y});
      }
    }
    if (!g.clipped)
      units.emplace_back(-1, whole);
    for (const auto& [key, prim] : units) {
      auto rendered = render_one(prim);
      if (const auto* e = std::get_if<std::string>(&rendered))
        return "render of strip " + std::to_string(p) + " part " + std::to_string(key) + ": " + *e;
      const std::vector<Fragment> have = take(p, key);
      if (have != std::get<std::vector<Fragment>>(rendered))
        return "coverage of strip " + std::to_string(p) + " part " + std::to_string(key) +
               ": pipeline " + std::to_string(have.size()) + " fragments, window-space render " +
               std::to_string(std::get<std::vector<Fragment>>(rendered).size());
    }
    for (const auto& [key, frags] : got_)
      if (key.first == p && !frags.empty())
        return "strip " + std::to_string(p) + " part " + std::to_string(key.second) +
               ": fragments of a segment the oracle's clipper discards";
    return "";
  }

  // A triangle: each part of the oracle's fan against the render of that part.
  std::string triangle(std::size_t p, const PrimGeometry& g) {
    for (std::size_t k = 0; k < g.parts.size(); ++k) {
      const Part& part = g.parts[k];
      auto rendered = render_one(make_triangle({FloatPoint{part.wv[0].x, part.wv[0].y},
                                                FloatPoint{part.wv[1].x, part.wv[1].y},
                                                FloatPoint{part.wv[2].x, part.wv[2].y}}));
      if (const auto* e = std::get_if<std::string>(&rendered))
        return "render of primitive " + std::to_string(p) + " part " + std::to_string(k) + ": " +
               *e;
      const std::vector<Fragment>& want = std::get<std::vector<Fragment>>(rendered);
      const std::int64_t key = g.clipped ? static_cast<std::int64_t>(k) : -1;
      const std::vector<Fragment> have = take(p, key);
      if (have != want)
        return "coverage of primitive " + std::to_string(p) + " part " + std::to_string(key) +
               ": pipeline " + std::to_string(have.size()) + " fragments, window-space render " +
               std::to_string(want.size()) + " (vertices " + raw_text(part.raw) + ")" +
               first_difference(have, want);
    }
    return "";
  }

  // "; first difference at I: pipeline (x, y, mask m), render (x, y, mask m)", or "".
  static std::string first_difference(const std::vector<Fragment>& have,
                                      const std::vector<Fragment>& want) {
    const auto text = [](const std::vector<Fragment>& l, std::size_t i) {
      return i < l.size() ? "(" + std::to_string(l[i].x) + ", " + std::to_string(l[i].y) +
                                ", mask " + std::to_string(l[i].mask) + ")"
                          : std::string();
    };
    for (std::size_t i = 0; i < std::max(have.size(), want.size()); ++i) {
      if (i < have.size() && i < want.size() && have[i] == want[i])
        continue;
      return "; first difference at " + std::to_string(i) + ": pipeline " + text(have, i) +
             ", render " + text(want, i);
    }
    return "";
  }

  const rastrules::Scene& s_;
  op::Rect sc_;
  bool any_centroid_;
  std::map<std::pair<std::uint32_t, std::int64_t>, std::vector<Fragment>> got_;
};

std::string coverage_problem(const rastrules::Scene& s, const kp::PipeResult& r) {
  return CoverageReplay(s, r).run();
}
} // namespace

Mismatches check_pipeline(const Scene& scene, const pipe::PipeResult& result,
                          const CheckOptions& options, PipelineStats* stats) {
  Checker out(options);
  PipelineStats st;
  out.used("oracle::pipe");
  st.values_checked = check_values(scene, result, out);
  std::string problem = replay(scene, result, st);
  if (problem.empty())
    problem = coverage_problem(scene, result);
  if (!problem.empty())
    out.note(problem);
  if (stats != nullptr)
    *stats = st;
  return out.take();
}

bool transform_overflows(const Scene& scene, std::size_t prim) {
  return geometry(scene, prim).transform_error;
}

} // namespace rastrules::check

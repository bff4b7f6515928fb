// SPDX-License-Identifier: MIT
// Helpers for the example tests (see support.hpp).

#include "support.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <utility>
#include <variant>

#include "rastrules/decision.hpp"
#include "rastrules/raster/walk.hpp"
#include "rastrules/snap.hpp"

namespace rastrules::test {

std::ostream& operator<<(std::ostream& os, const Pixel& p) {
  return os << "(" << p.x << ", " << p.y << ")";
}

Subpixel snap_px(double v) {
  const auto f = static_cast<float>(v);
  if (static_cast<double>(f) != v) {
    throw std::invalid_argument("snap_px: " + std::to_string(v) + " is not a float32");
  }
  const SnapResult r = snap_to_subpixel(f);
  if (r.status != SnapStatus::kOk) {
    throw std::invalid_argument("snap_px: " + std::to_string(v) + " " +
                                std::string(to_string(r.status)));
  }
  return r.value;
}

namespace {

Subpixel exact_subpixel(double v) {
  const double scaled = v * kSubpixelOne;
  if (scaled != std::floor(scaled) || scaled < kMinVertexRaw || scaled > kMaxVertexRaw) {
    throw std::invalid_argument("sample_px: " + std::to_string(v) + " is not on the 16.8 grid");
  }
  return Subpixel::from_raw(static_cast<std::int32_t>(scaled));
}

} // namespace

Vec2 sample_px(double x, double y) {
  return Vec2{exact_subpixel(x), exact_subpixel(y)};
}

TriangleSetup triangle_px(Px a, Px b, Px c, const RasterState& state) {
  const std::array<Vec2, 3> v{Vec2{snap_px(a.x), snap_px(a.y)}, Vec2{snap_px(b.x), snap_px(b.y)},
                              Vec2{snap_px(c.x), snap_px(c.y)}};
  return setup_triangle(v, state);
}

std::vector<Pixel> walk_pixels(const TriangleSetup& t, std::int32_t width, std::int32_t height) {
  std::vector<Pixel> out;
  raster::walk_triangle(t, width, height, [&](std::int32_t x, std::int32_t y) {
    out.push_back(Pixel{x, y});
  });
  return out;
}

std::vector<Pixel> centre_pixels(const TriangleSetup& t, std::int32_t width, std::int32_t height) {
  std::vector<Pixel> out;
  for (std::int32_t y = 0; y < height; ++y) {
    for (std::int32_t x = 0; x < width; ++x) {
      if (covers(t, pixel_center(x, y)))
        out.push_back(Pixel{x, y});
    }
  }
  return out;
}

std::vector<Pixel> pixels_in_picture(std::initializer_list<std::string_view> rows, char mark) {
  std::vector<Pixel> out;
  std::int32_t y = 0;
  for (const std::string_view row : rows) {
    for (std::size_t x = 0; x < row.size(); ++x) {
      if (row[x] == mark)
        out.push_back(Pixel{static_cast<std::int32_t>(x), y});
    }
    ++y;
  }
  return out;
}

std::string picture(const std::vector<Pixel>& pixels, std::int32_t width, std::int32_t height) {
  std::string s;
  for (std::int32_t y = 0; y < height; ++y) {
    s += '\n';
    for (std::int32_t x = 0; x < width; ++x) {
      s += std::find(pixels.begin(), pixels.end(), Pixel{x, y}) != pixels.end() ? '#' : '.';
    }
  }
  return s;
}

Primitive prim_px(PrimitiveType t, std::vector<FloatPoint> v) {
  Primitive p;
  p.type = t;
  p.v = std::move(v);
  return p;
}

Scene scene_px(std::int32_t width, std::int32_t height, const RasterState& state,
               std::initializer_list<std::array<Px, 3>> triangles) {
  Scene s;
  s.width = width;
  s.height = height;
  set_raster_state(s, state);
  for (const auto& t : triangles) {
    Primitive p;
    for (std::size_t i = 0; i < 3; ++i) {
      p.v[i] = {static_cast<float>(t[i].x), static_cast<float>(t[i].y)};
    }
    s.primitives.push_back(p);
  }
  return s;
}

std::vector<Pixel> pixels_of(const std::vector<Fragment>& fragments, std::uint32_t prim) {
  std::vector<Pixel> out;
  for (const Fragment& f : fragments) {
    if (f.prim == prim)
      out.push_back(Pixel{f.x, f.y});
  }
  return out;
}

std::vector<Primitive> tie_heavy_primitives(PrimitiveType t, std::size_t n, std::uint32_t seed,
                                            std::int32_t width, std::int32_t height, int steps) {
  std::uint32_t state = seed;
  auto coordinate = [&](std::int32_t side) {
    state = state * 1664525u + 1013904223u; // a linear congruential generator
    const auto cells = static_cast<std::uint32_t>((side + 2) * steps);
    return static_cast<float>(static_cast<std::int32_t>((state >> 8) % cells) - steps) /
           static_cast<float>(steps);
  };
  const std::size_t count = t == PrimitiveType::kLineStrip ? 3 : required_vertex_count(t);
  std::vector<Primitive> out(n);
  for (Primitive& p : out) {
    p.type = t;
    p.v.resize(count);
    for (FloatPoint& v : p.v)
      v = {coordinate(width), coordinate(height)};
  }
  return out;
}

PreparedScene prepared(const Scene& scene) {
  auto r = prepare(scene);
  if (const auto* e = std::get_if<SceneError>(&r))
    throw std::invalid_argument("prepared: the scene is rejected: " + e->what());
  return std::get<PreparedScene>(std::move(r));
}

namespace {

// The fragments of one primitive at one pixel, by segment (0 unless a line strip).
struct PixelFragments {
  bool any = false;                            // a fragment that is not a helper
  std::map<std::uint32_t, std::uint32_t> mask; // OR of the masks of its fragments
  std::map<std::uint32_t, std::optional<Centroid>> centroid;
  std::map<std::uint32_t, std::optional<std::uint32_t>> coverage_q16;
  std::map<std::uint32_t, std::uint32_t> helpers; // bit k: a helper of sample k (0: pixel)
};
using FragmentsAt = std::map<std::pair<std::int32_t, std::int32_t>, PixelFragments>;

FragmentsAt fragments_at(const PreparedScene& scene, std::size_t p) {
  FragmentsAt out;
  for (const Fragment& f : rasterize_primitive(scene, p)) {
    PixelFragments& pf = out[{f.x, f.y}];
    const std::uint32_t seg = f.seg.value_or(0);
    if (f.helper) {
      pf.helpers[seg] |= std::uint32_t{1} << f.sample.value_or(0);
      continue;
    }
    pf.any = true;
    pf.mask[seg] |= f.mask;
    pf.centroid[seg] = f.centroid;
    pf.coverage_q16[seg] = f.coverage_q16;
  }
  return out;
}

std::uint32_t value_or_zero(const std::map<std::uint32_t, std::uint32_t>& m, std::uint32_t k) {
  const auto it = m.find(k);
  return it == m.end() ? 0u : it->second;
}

// The single-sample path: the triangles' records at the centre and the line segments' records.
// rule: TRI.COVER.SAMPLE, LINE.D3D.EXIT, LINE.VK.EXIT, LINE.AA.FRAGMENT
std::string centre_disagreement(const PixelDecision& d, const PixelFragments& pf) {
  const Vec2 c = pixel_center(d.x, d.y);
  for (std::size_t i = 0; i < d.triangles.size(); ++i) {
    const TriangleDecision& t = d.triangles[i];
    if (t.covered != covers(t.setup, c))
      return "triangle " + std::to_string(i) + ": the record and covers() differ";
    if (t.covered && t.rule != rules::kTriCoverSample) {
      return "triangle " + std::to_string(i) + ": covered, decided by " + std::string(t.rule.id);
    }
  }
  for (const LineSegmentDecision& g : d.segments) {
    const bool has = pf.mask.count(g.seg) != 0;
    if (g.covered != has) {
      return "segment " + std::to_string(g.seg) + ": the record says " +
             (g.covered ? "covered" : "not covered") + ", the fragments " +
             (has ? "have one" : "have none");
    }
    const std::optional<std::uint32_t>& got =
        has ? pf.coverage_q16.at(g.seg) : std::optional<std::uint32_t>{};
    const bool aa = g.rule == rules::kLineAAFragment;
    if (has && (got.has_value() != aa || (aa && got.value_or(0) != g.coverage_q16)))
      return "segment " + std::to_string(g.seg) + ": the coverage differs";
  }
  return "";
}

// The multisampled path: each segment's mask, centroid, helper lanes and sample records.
// rule: MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
// rule: MSAA.QUAD.HELPER
std::string msaa_disagreement(const PreparedScene& scene, const PixelDecision& d,
                              const PixelFragments& pf) {
  const MultisampleState& ms = scene.msaa;
  for (const SegmentMaskDecision& g : d.msaa->segments) {
    const std::string seg = "segment " + std::to_string(g.seg) + ": ";
    if (g.coverage != g.explained)
      return seg + "the per-sample records do not explain the coverage";
    if (g.mask != value_or_zero(pf.mask, g.seg)) {
      return seg + "record mask " + std::to_string(g.mask) + ", fragment mask " +
             std::to_string(value_or_zero(pf.mask, g.seg));
    }
    if (g.mask != 0 && ms.has_centroid && pf.centroid.at(g.seg) != g.centroid)
      return seg + "the centroid differs";
    const std::uint32_t helpers = value_or_zero(pf.helpers, g.seg);
    const bool per_sample = ms.shading == ShadingRate::kSample;
    if (per_sample ? g.helper_samples != helpers : g.helper != (helpers != 0))
      return seg + "the helper lanes differ";
  }
  for (const auto* m : {&pf.mask, &pf.helpers}) {
    for (const auto& [seg, bits] : *m) {
      const bool recorded =
          std::any_of(d.msaa->segments.begin(), d.msaa->segments.end(),
                      [s = seg](const SegmentMaskDecision& g) { return g.seg == s; });
      if (!recorded)
        return "segment " + std::to_string(seg) + ": fragments but no record";
    }
  }
  return "";
}

} // namespace

// rule: TRI.COVER.SAMPLE, MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.QUAD.HELPER
std::string decision_disagreement(const PreparedScene& scene) {
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    const FragmentsAt frags = fragments_at(scene, p);
    for (std::int32_t y = 0; y < scene.height; ++y) {
      for (std::int32_t x = 0; x < scene.width; ++x) {
        const PixelDecision d = decide_pixel(scene, p, x, y);
        const auto it = frags.find({x, y});
        const PixelFragments pf = it == frags.end() ? PixelFragments{} : it->second;
        std::string why;
        if (d.prim != p || d.x != x || d.y != y) {
          why = "the record names another primitive or pixel";
        } else if (d.covered != pf.any) {
          why = std::string("the record says ") + (d.covered ? "covered" : "not covered") +
                ", rasterize_primitive " + (pf.any ? "has a fragment" : "has none");
        } else {
          why = d.msaa ? msaa_disagreement(scene, d, pf) : centre_disagreement(d, pf);
        }
        if (!why.empty()) {
          return "primitive " + std::to_string(p) + " at pixel (" + std::to_string(x) + ", " +
                 std::to_string(y) + "): " + why;
        }
      }
    }
  }
  return "";
}

} // namespace rastrules::test

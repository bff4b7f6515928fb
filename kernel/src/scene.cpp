// SPDX-License-Identifier: MIT
// Scene validation, snapping and rasterization entry points.
// Implements: SCENE.TARGET.LIMITS, SNAP.VERTEX.INVALID, SCENE.OUTPUT.FRAGMENTS,
//             SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP, SCENE.LINE_MODE,
//             SCENE.OUTPUT.COVERAGE

#include "rastrules/scene.hpp"

#include <algorithm>
#include <string>
#include <tuple>

#include "rastrules/point.hpp"
#include "rastrules/raster/walk.hpp"

namespace rastrules {

std::string_view to_string(FillConvention f) {
  switch (f) {
    case FillConvention::kTopLeft: return "top-left";
    case FillConvention::kTopRight: return "top-right";
    case FillConvention::kBottomLeft: return "bottom-left";
    case FillConvention::kBottomRight: return "bottom-right";
  }
  return "unknown";
}

std::string_view to_string(CullMode c) {
  switch (c) {
    case CullMode::kNone: return "none";
    case CullMode::kBack: return "back";
    case CullMode::kFront: return "front";
  }
  return "unknown";
}

std::string_view to_string(FrontFace f) {
  switch (f) {
    case FrontFace::kClockwise: return "cw";
    case FrontFace::kCounterClockwise: return "ccw";
  }
  return "unknown";
}

std::string_view to_string(TriangleStatus s) {
  switch (s) {
    case TriangleStatus::kRasterized: return "rasterized";
    case TriangleStatus::kDegenerate: return "degenerate (zero area after snapping)";
    case TriangleStatus::kCulledBack: return "culled (back-facing)";
    case TriangleStatus::kCulledFront: return "culled (front-facing)";
  }
  return "unknown";
}

std::string_view to_string(PrimitiveType t) {
  switch (t) {
  case PrimitiveType::kTriangle:
    return "triangle";
  case PrimitiveType::kPoint:
    return "point";
  case PrimitiveType::kLine:
    return "line";
  case PrimitiveType::kLineStrip:
    return "line_strip";
  }
  return "unknown";
}

Primitive make_triangle(const std::array<FloatPoint, 3>& v) {
  Primitive p;
  p.type = PrimitiveType::kTriangle;
  p.v.assign(v.begin(), v.end());
  return p;
}

std::size_t required_vertex_count(PrimitiveType t) {
  switch (t) {
  case PrimitiveType::kTriangle:
    return 3;
  case PrimitiveType::kPoint:
    return 1;
  case PrimitiveType::kLine:
    return 2;
  case PrimitiveType::kLineStrip:
    return 0;
  }
  return 0;
}

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.PRIM.LINE_STRIP
bool fragment_before(const Fragment& a, const Fragment& b) {
  // A missing seg (-1) sorts before every segment index.
  const std::int64_t sa = a.seg ? std::int64_t{*a.seg} : -1;
  const std::int64_t sb = b.seg ? std::int64_t{*b.seg} : -1;
  return std::tie(a.prim, a.y, a.x, sa) < std::tie(b.prim, b.y, b.x, sb);
}

namespace {

bool is_line(PrimitiveType t) {
  return t == PrimitiveType::kLine || t == PrimitiveType::kLineStrip;
}

bool is_quad(LineMode m) {
  return m == LineMode::kQuadWide || m == LineMode::kQuadNarrow;
}

std::string field_of(std::size_t p) {
  return "primitives[" + std::to_string(p) + "]";
}

} // namespace

// rule: SCENE.TARGET.LIMITS, SNAP.VERTEX.INVALID, SCENE.PRIM.POINT
// rule: SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP, SCENE.LINE_MODE
std::variant<PreparedScene, SceneError> prepare(const Scene& scene) {
  // rule: SCENE.TARGET.LIMITS
  if (scene.width < 1 || scene.width > kMaxTargetSide) {
    return SceneError{"target.width", "must be an integer in [1, " +
                                          std::to_string(kMaxTargetSide) + "], got " +
                                          std::to_string(scene.width)};
  }
  if (scene.height < 1 || scene.height > kMaxTargetSide) {
    return SceneError{"target.height", "must be an integer in [1, " +
                                           std::to_string(kMaxTargetSide) + "], got " +
                                           std::to_string(scene.height)};
  }
  PreparedScene out;
  out.width = scene.width;
  out.height = scene.height;
  out.state = scene.state;
  out.line_mode = scene.line_mode;
  out.primitives.reserve(scene.primitives.size());
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    const Primitive& in = scene.primitives[p];
    const std::size_t n = in.v.size();
    const std::size_t need = required_vertex_count(in.type);
    // rule: SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP
    if ((need != 0 && n != need) || (need == 0 && n < 2)) {
      const std::string count = need == 0   ? "at least 2 vertices"
                                : need == 1 ? "exactly 1 vertex"
                                            : "exactly " + std::to_string(need) + " vertices";
      return SceneError{field_of(p) + ".v", "a " + std::string(to_string(in.type)) + " must have " +
                                                count + " [x, y], got " + std::to_string(n)};
    }
    // rule: SCENE.PRIM.LINE, SCENE.LINE_MODE
    if (in.aa && !is_line(in.type)) {
      return SceneError{field_of(p) + ".aa",
                        "only lines and line strips can be antialiased, not a " +
                            std::string(to_string(in.type))};
    }
    if (in.aa && scene.line_mode != LineMode::kD3DDiamond) {
      return SceneError{field_of(p) + ".aa",
                        "antialiased lines need line_mode \"d3d\" (the D3D reference algorithm)"};
    }
    PreparedPrimitive prim;
    prim.type = in.type;
    prim.aa = in.aa;
    prim.v.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      Subpixel c[2];
      for (std::size_t k = 0; k < 2; ++k) {
        const std::string field =
            field_of(p) + ".v[" + std::to_string(i) + "][" + std::to_string(k) + "]";
        // rule: SNAP.VERTEX.INVALID
        const SnapResult s = snap_to_subpixel(in.v[i][k]);
        if (s.status != SnapStatus::kOk) {
          return SceneError{field, std::string("is ") + std::string(to_string(s.status))};
        }
        // rule: SCENE.PRIM.POINT
        if (in.type == PrimitiveType::kPoint &&
            (s.value.raw() < kMinPointRaw || s.value.raw() > kMaxPointRaw)) {
          return SceneError{field, "is outside the point range [" + std::to_string(kMinPointRaw) +
                                       ", " + std::to_string(kMaxPointRaw) +
                                       "] / 256 (the point's square must fit in the vertex range)"};
        }
        c[k] = s.value;
      }
      prim.v.push_back(Vec2{c[0], c[1]});
    }
    switch (in.type) {
    case PrimitiveType::kTriangle:
      prim.triangles.push_back(
          PreparedTriangle{setup_triangle({prim.v[0], prim.v[1], prim.v[2]}, scene.state), 0});
      break;
    case PrimitiveType::kPoint:
      // rule: SCENE.PRIM.POINT
      for (const TriangleSetup& t : setup_point(prim.v[0], scene.state)) {
        prim.triangles.push_back(PreparedTriangle{t, 0});
      }
      break;
    case PrimitiveType::kLine:
    case PrimitiveType::kLineStrip:
      // rule: SCENE.LINE_MODE
      if (!in.aa && is_quad(scene.line_mode)) {
        RasterState no_cull = scene.state;
        no_cull.cull = CullMode::kNone;
        for (std::size_t s = 0; s + 1 < prim.v.size(); ++s) {
          for (const auto& tri : quad_line_triangles(prim.v[s], prim.v[s + 1], scene.line_mode)) {
            prim.triangles.push_back(
                PreparedTriangle{setup_triangle(tri, no_cull), static_cast<std::uint32_t>(s)});
          }
        }
      }
      break;
    }
    out.primitives.push_back(std::move(prim));
  }
  return out;
}

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.COVERAGE, SCENE.PRIM.LINE_STRIP
std::vector<Fragment> rasterize_primitive(const PreparedScene& scene, std::size_t p) {
  const PreparedPrimitive& prim = scene.primitives[p];
  const auto id = static_cast<std::uint32_t>(p);
  const bool strip = prim.type == PrimitiveType::kLineStrip;
  std::vector<Fragment> out;
  auto seg_of = [&](std::uint32_t s) {
    return strip ? std::optional<std::uint32_t>(s) : std::nullopt;
  };
  if (!prim.triangles.empty() || !is_line(prim.type)) {
    // Triangles, points (two triangles that never overlap) and quadrilateral lines.
    for (const PreparedTriangle& t : prim.triangles) {
      raster::walk_triangle(t.setup, scene.width, scene.height,
                            [&](std::int32_t x, std::int32_t y) {
                              out.push_back(Fragment{id, x, y, 1u, seg_of(t.seg), std::nullopt});
                            });
    }
  } else {
    for (std::size_t s = 0; s + 1 < prim.v.size(); ++s) {
      const auto seg = static_cast<std::uint32_t>(s);
      if (prim.aa) {
        // rule: SCENE.OUTPUT.COVERAGE
        rasterize_aa_line(prim.v[s], prim.v[s + 1], scene.width, scene.height,
                          [&](std::int32_t x, std::int32_t y, std::uint32_t c) {
                            out.push_back(Fragment{id, x, y, 1u, seg_of(seg), c});
                          });
      } else {
        rasterize_aliased_line(prim.v[s], prim.v[s + 1], scene.line_mode, scene.width, scene.height,
                               [&](std::int32_t x, std::int32_t y) {
                                 out.push_back(Fragment{id, x, y, 1u, seg_of(seg), std::nullopt});
                               });
      }
    }
  }
  // The triangle walk emits (y, x) per triangle; a point's two triangles, quadrilateral line
  // halves, strip segments and aliased lines (travel order) need a sort.
  if (prim.triangles.size() > 1 || prim.type != PrimitiveType::kTriangle) {
    std::stable_sort(out.begin(), out.end(), fragment_before);
  }
  return out;
}

// rule: SCENE.OUTPUT.FRAGMENTS
void for_each_fragment(const PreparedScene& scene, std::size_t p,
                       const std::function<void(const Fragment&)>& emit) {
  const PreparedPrimitive& prim = scene.primitives[p];
  if (prim.type == PrimitiveType::kTriangle) {
    const auto id = static_cast<std::uint32_t>(p);
    raster::walk_triangle(prim.triangles[0].setup, scene.width, scene.height,
                          [&](std::int32_t x, std::int32_t y) {
                            emit(Fragment{id, x, y, 1u});
                          });
    return;
  }
  for (const Fragment& f : rasterize_primitive(scene, p))
    emit(f);
}

// rule: SCENE.OUTPUT.FRAGMENTS
std::vector<Fragment> rasterize(const PreparedScene& scene) {
  std::vector<Fragment> out;
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    std::vector<Fragment> f = rasterize_primitive(scene, p);
    out.insert(out.end(), f.begin(), f.end());
  }
  return out; // primitives in order, each sorted by (y, x, seg)
}

std::variant<std::vector<Fragment>, SceneError> render(const Scene& scene) {
  auto prepared = prepare(scene);
  if (auto* err = std::get_if<SceneError>(&prepared)) return *err;
  return rasterize(std::get<PreparedScene>(prepared));
}

}  // namespace rastrules

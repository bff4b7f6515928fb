// SPDX-License-Identifier: MIT
// Scene validation, snapping and rasterization entry points.
// Implements: SCENE.TARGET.LIMITS, SNAP.VERTEX.INVALID, SCENE.OUTPUT.FRAGMENTS

#include "rastrules/scene.hpp"

#include <string>

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

// rule: SCENE.TARGET.LIMITS, SNAP.VERTEX.INVALID
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
  out.triangles.reserve(scene.primitives.size());
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    std::array<Vec2, 3> snapped{};
    for (std::size_t i = 0; i < 3; ++i) {
      Subpixel c[2];
      for (std::size_t k = 0; k < 2; ++k) {
        // rule: SNAP.VERTEX.INVALID
        const SnapResult s = snap_to_subpixel(scene.primitives[p].v[i][k]);
        if (s.status != SnapStatus::kOk) {
          return SceneError{"primitives[" + std::to_string(p) + "].v[" + std::to_string(i) +
                                "][" + std::to_string(k) + "]",
                            std::string("is ") + std::string(to_string(s.status))};
        }
        c[k] = s.value;
      }
      snapped[i] = Vec2{c[0], c[1]};
    }
    out.triangles.push_back(setup_triangle(snapped, scene.state));
  }
  return out;
}

// rule: SCENE.OUTPUT.FRAGMENTS
std::vector<Fragment> rasterize(const PreparedScene& scene) {
  std::vector<Fragment> out;
  for (std::size_t p = 0; p < scene.triangles.size(); ++p) {
    const auto prim = static_cast<std::uint32_t>(p);
    raster::walk_triangle(scene.triangles[p], scene.width, scene.height,
                          [&](std::int32_t x, std::int32_t y) {
                            out.push_back(Fragment{prim, x, y, 1u});
                          });
  }
  return out;  // walk order is (y, x) within a primitive, primitives in order
}

std::variant<std::vector<Fragment>, SceneError> render(const Scene& scene) {
  auto prepared = prepare(scene);
  if (auto* err = std::get_if<SceneError>(&prepared)) return *err;
  return rasterize(std::get<PreparedScene>(prepared));
}

}  // namespace rastrules

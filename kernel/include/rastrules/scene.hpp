// SPDX-License-Identifier: MIT
// The kernel's scene model and its single entry point: validate, snap, set up, traverse.
// Implements: SCENE.FORMAT.V1 (in memory), SCENE.OUTPUT.FRAGMENTS, SCENE.TARGET.LIMITS,
//             SNAP.VERTEX.INVALID
// The JSON reader and writer live in tools/; the kernel has no third-party dependency.

#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "rastrules/fixed.hpp"
#include "rastrules/snap.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules {

enum class PrimitiveType { kTriangle };

struct Primitive {
  PrimitiveType type = PrimitiveType::kTriangle;
  std::array<std::array<float, 2>, 3> v{};  // window coordinates in pixels, read as float32
};

struct Scene {
  std::int32_t width = 0;
  std::int32_t height = 0;
  RasterState state;
  std::vector<Primitive> primitives;
};

// One covered pixel of one primitive. mask has bit i set for covered sample i; without
// multisampling the only sample is the pixel centre, so mask == 1.
// rule: SCENE.OUTPUT.FRAGMENTS
struct Fragment {
  std::uint32_t prim = 0;
  std::int32_t x = 0;
  std::int32_t y = 0;
  std::uint32_t mask = 1;
  friend constexpr bool operator==(const Fragment&, const Fragment&) = default;
};

// A rejected scene: the JSON-pointer-like path of the offending field and what is wrong.
struct SceneError {
  std::string field;    // e.g. "primitives[3].v[1][0]"
  std::string message;  // e.g. "is NaN"
  [[nodiscard]] std::string what() const { return field + ": " + message; }
};

// The scene after validation and snapping.
struct PreparedScene {
  std::int32_t width = 0;
  std::int32_t height = 0;
  RasterState state;
  std::vector<TriangleSetup> triangles;
};

// Returns the prepared scene, or the first error in field order. Checks
// SCENE.TARGET.LIMITS and snaps every vertex (SNAP.VERTEX.INVALID rejects NaN, infinities and
// out-of-range coordinates).
// rule: SCENE.TARGET.LIMITS, SNAP.VERTEX.INVALID
[[nodiscard]] std::variant<PreparedScene, SceneError> prepare(const Scene& scene);

// Returns the fragments of a prepared scene sorted by (prim, y, x), only inside the target.
// rule: SCENE.OUTPUT.FRAGMENTS, RASTER.TARGET.CLIP
[[nodiscard]] std::vector<Fragment> rasterize(const PreparedScene& scene);

// prepare() then rasterize().
[[nodiscard]] std::variant<std::vector<Fragment>, SceneError> render(const Scene& scene);

}  // namespace rastrules

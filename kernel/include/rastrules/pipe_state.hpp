// SPDX-License-Identifier: MIT
// The pipeline state a scene may ask for (SCENE.PIPELINE): positions before the transform,
// matrices, viewport, depth and attribute declarations. Every part is optional in a Scene
// (rastrules/scene.hpp); the stages that use them are rastrules/pipeline.hpp's.
// Implements: SCENE.PIPELINE (the state, in memory)
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "rastrules/name_table.hpp"

namespace rastrules::pipe {

// rule: PIPE.INPUT.POSITION, PIPE.TRANSFORM.FLOAT32
using Vec4f = std::array<float, 4>;  // x, y, z, w
using Mat4f = std::array<float, 16>; // row-major, acting on column vectors

// The viewport (PIPE.VIEWPORT.TRANSFORM, PIPE.VIEWPORT.RANGE).
struct Viewport {
  float x = 0.0f, y = 0.0f, width = 0.0f, height = 0.0f;
  float min_depth = 0.0f, max_depth = 1.0f;
  friend bool operator==(const Viewport&, const Viewport&) = default;
};

// rule: PIPE.INTERP.PERSPECTIVE, PIPE.INTERP.LINEAR, PIPE.INTERP.FLAT, PIPE.INTERP.LOCATION
enum class Interpolation { kPerspective, kLinear, kFlat };
enum class Location { kCenter, kCentroid, kSample };

// rule: PIPE.DEPTH.FORMAT, PIPE.DEPTH.TEST
enum class DepthFormat { kD16, kD24, kD32F };
enum class CompareFunc {
  kNever,
  kLess,
  kEqual,
  kLessEqual,
  kGreater,
  kNotEqual,
  kGreaterEqual,
  kAlways
};

// The depth bias terms of PIPE.DEPTH.BIAS.
struct DepthBias {
  std::int32_t bias = 0;
  float slope_scaled = 0.0f;
  float clamp = 0.0f;
  // Whether the bias can move a depth: a constant or a slope term (the clamp alone cannot).
  // rule: PIPE.DEPTH.BIAS
  [[nodiscard]] constexpr bool enabled() const { return bias != 0 || slope_scaled != 0.0f; }
};

// One declared attribute (PIPE.INPUT.ATTRIBUTES).
struct AttributeDecl {
  std::string name;
  Interpolation interpolation = Interpolation::kPerspective;
  Location location = Location::kCenter;
};

// The depth buffer and test (PIPE.DEPTH.*). Its format is a convention (Conventions::depth).
struct DepthState {
  CompareFunc func = CompareFunc::kLess;
  bool write = true;
  float clear = 1.0f;
  bool clip = true; // depth clipping (D3D DepthClipEnable)
  DepthBias bias;
};

// Which vertex of each segment gives flat attributes (PIPE.INTERP.FLAT).
enum class Provoking { kFirst, kLast };

using rastrules::to_string; // the spellings below

} // namespace rastrules::pipe

// The words of the pipeline state (spec/scene.md).
namespace rastrules {
template <> struct Names<pipe::Interpolation> {
  static constexpr auto table =
      in_enum_order<pipe::Interpolation>({"perspective", "linear", "flat"});
};
template <> struct Names<pipe::Location> {
  static constexpr auto table = in_enum_order<pipe::Location>({"center", "centroid", "sample"});
};
template <> struct Names<pipe::DepthFormat> {
  static constexpr auto table = in_enum_order<pipe::DepthFormat>({"d16", "d24", "d32f"});
};
template <> struct Names<pipe::CompareFunc> {
  static constexpr auto table = in_enum_order<pipe::CompareFunc>(
      {"never", "less", "equal", "less_equal", "greater", "not_equal", "greater_equal", "always"});
};
template <> struct Names<pipe::Provoking> {
  static constexpr auto table = in_enum_order<pipe::Provoking>({"first", "last"});
};
} // namespace rastrules

// SPDX-License-Identifier: MIT
// The triangle rules written a second time, for machines: exact, slow, independent.
// Written from spec/ (SNAP.*, TRI.*, RASTER.TARGET.CLIP) with exact rationals; never includes
// or calls kernel code, and shares none of its types.
// Implements (as oracle): SNAP.VERTEX.ROUND, SNAP.VERTEX.RANGE, SNAP.D3D.SATURATE,
//   TRI.FILL.TOP_EDGE, TRI.FILL.LEFT_EDGE, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION,
//   TRI.CULL.MODE, TRI.COVER.SAMPLE

#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rastrules::oracle {

// Raster state as plain strings, spelled as in spec/scene.md, so that the oracle does not
// depend on the kernel's enums.
struct State {
  std::string cull = "none";     // "none" | "back" | "front"
  std::string front_face = "cw"; // "cw" | "ccw"
  std::string fill = "top-left"; // "top-left" | "top-right" | "bottom-left" | "bottom-right"
};

using FloatTriangle = std::array<std::array<float, 2>, 3>;

struct Scene {
  std::int32_t width = 0;
  std::int32_t height = 0;
  State state;
  std::vector<FloatTriangle> triangles;
};

struct Fragment {
  std::uint32_t prim = 0;
  std::int32_t x = 0;
  std::int32_t y = 0;
  friend bool operator==(const Fragment&, const Fragment&) = default;
};

// Returns v * 256 rounded half to even as an integer, computed with exact rationals, or
// nullopt when v is NaN, infinite, or the result lies outside [-2^23, 2^23 - 1].
std::optional<std::int64_t> snap(float v);

// Returns D3D11.3's saturating float-to-fixed conversion to signed 16.8 as a raw integer,
// computed with exact rationals: NaN -> 0; |v| < 2^-9 -> 0; v >= FixedMax (2^15 - 2^-8,
// including +Inf) -> FixedMax; v <= FixedMin (-2^15, including -Inf) -> FixedMin; otherwise
// v * 256 rounded half to even.
std::int64_t snap_d3d_saturate(float v);

// The two choices of a fill convention (TRI.FILL.CONVENTION).
struct FillSides {
  bool top;  // horizontal edges with the interior below are inclusive (else those above)
  bool left; // other edges with the interior to the right are inclusive (else to the left)
};

// Returns the sides the fill convention `fill` ("top-left" | "top-right" | "bottom-left" |
// "bottom-right") makes inclusive. Throws std::invalid_argument for any other string.
// rule: TRI.FILL.CONVENTION
FillSides parse_fill(const std::string& fill);

// Returns +1 when the snapped vertices (raw 16.8) run clockwise on screen (y down), -1 when
// counter-clockwise, 0 when they are collinear or two coincide (TRI.ORIENT.AREA).
int winding(const std::array<std::array<std::int64_t, 2>, 3>& snapped);

// Returns whether the triangle with the given snapped vertices (raw 16.8 integers) covers the
// sample (raw 16.8), under `state`, decided by the spec's words: exact orientation, the top
// and left edges classified by "exactly horizontal and above the other edges" / "not
// horizontal and on the left side of the triangle", culling, and the fill convention.
bool covers(const std::array<std::array<std::int64_t, 2>, 3>& snapped,
            const std::array<std::int64_t, 2>& sample, const State& state);

// Returns every fragment of the scene, sorted by (prim, y, x), by testing every pixel centre
// of the target against every triangle (no bounding box, no stepping). Throws
// std::invalid_argument when a coordinate does not snap.
std::vector<Fragment> render(const Scene& scene);

} // namespace rastrules::oracle

// SPDX-License-Identifier: MIT
// Vertex snapping: float32 window coordinates to 16.8 fixed point.
// Implements: SNAP.VERTEX.ROUND, SNAP.VERTEX.RANGE, SNAP.VERTEX.INVALID, SNAP.D3D.SATURATE

#pragma once

#include <cstdint>
#include <string_view>

#include "rastrules/fixed.hpp"

namespace rastrules {

enum class SnapStatus {
  kOk,          // value snapped exactly (round half to even)
  kNaN,         // input is a NaN
  kInfinite,    // input is +Inf or -Inf
  kOutOfRange,  // rounded value lies outside SNAP.VERTEX.RANGE
};

[[nodiscard]] std::string_view to_string(SnapStatus s);

struct SnapResult {
  SnapStatus status = SnapStatus::kOk;
  Subpixel value;  // meaningful only when status == kOk
};

// Returns v * 2^8 rounded to the nearest integer, ties to even, computed from the bits of v
// with integer arithmetic only (no floating-point operation, so no dependence on the FPU's
// rounding mode). NaN, infinities and results outside [kMinVertexRaw, kMaxVertexRaw] are
// reported, never clamped: a scene with such a vertex is rejected (SNAP.VERTEX.INVALID).
// rule: SNAP.VERTEX.ROUND, SNAP.VERTEX.RANGE, SNAP.VERTEX.INVALID
[[nodiscard]] SnapResult snap_to_subpixel(float v);

// Returns the D3D11.3 float-to-fixed conversion (functional spec 3.2.4.1 and its diagram) to
// signed 16.8: NaN -> 0; |v| < 2^-9 -> 0; v >= FixedMax (including +Inf) -> FixedMax;
// v <= FixedMin (including -Inf) -> FixedMin; otherwise round half to even. Offered for callers
// that emulate D3D's saturating behaviour; the scene path rejects instead.
// rule: SNAP.D3D.SATURATE
[[nodiscard]] Subpixel snap_d3d_saturate(float v);

}  // namespace rastrules

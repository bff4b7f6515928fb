// SPDX-License-Identifier: MIT
// Path primitives in the scene (SCENE.PRIM.PATH): snapping a FloatPath, the work of a path and
// its fragments, for kernel/src/scene.cpp. Internal to the kernel.

#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>

#include "rastrules/scene.hpp"

namespace rastrules::detail {

// Snaps every control point of primitive p's path into prim.path (SNAP.VERTEX.INVALID), or
// returns the error naming the first bad point (by its position in "d" when the path was read
// from path data) or the path's size beyond kMaxPathSegments.
// rule: SCENE.PRIM.PATH, SNAP.VERTEX.INVALID, SCENE.INPUT.LIMITS
[[nodiscard]] std::optional<SceneError> prepare_path(const FloatPath& in, std::size_t p,
                                                     PreparedPrimitive& prim);

// The work of a path primitive (SCENE.INPUT.LIMITS, primitive_work).
[[nodiscard]] std::uint64_t path_work(const PreparedScene& scene, const PreparedPrimitive& prim);

// Calls emit for each fragment of path primitive p in (y, x) order: a pixel's covered samples
// ANDed with the sample mask (coverage "samples"), or its exact area (coverage "area"), as
// the kernel's path rasterizer finds them, one row at a time.
// rule: PATH.COVER.SAMPLE, PATH.AREA.EXACT, SCENE.OUTPUT.AREA, MSAA.MASK.AND
void path_fragments(const PreparedScene& scene, std::size_t p,
                    const std::function<void(Fragment&&)>& emit);

} // namespace rastrules::detail

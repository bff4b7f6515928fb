// SPDX-License-Identifier: MIT
// The explanation of one pixel, as text or JSON: what `rastrules explain` prints and what the C
// API's rr_explain returns. It formats the kernel's decision records (rastrules/decision.hpp:
// decide_pixel) for a window-space scene, and run_pipeline's fragments at the pixel for a
// pipeline scene; it decides nothing itself.
// Implements: SCENE.OUTPUT.PIPELINE (the explanation of a pipeline scene's pixel)

#pragma once

#include <cstdint>
#include <string>
#include <variant>

#include "rastrules/pipeline.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::io {

// Returns why each primitive of a window-space scene covers, or does not cover, pixel (x, y):
// per primitive the snapped vertices, each edge's exact value at the centre, the top and left
// edges and the rule that decided (per sample on a multisampled scene), then the primitives
// that cover it. prepared is prepare(scene). Preconditions: 0 <= x < scene.width,
// 0 <= y < scene.height.
// rule: SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP, SCENE.LINE_MODE
[[nodiscard]] std::string explain_window_pixel(const Scene& scene, const PreparedScene& prepared,
                                               std::int32_t x, std::int32_t y, bool as_json);

// Returns the fragments run_pipeline produced at pixel (x, y) of a pipeline scene, with what
// each carries and the drawn primitive it was interpolated from; an error only when result
// does not belong to scene. result is pipe::run_pipeline(scene). Preconditions: as above.
// rule: SCENE.OUTPUT.PIPELINE
[[nodiscard]] std::variant<std::string, SceneError>
explain_pipeline_pixel(const Scene& scene, const pipe::PipeResult& result, std::int32_t x,
                       std::int32_t y, bool as_json);

// Returns raw / 2^frac_bits as an exact decimal ("-3.5", "0.00390625").
// Preconditions: 0 <= frac_bits <= 16.
[[nodiscard]] std::string fixed_decimal(std::int64_t raw, int frac_bits);

} // namespace rastrules::io

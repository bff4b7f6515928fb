// SPDX-License-Identifier: MIT
// Kernel against oracle, written once (in the manner of CGAL's Kernel_checker): the only place
// that knows both the kernel's types and the exact oracle's, with the only kernel->oracle
// adapter. The showcase, the libFuzzer targets and the properties call it; the kernel never
// does, and the oracle never includes the kernel.
// Implements: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.COVERAGE, SCENE.OUTPUT.MSAA (checks)
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "rastrules/oracle/msaa.hpp"
#include "rastrules/oracle/path.hpp"
#include "rastrules/oracle/triangle.hpp"
#include "rastrules/pipeline.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::check {

// The kernel->oracle adapter: raster state as the oracle's words (rastrules/names.hpp), a
// vertex by the oracle's own snapping (never the kernel's; throws std::invalid_argument when
// it does not snap), and a whole scene as the multisampling oracle reads it.
[[nodiscard]] oracle::State oracle_state(const RasterState& state);
[[nodiscard]] std::array<std::int64_t, 2> oracle_raw(const FloatPoint& v);
[[nodiscard]] oracle::msaa::Input oracle_msaa_input(const Scene& scene);

// A path as the path oracle reads it: every control point by the oracle's own snapping.
// rule: SCENE.PRIM.PATH
[[nodiscard]] oracle::path::Path oracle_path(const FloatPath& path);

// Whether a scene goes to the multisampling oracle: anything SCENE.MSAA asks for beyond one
// sample at the centre with pixel shading.
[[nodiscard]] bool multisampled(const Scene& scene);

struct CheckOptions {
  std::size_t max_mismatches = std::numeric_limits<std::size_t>::max(); // kept, in order
};

// What the check found: mismatches (empty when the kernel agrees with the oracle) and which
// oracle checked what, in the order first used.
struct Mismatches {
  std::vector<std::string> mismatches;
  std::size_t count = 0; // all found, also beyond max_mismatches
  std::vector<std::string> oracles;
  [[nodiscard]] bool agree() const { return count == 0; }
};

// Compares the kernel's fragments of a window-space scene with the exact oracles. One sample
// at the centre: the fragment list itself (inside the target, sorted, mask 1, seg on strips
// only, coverage on antialiased lines only and in [1, 65536]), triangles against
// oracle::render, points against point_covers, aliased lines against aliased_line_pixels,
// quadrilateral lines against quad_line_covers, antialiased lines against aa_pixels' set and
// aa_check (coverage within LINE.AA.PRECISION). Multisampled scenes: every fragment field
// against oracle::msaa::render and the resolved target against oracle::msaa::resolve.
// Path primitives, in any scene: each pixel's mask against oracle::path::cover_samples (the
// scene's pattern and fill convention, ANDed with the sample mask), or its exact area and
// alpha against oracle::path::cover_area; the other primitives are checked as above without
// them (the resolve too).
// Preconditions: ps is prepare(scene) and kernel its fragments (rasterize or render).
// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.COVERAGE, SCENE.OUTPUT.MSAA, MSAA.RESOLVE.AVERAGE
[[nodiscard]] Mismatches check_against_oracle(const Scene& scene, const PreparedScene& ps,
                                              const std::vector<Fragment>& kernel,
                                              const CheckOptions& options = {});

// What check_pipeline compared, for reports and the properties' statistics.
struct PipelineStats {
  std::size_t values_checked = 0; // attribute and depth values against each drawn primitive
  std::size_t fragments = 0, killed = 0, clipped_prims = 0;
  std::size_t attr_checks = 0, depth_checks = 0; // values in the replay from the scene alone
  bool horizon = false, saturated = false;       // an attribute beyond the horizon, saturated
};

// Checks run_pipeline's result for scene against the exact oracle, in three passes.
// 1. Fragment by fragment: barycentrics summing to their area (PIPE.BARY.SUM), finite
//    attributes (PIPE.INTERP.HORIZON), stored depths inside the viewport's range
//    (PIPE.DEPTH.CLAMP), and, from each fragment's drawn primitive, every attribute
//    (PIPE.INTERP.BOUND, flat values exactly) and every sample depth (PIPE.DEPTH.BOUND).
// 2. A replay from the scene alone, which trusts nothing the kernel reports: the oracle's
//    transform, clip volume, clipper and fan give each primitive's parts (triangles) or
//    segments (points, lines, each segment of a strip: PIPE.BARY.LINE, LINE.STRIP.SEQUENCE);
//    every drawn primitive equals the oracle's bit for bit; barycentrics are the exact ones at
//    the evaluation point (PIPE.BARY.EXACT, PIPE.INTERP.LOCATION); attributes and depths lie
//    within the spec's bounds; the depth test is replayed sample by sample (PIPE.DEPTH.TEST,
//    .WRITE, .KILL) into a depth buffer equal to the kernel's; fragments lie inside the
//    viewport's scissor (PIPE.VIEWPORT.SCISSOR) in the output order.
// 3. The coverage of every part equals the window-space render of that part (rastrules::render
//    with the scene's raster and multisample state), cut to the scissor.
// Passes 2 and 3 report their first problem only. Precondition: result is run_pipeline(scene).
// rule: PIPE.BARY.SUM, PIPE.INTERP.HORIZON, PIPE.DEPTH.CLAMP, PIPE.INTERP.BOUND, PIPE.DEPTH.BOUND
// rule: PIPE.CLIP.UNCLIPPED, PIPE.CLIP.POLYGON, PIPE.BARY.EXACT, PIPE.DEPTH.TEST, PIPE.DEPTH.KILL
[[nodiscard]] Mismatches check_pipeline(const Scene& scene, const pipe::PipeResult& result,
                                        const CheckOptions& options = {},
                                        PipelineStats* stats = nullptr);

// Whether primitive prim has a clip-space position beyond PIPE.INPUT.POSITION after the scene's
// transform, by the oracle's float32 arithmetic (the pipeline must then reject the scene).
[[nodiscard]] bool transform_overflows(const Scene& scene, std::size_t prim);

} // namespace rastrules::check

// SPDX-License-Identifier: MIT
// The stages of run_pipeline, one file each under kernel/src/pipe/, with typed hand-offs;
// run_pipeline (pipeline_scene.cpp) composes them in the order of the design's data flow:
//
//   validate -> assemble (transform, clip, divide, viewport) -> prepare (snap and set up)
//   -> cover -> link (fragments to drawn primitives) -> draw (their depths, w, attributes)
//   -> shade (depth test and write, barycentrics, attributes) on the depth target
//
// Only the stages a scene asks for run (PIPE.EFFECTS.ON_DEMAND). Internal to the kernel: the
// public interface is rastrules/pipeline.hpp.
// Implements: PIPE.EFFECTS.ON_DEMAND (the stage order)
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "rastrules/pipeline.hpp"

namespace rastrules::pipe::detail {

// "name[i]", for error fields.
std::string idx(const char* name, std::size_t i);
SceneError err(std::string field, std::string message);

// What a coverage primitive of the internal window-space scene came from.
struct Source {
  std::size_t prim = 0;                 // the scene's primitive index
  std::optional<std::uint32_t> part;    // fan triangle or clipped segment, when clipped
  std::vector<WindowVertex> v;          // window x, y (unsnapped), depth z, clip w
  std::vector<std::vector<float>> attr; // per vertex
  // Per segment (one entry for a triangle, point or line; one per segment of a strip): per
  // attribute, the provoking vertex's value (PIPE.INTERP.FLAT).
  std::vector<std::vector<float>> flat;
};

// The number of drawn primitives (PipeResult::drawn) a coverage primitive of type t with nv
// vertices stands for: one per segment of a strip (LINE.STRIP.SEQUENCE), else one.
std::size_t segments_of(PrimitiveType t, std::size_t nv);

// validate.cpp. Returns the viewport (the whole target by default), or the first error of the
// pipeline state; the primitives are checked by assemble() and prepare().
std::variant<Viewport, SceneError> validate(const Scene& s, const PipeOptions& o);

// assemble.cpp. The internal window-space scene (one coverage primitive per unclipped primitive
// or clipped part) and where each of its primitives came from; or the first error of a
// primitive (attributes, vertex counts, positions).
struct Assembled {
  Scene ws;
  std::vector<Source> sources;
};
std::variant<Assembled, SceneError> assemble(const Scene& s, const Viewport& vp);

// Replaces the primitive index of an error field "primitives[N]..." of the internal scene with
// the index of its source primitive.
SceneError remap(SceneError e, const std::vector<Source>& sources);

// cover.cpp. Appends the covered fragments of every prepared primitive inside the scissor, in
// (prim, part, y, x, seg, sample) order, f.prim being the index in ps (empty sources: ps is the
// scene itself, primitive p its primitive p); returns the error of a
// scene beyond the fragment limit (SCENE.INPUT.LIMITS).
std::optional<SceneError> cover(const PreparedScene& ps, const std::vector<Source>& sources,
                                const ScissorRect& scissor, const PipeOptions& o,
                                std::vector<Fragment>& fragments);

// Which drawn primitive each fragment belongs to: drawn primitives are one per coverage
// primitive, one per segment of a strip, so that a strip's segment k is interpolated from its
// own vertices k and k + 1 (LINE.STRIP.SEQUENCE).
struct Links {
  std::vector<std::size_t> first_drawn; // per coverage primitive, then the total
  std::vector<std::uint32_t> drawn_of;  // per fragment
};
// Fills data (drawn, part, passed) and turns each fragment's prim into the scene's index.
Links link(const std::vector<Source>& sources, std::vector<Fragment>& fragments,
           std::vector<FragmentData>& data);

// draw.cpp. A drawn primitive as shading needs it.
struct Drawn {
  PrimitiveType type = PrimitiveType::kTriangle;
  std::vector<Vec2> v; // snapped vertices: 3, 2 or 1
  std::array<float, 3> z{}, w{1.0f, 1.0f, 1.0f};
  std::vector<std::array<float, 3>> a;
  DepthValue lo, hi; // conservative bounds of every sample's stored depth (triangles, points)
  bool bounded = false;
};
// Returns every drawn primitive (window depths after bias, w, attribute values, Hi-Z bounds)
// and appends its public record to out.
std::vector<Drawn> draw(const Scene& s, const PreparedScene& ps, const std::vector<Source>& sources,
                        const Links& links, const Viewport& vp, std::vector<DrawnPrimitive>& out);

// shade.cpp. Depth (test and write) and attributes of every fragment, on the depth target with
// its tiles, fast clear and Hi-Z; fills result.data, depth_buffer and stats.
void shade(const Scene& s, const PreparedScene& ps, const Viewport& vp, const PipeOptions& o,
           const std::vector<Drawn>& drawn, const Links& links, PipeResult& result);

} // namespace rastrules::pipe::detail

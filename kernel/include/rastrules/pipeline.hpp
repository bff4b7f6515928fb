// SPDX-License-Identifier: MIT
// The pipeline around the rules (spec/rules/pipe.md): transforms, clipping, divide and viewport,
// exact barycentrics, attribute interpolation and depth. Standard library only.
// The building blocks are free functions (used by the scene pipeline, the tests, the properties
// and the benchmarks); run_pipeline() strings them together for a whole scene.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "rastrules/fixed.hpp"
#include "rastrules/isa.hpp"
#include "rastrules/pipe_state.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::pipe {

// ---------------------------------------------------------------------------------------------
// Input and transforms

// The magnitude limit of positions before and after the transform (PIPE.INPUT.POSITION).
inline constexpr double kMaxPosition = 18446744073709551616.0; // 2^64
inline constexpr std::size_t kMaxAttributes = 16;              // PIPE.INPUT.ATTRIBUTES

// Returns m * v with each row fl32(((m0*x + m1*y) + m2*z) + m3*w).
// rule: PIPE.TRANSFORM.FLOAT32
[[nodiscard]] Vec4f transform(const Mat4f& m, const Vec4f& v);

// ---------------------------------------------------------------------------------------------
// Viewport

// Returns nullopt when vp satisfies PIPE.VIEWPORT.RANGE, else {field, message}, field one of
// "x", "y", "width", "height", "min_depth", "max_depth".
// rule: PIPE.VIEWPORT.RANGE
[[nodiscard]] std::optional<std::pair<std::string, std::string>> check_viewport(const Viewport& vp);

// A vertex after divide and viewport (PIPE.VIEWPORT.TRANSFORM): window x, y (pixels, float32,
// not yet snapped), window depth z, and the clip w kept for perspective interpolation.
struct WindowVertex {
  float x = 0.0f, y = 0.0f, z = 0.0f, w = 1.0f;
  friend bool operator==(const WindowVertex&, const WindowVertex&) = default;
};

// Returns the divide and viewport transform of clip-space position p (p[3] > 0).
// rule: PIPE.VIEWPORT.TRANSFORM
[[nodiscard]] WindowVertex to_window(const Vec4f& p, const Viewport& vp);

// Returns v clamped to the snap range [-32768, 32767.99609375] (D3D's FixedMin and FixedMax):
// the window x and y of clip-space vertices pass through it before snapping.
// rule: PIPE.CLIP.SATURATE
[[nodiscard]] constexpr float saturate_to_snap_range(float v) {
  return v < -32768.0f ? -32768.0f : (v > 32767.99609375f ? 32767.99609375f : v);
}

// The implicit scissor of PIPE.VIEWPORT.SCISSOR: pixels [x0, x1) x [y0, y1), half-open and
// 64-bit (raster::PixelRect, the traversal's, is inclusive and 32-bit).
struct ScissorRect {
  std::int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  [[nodiscard]] bool contains(std::int64_t px, std::int64_t py) const {
    return px >= x0 && px < x1 && py >= y0 && py < y1;
  }
};
// rule: PIPE.VIEWPORT.SCISSOR
[[nodiscard]] ScissorRect viewport_scissor(const Viewport& vp);

// ---------------------------------------------------------------------------------------------
// Clipping

inline constexpr double kGuardBand = 31744.0; // px, PIPE.CLIP.VOLUME
inline constexpr double kWMin = 0x1p-126;     // the w plane: float32's smallest normal

// The clip volume of one primitive (PIPE.CLIP.VOLUME).
struct ClipVolume {
  double w_min = kWMin;
  double gx_lo = -1.0, gx_hi = 1.0, gy_lo = -1.0, gy_hi = 1.0;
  bool depth_clip = true;
};

// Returns the volume under viewport vp (the same for every primitive; vs is not used and kept
// for callers that pass the primitive).
// rule: PIPE.CLIP.VOLUME
[[nodiscard]] ClipVolume clip_volume(const std::vector<Vec4f>& vs, const Viewport& vp,
                                     bool depth_clip);

// A clip-space vertex with its attributes (all interpolated alike by the clipper).
struct ClipVertex {
  Vec4f pos{};
  std::vector<float> attr;
  friend bool operator==(const ClipVertex&, const ClipVertex&) = default;
};

// Returns whether p is inside every plane of the volume.
[[nodiscard]] bool inside(const ClipVolume& vol, const Vec4f& p);

// Returns the clipped polygon of triangle t (empty when nothing is left); t itself when all
// three vertices are inside (PIPE.CLIP.UNCLIPPED).
// rule: PIPE.CLIP.POLYGON, PIPE.CLIP.COMPUTE, PIPE.CLIP.UNCLIPPED
[[nodiscard]] std::vector<ClipVertex> clip_polygon(const std::vector<ClipVertex>& polygon,
                                                   const ClipVolume& vol);

// Returns the clipped segment (a, b), or nullopt when it lies outside.
// rule: PIPE.CLIP.LINE
[[nodiscard]] std::optional<std::array<ClipVertex, 2>>
clip_segment(const ClipVertex& a, const ClipVertex& b, const ClipVolume& vol);

// ---------------------------------------------------------------------------------------------
// Barycentrics and interpolation

// Exact barycentrics (PIPE.BARY.EXACT): lambda_i = e[i] / area, and e[0] + e[1] + e[2] == area.
struct Barycentrics {
  std::array<std::int64_t, 3> e{};
  std::int64_t area = 0;
  friend bool operator==(const Barycentrics&, const Barycentrics&) = default;
};

// Returns the barycentrics of s in the triangle of snapped vertices v (in primitive order).
// rule: PIPE.BARY.EXACT
[[nodiscard]] Barycentrics barycentrics(const std::array<Vec2, 3>& v, Vec2 s);

// Returns the perspective-correct value (PIPE.INTERP.PERSPECTIVE, PIPE.INTERP.HORIZON): a are
// the vertex values, w the vertices' clip w, flat the provoking vertex's value.
// rule: PIPE.INTERP.PERSPECTIVE, PIPE.INTERP.HORIZON
[[nodiscard]] float interpolate_perspective(const Barycentrics& b, const std::array<float, 3>& a,
                                            const std::array<float, 3>& w, float flat);
// rule: PIPE.INTERP.LINEAR, PIPE.INTERP.HORIZON
[[nodiscard]] float interpolate_linear(const Barycentrics& b, const std::array<float, 3>& a);

// ---------------------------------------------------------------------------------------------
// Depth

// A stored depth value: the UNORM integer for d16/d24, the float32 bits' value for d32f
// (stored as the float itself; compared as floats).
struct DepthValue {
  std::uint32_t unorm = 0; // d16, d24
  float f = 0.0f;          // d32f
  friend bool operator==(const DepthValue&, const DepthValue&) = default;
};

// Returns the screen-linear depth at the barycentrics (PIPE.DEPTH.INTERP), before the clamp.
// rule: PIPE.DEPTH.INTERP
[[nodiscard]] double interpolate_depth(const Barycentrics& b, const std::array<float, 3>& z);

// Returns the clamped depth converted to the format (PIPE.DEPTH.CLAMP, PIPE.DEPTH.FORMAT).
// rule: PIPE.DEPTH.CLAMP, PIPE.DEPTH.FORMAT
[[nodiscard]] DepthValue to_depth_format(double z, float min_depth, float max_depth, DepthFormat f);

// Returns whether the test passes for the new value against the old one (PIPE.DEPTH.TEST).
// rule: PIPE.DEPTH.TEST
[[nodiscard]] bool depth_test(CompareFunc func, const DepthValue& now, const DepthValue& old,
                              DepthFormat f);

// Returns the per-primitive bias of PIPE.DEPTH.BIAS for a triangle with snapped vertices v and
// window depths z (0 when both bias terms are zero). format nullopt: no depth buffer (UNORM r
// of 24 bits).
// rule: PIPE.DEPTH.BIAS
[[nodiscard]] float depth_bias(const std::array<Vec2, 3>& v, const std::array<float, 3>& z,
                               const DepthBias& bias, std::optional<DepthFormat> format);

// ---------------------------------------------------------------------------------------------
// The scene pipeline

// Which stages a scene needs (PIPE.EFFECTS.ON_DEMAND).
struct Effects {
  bool clip_space = false; // some primitive has pos
  bool depth = false;
  bool attributes = false;
  bool barycentrics = false; // depth or attributes
  [[nodiscard]] bool coverage_only() const { return !clip_space && !depth && !attributes; }
};
[[nodiscard]] Effects effects_of(const Scene& s);

// What a fragment of a pipeline scene carries besides its coverage (PipeResult::data[i] goes
// with PipeResult::fragments[i]).
// A fragment none of whose samples passes the depth test is killed (PIPE.DEPTH.KILL):
// passed == 0 and no bary, attr or depth. Helper lanes are never depth-tested.
struct FragmentData {
  std::uint32_t drawn = 0;           // index into PipeResult::drawn
  std::optional<std::uint32_t> part; // fan triangle or clipped segment index, when clipped
  std::optional<Barycentrics> bary;  // at the first attribute's location, or the pixel centre
  std::vector<float> attr;           // one per declared attribute
  std::vector<DepthValue> depth;     // one per sample of the mask (ascending sample index)
  std::uint32_t passed = 0;          // samples that passed the depth test (== mask without depth)
  friend bool operator==(const FragmentData&, const FragmentData&) = default;
};

// A primitive as drawn after clipping, divide, viewport, snapping and depth bias: what every
// fragment's values were interpolated from (for explanations and exact re-computation).
struct DrawnPrimitive {
  PrimitiveType type = PrimitiveType::kTriangle;
  std::uint32_t prim = 0; // the scene's primitive index
  std::optional<std::uint32_t> part;
  // The segment of an unclipped line strip: each segment is drawn (and listed here) as a line
  // of its own (LINE.STRIP.SEQUENCE); a clipped strip's segments are parts instead.
  std::optional<std::uint32_t> seg;
  std::vector<Vec2> snapped;                // 3 (triangle), 2 (line, strip segment), 1 (point)
  std::array<float, 3> z{};                 // window depth of the vertices (biased)
  std::array<float, 3> w{1.0f, 1.0f, 1.0f}; // clip w of the vertices
  std::vector<std::array<float, 3>> attr;   // per attribute, the vertices' values
  std::vector<float> flat;                  // per attribute, the provoking vertex's value
};

// What the optimizations saved (not part of the result: it differs between options).
struct PipeStats {
  std::uint64_t hiz_rejected = 0;        // (primitive, tile) pairs Hi-Z killed whole
  std::uint64_t depth_samples = 0;       // sample depths computed
  std::uint64_t attributes = 0;          // attribute values interpolated
  std::uint64_t tiles_never_written = 0; // tiles fast clear filled only at the end
};

// The result, as two parallel arrays so that a coverage-only scene costs what the kernel alone
// costs (PIPE.EFFECTS.ON_DEMAND): fragments are the kernel's (SCENE.OUTPUT.FRAGMENTS, prim being
// the scene's primitive index), sorted by (prim, part, y, x, seg, sample); data is empty when
// the scene has no clip-space input, depth or attributes, else data[i] belongs to fragments[i].
// An attribute at the centroid makes every fragment carry its centroid (as the scene's
// `centroid` key does, with the D3D11 rule unless the scene names another).
struct PipeResult {
  std::vector<Fragment> fragments;
  std::vector<FragmentData> data;
  std::vector<DrawnPrimitive> drawn;    // with depth or attributes: every drawn primitive
  std::vector<DepthValue> depth_buffer; // width * height * samples, row-major, sample-minor
  Effects effects;
  PipeStats stats;
};

// Optimizations that never change a result (PIPE.OPT.*); all on by default. plain() turns
// every one off: the reference path the properties compare them with.
struct PipeOptions {
  RenderOptions render;        // traversal and instruction set; threads shade tiles (binning only)
  std::int32_t tile_size = 16; // 16 or 32 px: the tiles of binning, fast clear and Hi-Z
  bool binning = true;         // PIPE.OPT.TILES: depth and attributes computed tile by tile
  bool hiz = true;             // PIPE.OPT.HIZ: per-tile depth bounds reject whole primitives
  bool early_z = true;         // PIPE.OPT.EARLY_Z: depth test before attributes
  bool fast_clear = true;      // PIPE.OPT.FAST_CLEAR: tiles cleared on their first write
  [[nodiscard]] static PipeOptions plain() {
    PipeOptions o;
    o.render.traversal = Traversal::kPlain;
    o.binning = o.hiz = o.early_z = o.fast_clear = false;
    return o;
  }
  // The most fragments (helper lanes included) a run may produce, and the most one primitive
  // may hold to sort them (SCENE.INPUT.LIMITS); beyond it run_pipeline returns an error.
  std::uint64_t max_fragments = std::uint64_t{1} << 26;
  // The most sample tests the plain traversal of the clipped primitives may make, checked
  // before they are rasterized (primitive_work, SCENE.INPUT.LIMITS).
  std::uint64_t max_work = kDefaultMaxWork;
};

// Returns the first error of a scene's pipeline state and per-vertex lists, in field order: the
// viewport (PIPE.VIEWPORT.RANGE), the matrices (PIPE.TRANSFORM.FLOAT32), the attribute
// declarations (PIPE.INPUT.ATTRIBUTES, PIPE.INTERP.LOCATION), the depth state
// (PIPE.DEPTH.FORMAT, PIPE.DEPTH.BIAS, SCENE.INPUT.LIMITS), then each primitive's vertex count,
// z and w (window space only, one per vertex) and attr (exactly when attributes are declared,
// one list per vertex, one finite value per attribute). run_pipeline checks the same first;
// positions and what the transform makes of them are checked as it runs.
// rule: SCENE.PIPELINE, PIPE.INPUT.ATTRIBUTES
[[nodiscard]] std::optional<SceneError> validate(const Scene& s);

// What every reader of a scene does after reading it (the command line's load_scene, the C
// API, the Python module): a scene with pipeline state (has_pipeline_state) is validated and
// returns nullopt (run_pipeline draws it); any other is prepared and returns its prepared
// scene. Returns the first error of bad input.
// rule: SCENE.INPUT.ERRORS, SCENE.PIPELINE
[[nodiscard]] std::variant<std::optional<PreparedScene>, SceneError> check_scene(const Scene& s);

// Validates, transforms, clips, rasterizes (all rules of the other files), interpolates and
// tests depth. Returns the first error (field, message) of bad input.
[[nodiscard]] std::variant<PipeResult, SceneError> run_pipeline(const Scene& s,
                                                                const PipeOptions& o = {});

} // namespace rastrules::pipe

// SPDX-License-Identifier: MIT
// The kernel's scene model and its single entry point: validate, snap, set up, traverse.
// Implements: SCENE.FORMAT.V1 (in memory), SCENE.OUTPUT.FRAGMENTS, SCENE.TARGET.LIMITS,
//             SNAP.VERTEX.INVALID, SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP,
//             SCENE.LINE_MODE, SCENE.OUTPUT.COVERAGE
// The JSON reader and writer live in tools/; the kernel has no third-party dependency.

#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "rastrules/conventions.hpp"
#include "rastrules/fixed.hpp"
#include "rastrules/isa.hpp"
#include "rastrules/line.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/name_table.hpp"
#include "rastrules/path_types.hpp"
#include "rastrules/pipe_state.hpp"
#include "rastrules/snap.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules {

namespace path {
struct AreaValue; // rastrules/path.hpp
} // namespace path

// rule: SCENE.FORMAT.V1, SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP
enum class PrimitiveType { kTriangle, kPoint, kLine, kLineStrip, kPath };
template <> struct Names<PrimitiveType> {
  static constexpr auto table =
      in_enum_order<PrimitiveType>({"triangle", "point", "line", "line_strip", "path"});
};

// A window-space position in pixels, read as float32.
using FloatPoint = std::array<float, 2>;

// A 2D path as read, before snapping (SCENE.PRIM.PATH): contours of float32 control points in
// pixels, the fill rule and the coverage its fragments carry. prepare() snaps every point
// (SNAP.VERTEX.*) into a path::Path.
// rule: SCENE.PRIM.PATH, PATH.GEOMETRY
struct FloatPathSegment {
  path::SegmentKind kind = path::SegmentKind::kLine;
  std::array<FloatPoint, 3> p{}; // as path::Segment: the first path::point_count(kind) are used
  friend bool operator==(const FloatPathSegment&, const FloatPathSegment&) = default;
};
struct FloatContour {
  FloatPoint start{};
  std::vector<FloatPathSegment> segments;
  friend bool operator==(const FloatContour&, const FloatContour&) = default;
};
struct FloatPath {
  path::FillRule fill_rule = path::FillRule::kNonZero;
  path::Coverage coverage = path::Coverage::kSamples;
  std::vector<FloatContour> contours;
  // Where each control point was read in the primitive's SVG path data ("d"), as character
  // offsets in reading order (each contour's start, then its segments' points), so that an
  // error names the text; empty when the path was not read from path data.
  std::vector<std::size_t> d_offsets;
};

struct Primitive {
  PrimitiveType type = PrimitiveType::kTriangle;
  // Window coordinates in pixels, read as float32: 3 for a triangle, 1 for a point, 2 for a
  // line, at least 2 for a line strip. A default primitive is a triangle with 3 zero vertices.
  // Empty when pos is given.
  std::vector<FloatPoint> v = std::vector<FloatPoint>(3);
  bool aa = false;                    // antialiased (lines and line strips only; SCENE.PRIM.LINE)
  Rgba8 color = {255, 255, 255, 255}; // written to covered samples by resolve() (SCENE.MSAA)
  // The pipeline's inputs (SCENE.PIPELINE), all empty for a window-space primitive that asks
  // for nothing more: positions before the transform (then v is empty: a window-space
  // primitive is the identity case of a clip-space one), window depth and w per vertex of a
  // window-space one (default 0 and 1), and per vertex one value per declared attribute.
  std::vector<pipe::Vec4f> pos;         // PIPE.INPUT.POSITION
  std::vector<float> z;                 // window space only (PIPE.DEPTH.INTERP)
  std::vector<float> w;                 // window space only (PIPE.INTERP.PERSPECTIVE)
  std::vector<std::vector<float>> attr; // PIPE.INPUT.ATTRIBUTES
  // A path primitive's path (type kPath, and then v is empty): SCENE.PRIM.PATH.
  std::optional<FloatPath> path;
};

// Returns a triangle primitive with the given vertices.
[[nodiscard]] Primitive make_triangle(const std::array<FloatPoint, 3>& v);

// Returns a path primitive (no vertices) with the given path (SCENE.PRIM.PATH).
[[nodiscard]] Primitive make_path(FloatPath path);

// Returns the primitive's coverage fields (type, v, aa, color) without its pipeline inputs.
[[nodiscard]] Primitive coverage_of(const Primitive& p);

// Returns the number of vertices a primitive of type t must have (0 for a line strip, whose
// count is "at least 2").
[[nodiscard]] std::size_t required_vertex_count(PrimitiveType t);

// Returns what is wrong with n vertices for a primitive of type t, e.g. "a line must have
// exactly 2 vertices [x, y], got 3" ("[x, y, z] or [x, y, z, w]" for clip-space positions), or
// nullopt when n is right. The one wording of this rule for every reader of scenes.
// rule: SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP
[[nodiscard]] std::optional<std::string> vertex_count_problem(PrimitiveType t, std::size_t n,
                                                              bool clip_space);

// A scene: the target and its conventions, the primitives, and the pipeline state it asks for.
// A scene without pipeline state (has_pipeline_state() false) is drawn by coverage alone;
// otherwise rastrules::pipe::run_pipeline() draws it (transform, clipping, depth, attributes),
// only the stages it asks for running (PIPE.EFFECTS.ON_DEMAND).
// rule: SCENE.FORMAT.V1, SCENE.PIPELINE
struct Scene {
  std::int32_t width = 0;
  std::int32_t height = 0;
  // Every convention in one value (PROFILE.CONVENTIONS): fill, front face, line mode, pattern
  // kind, centroid rule, MultisampleEnable, provoking vertex, depth format. D3D11's by default;
  // `scene.conventions = profile(ProfileName::kVulkan)` or apply() gives another profile's.
  Conventions conventions;
  CullMode cull = CullMode::kNone;  // TRI.CULL.MODE: pipeline state, not a convention
  MultisampleState msaa;            // SCENE.MSAA; default: one sample at the centre
  Rgba8 clear_color = {0, 0, 0, 0}; // the samples' value before any primitive
  std::vector<Primitive> primitives;
  // The pipeline state (SCENE.PIPELINE); absent or empty: not asked for.
  std::optional<pipe::Viewport> viewport; // default: the whole target, depth [0, 1]
  std::optional<pipe::Mat4f> model, view, projection;
  std::optional<pipe::DepthState> depth; // no depth test without it
  std::vector<pipe::AttributeDecl> attributes;
};

// Returns the triangle setup's state of a scene: its cull mode, front face and fill convention.
[[nodiscard]] inline RasterState raster_state(const Scene& scene) {
  return RasterState{scene.cull, scene.conventions.front_face, scene.conventions.fill};
}

// Sets a scene's cull mode, front face and fill convention from a triangle setup's state.
inline void set_raster_state(Scene& scene, const RasterState& state) {
  scene.cull = state.cull;
  scene.conventions.front_face = state.front_face;
  scene.conventions.fill = state.fill;
}

// Sets a scene's sample pattern and the conventions' pattern kind together (validate() and
// prepare() require them to agree: PROFILE.CONVENTIONS).
inline void set_sample_pattern(Scene& scene, SamplePattern pattern) {
  scene.conventions.pattern = pattern.kind;
  scene.msaa.pattern = std::move(pattern);
}

// Returns the path of the scene's first pipeline field (SCENE.PIPELINE) in the order of
// spec/scene.md ("viewport", "transform.model", ".view", ".projection", "depth", "attributes",
// then per primitive "primitives[i].pos", ".z", ".w", ".attr"), or nullopt when it has none:
// such a scene is drawn by coverage alone. The provoking vertex is a convention, not a stage:
// it changes nothing without flat attributes.
[[nodiscard]] std::optional<std::string> first_pipeline_field(const Scene& scene);
[[nodiscard]] inline bool has_pipeline_state(const Scene& scene) {
  return first_pipeline_field(scene).has_value();
}

// Returns a scene with the target, conventions, cull mode and sample state of scene, without
// primitives and without pipeline state: the window-space scene the pipeline draws into (the
// picture's grid, the resolve, the pipeline's internal scene of clipped parts).
[[nodiscard]] Scene target_of(const Scene& scene);

// The exact area coverage of a path fragment (PATH.AREA.EXACT), immutable and shared by
// copies of the fragment, compared by value; empty for every other fragment.
// rule: PATH.AREA.EXACT, SCENE.OUTPUT.AREA
class ExactArea {
public:
  ExactArea() = default;
  explicit ExactArea(std::shared_ptr<const path::AreaValue> value) : value_(std::move(value)) {}
  [[nodiscard]] explicit operator bool() const { return value_ != nullptr; }
  // The area in px^2 as a reduced fraction, "num/den", or "num" when it is an integer.
  [[nodiscard]] std::string text() const;
  // The bound of the area's error in px^2 as a reduced fraction, "num/den" (paths with curves,
  // PATH.AREA.CURVE), or "" when the area is exact.
  [[nodiscard]] std::string bound_text() const;
  // The area as 8-bit alpha, as 2D libraries store coverage: floor(area * 255 + 1/2).
  [[nodiscard]] std::uint8_t alpha() const;
  // The area rounded to the nearest double.
  [[nodiscard]] double approx() const;
  // The value, for rastrules/path.hpp's users (null when empty).
  [[nodiscard]] const path::AreaValue* get() const { return value_.get(); }
  friend bool operator==(const ExactArea& a, const ExactArea& b);

private:
  std::shared_ptr<const path::AreaValue> value_;
};

// One covered pixel of one primitive. mask has bit i set for covered sample i; without
// multisampling the only sample is the pixel centre, so mask == 1. Antialiased line
// fragments carry their coverage (coverage_q16 / 65536, SCENE.OUTPUT.COVERAGE); line strip
// fragments carry the index of the segment that produced them (SCENE.PRIM.LINE_STRIP).
// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.COVERAGE, SCENE.PRIM.LINE_STRIP
struct Fragment {
  Fragment() = default;
  // Brace forms {prim, x, y}, {prim, x, y, mask}, ... keep working without naming the
  // optional fields.
  constexpr Fragment(std::uint32_t prim_, std::int32_t x_, std::int32_t y_, std::uint32_t mask_ = 1,
                     std::optional<std::uint32_t> seg_ = std::nullopt,
                     std::optional<std::uint32_t> coverage_q16_ = std::nullopt)
      : prim(prim_), x(x_), y(y_), mask(mask_), seg(seg_), coverage_q16(coverage_q16_) {}

  std::uint32_t prim = 0;
  std::int32_t x = 0;
  std::int32_t y = 0;
  std::uint32_t mask = 1;
  std::optional<std::uint32_t> seg;          // line strips only
  std::optional<std::uint32_t> coverage_q16; // antialiased lines only, in [1, 65536]
  // Multisampling (SCENE.OUTPUT.MSAA). mask is the coverage ANDed with the sample mask
  // (MSAA.MASK.AND). A helper lane (MSAA.QUAD.HELPER) has helper == true and mask == 0.
  // Under sample-frequency shading each fragment is one sample: sample == i, mask == 1 << i
  // (0 for a helper). centroid: present when the scene asks for a centroid rule.
  // derivatives: present when the scene asks for derivatives.
  bool helper = false;
  std::optional<std::uint32_t> sample;
  std::optional<Centroid> centroid;
  std::optional<EvalDerivatives> derivatives;
  // A path with "coverage": "area" (SCENE.OUTPUT.AREA): the pixel's exact covered area; mask is
  // then every sample of the pattern that the sample mask keeps.
  ExactArea area;
  friend bool operator==(const Fragment&, const Fragment&) = default;
};

// The order of SCENE.OUTPUT.FRAGMENTS: (prim, y, x, seg, sample), a missing seg or sample first.
[[nodiscard]] bool fragment_before(const Fragment& a, const Fragment& b);

// A rejected scene: the JSON-pointer-like path of the offending field and what is wrong.
struct SceneError {
  // Bad input, or a limit of SCENE.INPUT.LIMITS that the caller may raise (the command line
  // adds how: --max-work, --max-fragments).
  enum class Kind { kInput, kWorkLimit, kFragmentLimit };
  std::string field;   // e.g. "primitives[3].v[1][0]"
  std::string message; // e.g. "is NaN"
  Kind kind = Kind::kInput;
  [[nodiscard]] std::string what() const { return field + ": " + message; }
};

// A triangle the scene draws: a triangle primitive, one half of a point's square, or one half
// of a quadrilateral line segment (seg is the segment index within its primitive).
struct PreparedTriangle {
  TriangleSetup setup;
  std::uint32_t seg = 0;
};

// One primitive after validation and snapping.
struct PreparedPrimitive {
  PrimitiveType type = PrimitiveType::kTriangle;
  bool aa = false;
  Rgba8 color = {255, 255, 255, 255};
  std::vector<Vec2> v; // snapped vertices
  // The triangles drawn for it: the triangle itself; the point's two (SCENE.PRIM.POINT); two
  // per segment of a quadrilateral line (LineMode kQuadWide/kQuadNarrow, and kD3DDiamond lines,
  // aliased or antialiased, with more than one sample: MSAA.LINE.MODE). Empty for the other
  // aliased and antialiased lines, which the line rasterizers draw from v.
  std::vector<PreparedTriangle> triangles;
  // A path primitive (type kPath, v empty): its snapped path and the coverage it asks for.
  std::shared_ptr<const path::Path> path;
  path::Coverage coverage = path::Coverage::kSamples;
};

// The scene after validation and snapping.
struct PreparedScene {
  std::int32_t width = 0;
  std::int32_t height = 0;
  Conventions conventions;
  RasterState state; // the triangle setup's view: the scene's cull mode, fill and front face
  MultisampleState msaa;
  Rgba8 clear_color = {0, 0, 0, 0};
  std::vector<PreparedPrimitive> primitives;
};

// Returns the prepared scene, or the first error in field order. Checks
// SCENE.TARGET.LIMITS, the vertex count of each primitive type, "aa" only on lines with
// line_mode d3d, snaps every vertex (SNAP.VERTEX.INVALID rejects NaN, infinities and
// out-of-range coordinates) and checks point positions against the point range
// [kMinPointRaw, kMaxPointRaw] (SCENE.PRIM.POINT).
// rule: SCENE.TARGET.LIMITS, SNAP.VERTEX.INVALID, SCENE.PRIM.POINT
// rule: SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP, SCENE.LINE_MODE
[[nodiscard]] std::variant<PreparedScene, SceneError> prepare(const Scene& scene);

// Returns the fragments of primitive p of a prepared scene sorted by (y, x, seg, sample), only
// inside the target. Preconditions: p < scene.primitives.size().
// rule: SCENE.OUTPUT.FRAGMENTS, RASTER.TARGET.CLIP
[[nodiscard]] std::vector<Fragment> rasterize_primitive(const PreparedScene& scene, std::size_t p);
// The same with the traversal and instruction set of options (options.threads is not used:
// one primitive is rasterized by the calling thread). Equal results for all options
// (FAST.EQUALS.PLAIN, FAST.ISA.DISPATCH).
// rule: FAST.EQUALS.PLAIN
[[nodiscard]] std::vector<Fragment> rasterize_primitive(const PreparedScene& scene, std::size_t p,
                                                        const RenderOptions& options);

// Calls emit for each fragment of primitive p in (y, x, seg, sample) order, as
// rasterize_primitive returns them. In a single-sample scene (one sample at the centre, full
// mask, pixel shading, no centroid, no quads) a triangle's fragments are streamed as the
// traversal finds them (memory does not grow with their number); a point's, a line's, a line
// strip's and every primitive's of a multisampled scene are collected and sorted first (memory
// proportional to that one primitive's fragments).
// rule: SCENE.OUTPUT.FRAGMENTS
void for_each_fragment(const PreparedScene& scene, std::size_t p,
                       const std::function<void(const Fragment&)>& emit);
void for_each_fragment(const PreparedScene& scene, std::size_t p, const RenderOptions& options,
                       const std::function<void(const Fragment&)>& emit);

// for_each_fragment with a bound on memory: a primitive whose fragments are collected and
// sorted before they are emitted (everything but a single-sample triangle, which is streamed)
// may hold at most max_collected entries: fragments, helper lanes, and for a multisampled
// primitive also the pixels it touches (a point's or quadrilateral segment's pixel once per
// triangle). When primitive p needs more, nothing of it is emitted and false is returned.
// Held memory is then at most about 200 bytes per entry (fragments, touched pixels and, with
// quads, their lane, quad and derivative maps).
// rule: SCENE.INPUT.LIMITS
[[nodiscard]] bool for_each_fragment_bounded(const PreparedScene& scene, std::size_t p,
                                             std::uint64_t max_collected,
                                             const std::function<void(const Fragment&)>& emit);
[[nodiscard]] bool for_each_fragment_bounded(const PreparedScene& scene, std::size_t p,
                                             std::uint64_t max_collected,
                                             const RenderOptions& options,
                                             const std::function<void(const Fragment&)>& emit);

// Whether primitive p is streamed as the traversal finds it (a triangle of a single-sample
// scene): for_each_fragment holds nothing of it, and its rows can be drawn apart.
// rule: SCENE.INPUT.LIMITS
[[nodiscard]] bool is_streamed(const PreparedScene& scene, std::size_t p);

// The pixels of the target a walk of streamed primitive p visits: rows [y0, y1], columns
// [x0, x1], inclusive (empty when y1 < y0: degenerate, culled or outside the target).
struct PixelBounds {
  std::int32_t x0 = 0, y0 = 0, x1 = -1, y1 = -1;
};
[[nodiscard]] PixelBounds streamed_bounds(const PreparedScene& scene, std::size_t p);

// Calls emit for the fragments of streamed primitive p in the rows [y_first, y_last], in the
// order for_each_fragment emits them: the fragments of consecutive row ranges, concatenated,
// are for_each_fragment's (FAST.THREADS.DETERMINISTIC splits a large triangle this way).
// Preconditions: is_streamed(scene, p).
// rule: FAST.THREADS.DETERMINISTIC, FAST.EQUALS.PLAIN
void for_each_fragment_in_rows(const PreparedScene& scene, std::size_t p, std::int32_t y_first,
                               std::int32_t y_last, const RenderOptions& options,
                               const std::function<void(const Fragment&)>& emit);

// The default work limit of a render (SCENE.INPUT.LIMITS): most sample tests the plain
// traversal may make, summed over the primitives (primitive_work).
inline constexpr std::uint64_t kDefaultMaxWork = std::uint64_t{1} << 36; // 68719476736

// The most segments one path may have (SCENE.INPUT.LIMITS).
inline constexpr std::size_t kMaxPathSegments = std::size_t{1} << 20;

// The work of a path, in sample tests (SCENE.INPUT.LIMITS, primitive_work): a line piece's
// crossing of a sample row, a curve's exact crossings of one, one exact rational operation of
// the area rasterizer and one pixel's exact area, each measured against the plain triangle
// walk's sample test (about 1.75 ns).
inline constexpr std::uint64_t kPathPieceWork = 16;
inline constexpr std::uint64_t kPathCurveWork = 256;
inline constexpr std::uint64_t kPathAreaWork = 32;
inline constexpr std::uint64_t kPathAreaPixelWork = 512;

// Returns the work of primitive p by the plain definition, known before it is rasterized: for
// each triangle it draws (RASTER.WALK.BBOX), the pixels of its walk bounds clipped to the
// target, times the samples tested per pixel (1 in a single-sample scene, else the pattern's
// count); for each segment the line rasterizers draw, 16 times the columns plus the rows
// (each clipped to the target) of its bounding box widened by 2 pixels, which bound their
// per-row and per-column walks (a step costs about 16 sample tests). It depends on the scene alone:
// equal for every traversal, instruction set and thread count. Preconditions: p <
// scene.primitives.size().
// rule: SCENE.INPUT.LIMITS
[[nodiscard]] std::uint64_t primitive_work(const PreparedScene& scene, std::size_t p);

// Returns the first primitive at which the sum of primitive_work in primitive order passes
// max_work, or nullopt when the whole scene's work is within it.
// rule: SCENE.INPUT.LIMITS
[[nodiscard]] std::optional<std::size_t> first_primitive_over_work(const PreparedScene& scene,
                                                                   std::uint64_t max_work);

// Returns what is wrong with the primitive at which a scene's work passes max_work: "brings
// the work to more than N sample tests (limit SCENE.INPUT.LIMITS)", the one wording of this
// limit for every caller.
// rule: SCENE.INPUT.LIMITS
[[nodiscard]] std::string work_limit_problem(std::uint64_t max_work);

// Streams a prepared scene's fragments as `rastrules render` does on one thread: the work limit
// checked before any primitive is drawn, then each primitive's fragments in output order
// (for_each_fragment_bounded, a primitive held to be sorted at most 2 * max_fragments entries),
// at most max_fragments in all (emit is not called for the one beyond). Returns the first
// limit passed, as a SceneError of kind kWorkLimit or kFragmentLimit whose field is empty and
// whose message names the primitive ("primitives[3] brings the work to ...", "more than N
// fragments (limit SCENE.INPUT.LIMITS)", "primitives[3] touches more than ..."), or nullopt.
// The C API and the Python module draw window-space scenes with it.
// rule: SCENE.INPUT.LIMITS, SCENE.OUTPUT.FRAGMENTS
[[nodiscard]] std::optional<SceneError>
stream_within_limits(const PreparedScene& scene, std::uint64_t max_fragments,
                     std::uint64_t max_work, const std::function<void(const Fragment&)>& emit);

// Returns the fragments of a prepared scene sorted by (prim, y, x, seg, sample), only inside the
// target.
// rule: SCENE.OUTPUT.FRAGMENTS, RASTER.TARGET.CLIP
[[nodiscard]] std::vector<Fragment> rasterize(const PreparedScene& scene);
// The same with options: primitives are rasterized by options.threads threads and the result
// is identical for every thread count (FAST.THREADS.DETERMINISTIC).
// rule: FAST.THREADS.DETERMINISTIC
[[nodiscard]] std::vector<Fragment> rasterize(const PreparedScene& scene,
                                              const RenderOptions& options);

// A resolved target: one RGBA8 value per pixel, row-major, y down.
struct ResolvedImage {
  std::int32_t width = 0;
  std::int32_t height = 0;
  std::vector<Rgba8> pixels;
};

// The largest width * height * samples resolve() accepts (a 256 MiB sample buffer).
// rule: MSAA.LIMITS
inline constexpr std::int64_t kMaxResolveSamples = std::int64_t{1} << 26;

// Returns what is wrong with resolving a width x height target of n samples ("the 8192x8192
// target with 4 samples has 268435456 samples, more than 67108864 (limit MSAA.LIMITS)"), or
// nothing: the one wording of the limit, for resolve(), Resolver and the command line.
// rule: MSAA.LIMITS
[[nodiscard]] std::optional<std::string> resolve_size_problem(std::int32_t width,
                                                              std::int32_t height, std::uint32_t n);

// Writes each fragment's primitive colour to its covered samples (fragments of helper lanes
// write nothing) in fragment order, over samples cleared to clear_color, then resolves every
// pixel with resolve_pixel(). No blending: the coverage of antialiased lines is not applied.
// Returns an error naming the limit when width * height * samples > kMaxResolveSamples.
// rule: MSAA.RESOLVE.AVERAGE
[[nodiscard]] std::variant<ResolvedImage, SceneError>
resolve(const PreparedScene& scene, const std::vector<Fragment>& fragments);

// resolve() one fragment at a time, for fragments streamed as they are found: memory is the
// target's samples (4 bytes each, at most kMaxResolveSamples), whatever the fragment count.
// The scene must outlive the resolver.
// rule: MSAA.RESOLVE.AVERAGE, MSAA.LIMITS
class Resolver {
public:
  // Returns the resolver, or resolve()'s error for a target beyond kMaxResolveSamples.
  [[nodiscard]] static std::variant<Resolver, SceneError> start(const PreparedScene& scene);
  // Writes fragment f, the index-th, to the samples; an error names a primitive or pixel
  // outside the scene.
  [[nodiscard]] std::optional<SceneError> add(const Fragment& f, std::size_t index);
  // Resolves every pixel (resolve_pixel()).
  [[nodiscard]] ResolvedImage finish() const;

private:
  explicit Resolver(const PreparedScene& scene);
  const PreparedScene* scene_;
  std::vector<Rgba8> samples_;
};

// Returns the fragments of the scene: prepare() then rasterize() for a scene without pipeline
// state (the identity case of the pipeline, and its only cost), else the fragments of
// rastrules::pipe::run_pipeline() with no fragment limit (PIPE.EFFECTS.ON_DEMAND).
// rule: PIPE.EFFECTS.ON_DEMAND
[[nodiscard]] std::variant<std::vector<Fragment>, SceneError> render(const Scene& scene);
[[nodiscard]] std::variant<std::vector<Fragment>, SceneError> render(const Scene& scene,
                                                                     const RenderOptions& options);

} // namespace rastrules

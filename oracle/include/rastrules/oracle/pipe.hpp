// SPDX-License-Identifier: MIT
// The pipeline around the rules (spec/rules/pipe.md) written a second time, for machines:
// exact, slow, independent. Every value is an exact GMP rational; the float32 and double
// formulas the spec prescribes (transforms, divide and viewport, the clip volume, the clipper)
// are evaluated as exact rationals rounded to the nearest float32 / double (ties to even) after
// each operation, by the oracle's own rounding function, not by the hardware. It never includes
// or calls kernel code and shares none of its types: everything is plain integers, floats and
// strings spelled as in the spec ("d16", "less", ...).
// Implements (as oracle): PIPE.TRANSFORM.FLOAT32, PIPE.CLIP.VOLUME, PIPE.CLIP.POLYGON,
//   PIPE.CLIP.COMPUTE, PIPE.CLIP.GUARD_BAND_BOUND, PIPE.VIEWPORT.TRANSFORM, PIPE.VIEWPORT.SCISSOR,
//   PIPE.BARY.EXACT, PIPE.BARY.SUM, PIPE.INTERP.PERSPECTIVE, PIPE.INTERP.LINEAR,
//   PIPE.INTERP.FLAT, PIPE.INTERP.HORIZON, PIPE.INTERP.BOUND, PIPE.DEPTH.INTERP,
//   PIPE.DEPTH.CLAMP, PIPE.DEPTH.FORMAT, PIPE.DEPTH.BOUND, PIPE.DEPTH.TEST

#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rastrules::oracle::pipe {

// A position in raw 16.8 units (1/256 px), y down.
using Raw2 = std::array<std::int64_t, 2>;
using Vec4 = std::array<float, 4>;  // x, y, z, w
using Mat4 = std::array<float, 16>; // row-major, acting on column vectors

// ---------------------------------------------------------------------------------------------
// Rounding (the oracle's own, from exact rationals)

// fl32 and fl64 of the exact product, quotient, sum of two floats / doubles, by exact rational
// arithmetic and round to nearest, ties to even (overflow gives an infinity). Exposed so that
// tests can compare them with the hardware's.
float fl32_mul(float a, float b);
float fl32_add(float a, float b);
float fl32_div(float a, float b);
double fl64_mul(double a, double b);
double fl64_add(double a, double b);
double fl64_div(double a, double b);
// The float32 nearest to the double d (ties to even; beyond the range: an infinity).
float nearest_float(double d);

// The spacing of float32 at x (PIPE.INTERP.BOUND): 2^(e - 23) for 2^e <= |x| < 2^(e + 1),
// at least 2^-149. Returned as a double (exact: every such power of two is a double).
double ulp32(double x);

// ---------------------------------------------------------------------------------------------
// Input, transforms, viewport (float32 formulas of the spec)

// rule: PIPE.TRANSFORM.FLOAT32
Vec4 transform(const Mat4& m, const Vec4& v);

struct Viewport {
  float x = 0.0f, y = 0.0f, width = 0.0f, height = 0.0f;
  float min_depth = 0.0f, max_depth = 1.0f;
};

struct WindowVertex {
  float x = 0.0f, y = 0.0f, z = 0.0f, w = 1.0f;
};

// rule: PIPE.VIEWPORT.TRANSFORM
WindowVertex to_window(const Vec4& p, const Viewport& vp);

// Pixels [x0, x1) x [y0, y1) of the implicit viewport scissor.
struct Rect {
  std::int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
// rule: PIPE.VIEWPORT.SCISSOR
Rect viewport_scissor(const Viewport& vp);

// ---------------------------------------------------------------------------------------------
// Clipping (PIPE.CLIP.*): the double / float32 formulas of the spec

inline constexpr double kGuardBand = 31744.0; // px
inline constexpr int kWMinLog2 = -126; // the w plane: w >= 2^-126 (float32's smallest normal)

struct Volume {
  double w_min = 0.0;
  double gx_lo = -1.0, gx_hi = 1.0, gy_lo = -1.0, gy_hi = 1.0;
  bool depth_clip = true;
};

// rule: PIPE.CLIP.VOLUME
Volume clip_volume(const std::vector<Vec4>& vs, const Viewport& vp, bool depth_clip);

// Whether every plane's fl64 distance is >= 0.
bool inside(const Volume& vol, const Vec4& p);

struct ClipVertex {
  Vec4 pos{};
  std::vector<float> attr;
};

// Sutherland-Hodgman over the planes in spec order (w, x_lo, x_hi, y_lo, y_hi, z_near,
// z_far), each intersection computed from the inside endpoint I towards the outside one O as
// I + t (O - I), t = d_I / (d_I - d_O), in fl64. Vertices stay doubles from plane to plane and
// are rounded to float32 once, when the polygon is complete (PIPE.CLIP.COMPUTE: "rounded once").
// No duplicate removal; fewer than 3 vertices (no fan triangle) give an empty result.
// rule: PIPE.CLIP.POLYGON, PIPE.CLIP.COMPUTE
std::vector<ClipVertex> clip_polygon(const std::vector<ClipVertex>& polygon, const Volume& vol);

// The segment (a, b) cut at the same planes in the same order with the same intersection as
// clip_polygon (from the inside endpoint, doubles between planes, rounded once); nullopt when a
// plane has both endpoints outside.
// rule: PIPE.CLIP.LINE
std::optional<std::array<ClipVertex, 2>> clip_segment(const ClipVertex& a, const ClipVertex& b,
                                                      const Volume& vol);

// The fields of a viewport that violate PIPE.VIEWPORT.RANGE, decided exactly (x + width and
// y + height as exact sums): "x" or "y" out of [-32768, 32767] or not finite; "width" or
// "height" not finite or not > 0; "x" and "width" (either may be named) when x + width is out of
// [-32768, 32767], the same for y; "min_depth" or "max_depth" out of [0, 1]; both when
// min_depth > max_depth. Empty when the viewport is valid.
// rule: PIPE.VIEWPORT.RANGE
std::vector<std::string> viewport_violations(const Viewport& vp);

// ---------------------------------------------------------------------------------------------
// Exact projection and the exact clipper (PIPE.CLIP.GUARD_BAND_BOUND)

// The exact window position of a clip-space vertex: X = (x/w + 1) W/2 + X0, Y = (1 - y/w) H/2
// + Y0, Z = MinDepth + z/w (MaxDepth - MinDepth), all exact; X and Y snapped to 1/256 with
// round half to even, without range limit. Doubles are the nearest to the exact values; raw
// is nullopt when the snapped value does not fit in int64.
struct ExactWindow {
  double x = 0.0, y = 0.0, z = 0.0;
  std::optional<std::int64_t> raw_x, raw_y;
};
// Precondition: p[3] > 0.
ExactWindow project_exact(const Vec4& p, const Viewport& vp);

// The integer nearest to v * 256, ties to even, exactly and without range limit (nullopt only
// when it does not fit in int64, or v is not finite).
std::optional<std::int64_t> snap_unbounded(double v);

// A convex region of the window plane given by exact rational vertices (raw 16.8 units, not
// necessarily integers), for deciding which samples it covers away from its edges.
class ExactRegion {
public:
  enum class Side { kInside, kOutside, kNear };

  // The unclipped triangle of PIPE.CLIP.GUARD_BAND_BOUND: the clip-space vertices (each with
  // w > 0) projected exactly and snapped to 1/256 without range limit.
  static ExactRegion unclipped_triangle(const std::array<Vec4, 3>& clip, const Viewport& vp);
  // The triangle clipped exactly (rational Sutherland-Hodgman against the same planes as
  // clip_polygon, the planes' coefficients being vol's doubles taken exactly), then projected
  // exactly (not snapped).
  static ExactRegion clipped_polygon(const std::array<Vec4, 3>& clip, const Volume& vol,
                                     const Viewport& vp);

  ExactRegion(const ExactRegion&);
  ExactRegion& operator=(const ExactRegion&);
  ExactRegion(ExactRegion&&) noexcept;
  ExactRegion& operator=(ExactRegion&&) noexcept;
  ~ExactRegion();

  // kNear: within `near_raw` raw units (exactly, Euclidean distance, closed) of an edge segment;
  // otherwise kInside when strictly inside a region of nonzero area, else kOutside.
  [[nodiscard]] Side classify(const Raw2& sample, std::int64_t near_raw) const;
  // Where each edge (v_i, v_i+1) lies: 0, 1, 2 on the original triangle's edge (v0 v1),
  // (v1 v2), (v2 v0); -1 - p on clip plane p (0 .. 6 in spec order: w, x_lo, x_hi, y_lo, y_hi,
  // z_near, z_far).
  [[nodiscard]] const std::vector<int>& edge_origins() const;
  // Whether the sample lies within near_raw raw units of edge i (closed, exactly).
  [[nodiscard]] bool near_edge(const Raw2& sample, std::int64_t near_raw, std::size_t i) const;
  // Whether the region has nonzero area and the sample lies strictly inside it.
  [[nodiscard]] bool strictly_inside(const Raw2& sample) const;
  // The bounding box in raw units, rounded outward to integers: {x0, y0, x1, y1}.
  [[nodiscard]] std::array<std::int64_t, 4> bounds_raw() const;
  // The vertices in pixels (nearest doubles), for messages.
  [[nodiscard]] std::vector<std::array<double, 2>> vertices_px() const;
  // The number of vertices (repeated ones included).
  [[nodiscard]] std::size_t size() const;

private:
  struct Impl;
  explicit ExactRegion(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// ---------------------------------------------------------------------------------------------
// Barycentrics (PIPE.BARY.*)

struct Bary {
  std::array<std::int64_t, 3> e{};
  std::int64_t area = 0;
  friend bool operator==(const Bary&, const Bary&) = default;
};

// e0 = E_{v1 v2}(s), e1 = E_{v2 v0}(s), e2 = E_{v0 v1}(s), area = E_{v0 v1}(v2), computed with
// exact integers (throws std::logic_error when a value does not fit in int64).
// rule: PIPE.BARY.EXACT
Bary barycentrics(const std::array<Raw2, 3>& v, const Raw2& s);

// Whether s lies in the closed triangle (every e_i has the sign of the area or is zero;
// false for a degenerate triangle).
bool inside_closed(const Bary& b);

// ---------------------------------------------------------------------------------------------
// Interpolation (PIPE.INTERP.*)

// The exact values (nearest doubles). Perspective: sum(e_i a_i / w_i) / sum(e_i / w_i) with
// exact 1/w_i; nullopt when the denominator times the sign of the area is <= 0 (the horizon).
// Linear: sum(e_i a_i) / area. Preconditions: area != 0, w_i != 0.
std::optional<double> perspective_exact(const Bary& b, const std::array<float, 3>& a,
                                        const std::array<float, 3>& w);
double linear_exact(const Bary& b, const std::array<float, 3>& a);

// The same values rounded once from the exact rationals to the nearest float32 (ties to even),
// +-FLT_MAX beyond the range (PIPE.INTERP.HORIZON's saturation): the exactly rounded values
// the fuzzer measures drivers against (FUZZ.VALUES.EXACT). nullopt at the horizon, as above.
std::optional<float> perspective_nearest32(const Bary& b, const std::array<float, 3>& a,
                                           const std::array<float, 3>& w);
float linear_nearest32(const Bary& b, const std::array<float, 3>& a);

// A kernel value checked against PIPE.INTERP.BOUND and PIPE.INTERP.HORIZON.
struct InterpCheck {
  bool ok = false;
  bool finite = true;        // got is neither NaN nor infinite
  bool inside = false;       // the evaluation point is in the closed triangle
  bool in_range = true;      // inside: got in [min a_i - bound, max a_i + bound] (exactly)
  bool horizon = false;      // exact denominator (times sign(area)) <= 0: flat value expected
  bool near_horizon = false; // |denominator| <= 2^-48 sum|e_i / w_i|: fl64 may decide either
                             // way, only finiteness is checked
  bool saturated = false;    // accepted as +-FLT_MAX because the bound reaches beyond it
  double exact = 0.0;        // x (nearest double; the flat value at the horizon)
  double bound = 0.0;        // ulp32(x) + 2^-48 S (nearest double)
  double s = 0.0;            // S of PIPE.INTERP.BOUND
  float got = 0.0f;
  [[nodiscard]] std::string describe() const;
};

// rule: PIPE.INTERP.PERSPECTIVE, PIPE.INTERP.HORIZON, PIPE.INTERP.BOUND
InterpCheck check_perspective(const Bary& b, const std::array<float, 3>& a,
                              const std::array<float, 3>& w, float flat, float got);
// rule: PIPE.INTERP.LINEAR, PIPE.INTERP.HORIZON, PIPE.INTERP.BOUND
InterpCheck check_linear(const Bary& b, const std::array<float, 3>& a, float got);

// The flat value of a primitive's vertex values under "first" or "last".
// rule: PIPE.INTERP.FLAT
float flat_value(const std::vector<float>& vertex_values, const std::string& provoking);

// ---------------------------------------------------------------------------------------------
// Depth (PIPE.DEPTH.*). Formats: "d16", "d24", "d32f".

// The exact screen-linear depth sum(e_i Z_i) / area (nearest double). Precondition: area != 0.
double depth_exact(const Bary& b, const std::array<float, 3>& z);

// A stored value: unorm for d16/d24, f for d32f.
struct Stored {
  std::uint32_t unorm = 0;
  float f = 0.0f;
  friend bool operator==(const Stored&, const Stored&) = default;
};

// The exactly rounded stored value of the exact depth sum(e_i Z_i) / area (not first rounded to
// a double): clamped, then stored as store_exact does. Precondition: area != 0.
// rule: PIPE.DEPTH.INTERP, PIPE.DEPTH.CLAMP, PIPE.DEPTH.FORMAT
Stored depth_stored_nearest(const Bary& b, const std::array<float, 3>& z, float min_depth,
                            float max_depth, const std::string& format);

// The exactly rounded stored value of an exact depth d (a double taken exactly): clamped to
// [min_depth, max_depth], then floor(d (2^n - 1) + 1/2) exactly, or the nearest float32 (ties
// to even).
// rule: PIPE.DEPTH.CLAMP, PIPE.DEPTH.FORMAT
Stored store_exact(double d, float min_depth, float max_depth, const std::string& format);

struct DepthCheck {
  bool ok = false;
  double exact = 0.0;   // sum(e_i Z_i) / area, before the clamp (nearest double)
  double clamped = 0.0; // after the clamp
  double bound = 0.0;   // 2^-50 S
  Stored expected;      // the exactly rounded value of `clamped`
  Stored lo, hi;        // the stored values allowed (inclusive range)
  double got_z = 0.0;   // check_depth_interp: the kernel's double
  Stored got;           // check_depth_stored: the kernel's stored value
  [[nodiscard]] std::string describe(const std::string& format) const;
};

// The kernel's interpolated depth (before the clamp) within 2^-50 S of the exact one.
// rule: PIPE.DEPTH.INTERP, PIPE.DEPTH.BOUND
DepthCheck check_depth_interp(const Bary& b, const std::array<float, 3>& z, double got);
// A stored value against PIPE.DEPTH.BOUND: UNORM within the roundings of values within
// 2^-50 S of x (which differ from the exactly rounded one by one, and only near a half-integer);
// d32f the nearest float of some value within 2^-50 S of x.
// rule: PIPE.DEPTH.BOUND, PIPE.DEPTH.CLAMP, PIPE.DEPTH.FORMAT
DepthCheck check_depth_stored(const Bary& b, const std::array<float, 3>& z, float min_depth,
                              float max_depth, const std::string& format, const Stored& got);

// The depth bias of PIPE.DEPTH.BIAS for a triangle with snapped vertices v (raw 16.8) and
// window depths z, format "d16", "d24", "d32f" or "" (no depth buffer: r of 24 bits). dZ/dx and
// dZ/dy are the exact plane derivatives (per pixel) rounded once to double (the spec's choice),
// MaxDepthSlope their larger magnitude rounded to float32 (0 for a degenerate triangle, where
// they do not exist); r = 1/(2^n - 1) rounded to float32, or 2^(exponent(max |Z_i|) - 23) for
// d32f with exponent(v) = max(floor(log2 v), -126) (the exponent field's value; -126 for 0 and
// subnormals); Bias = fl32(fl32(float(bias) * r) + fl32(slope_scaled * MaxDepthSlope)),
// clamped by clamp (min when > 0, max when < 0).
// rule: PIPE.DEPTH.BIAS
// +-FLT_MAX for an infinity, v otherwise (the saturation of PIPE.DEPTH.BIAS).
float sat32(float v);
float depth_bias(const std::array<Raw2, 3>& v, const std::array<float, 3>& z, std::int32_t bias,
                 float slope_scaled, float clamp, const std::string& format);

// The comparison of PIPE.DEPTH.TEST on stored values ("never", "less", ..., "always").
// rule: PIPE.DEPTH.TEST
bool depth_test(const std::string& func, const Stored& now, const Stored& old,
                const std::string& format);

} // namespace rastrules::oracle::pipe

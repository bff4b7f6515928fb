// SPDX-License-Identifier: MIT
// Scene validation, snapping and rasterization entry points.
// Implements: SCENE.TARGET.LIMITS, SNAP.VERTEX.INVALID, SCENE.OUTPUT.FRAGMENTS,
//             SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP, SCENE.LINE_MODE,
//             SCENE.OUTPUT.COVERAGE, SCENE.MSAA, SCENE.OUTPUT.MSAA, MSAA.LIMITS, MSAA.MASK.AND,
//             MSAA.POINT.PER_SAMPLE, MSAA.LINE.MODE, MSAA.SHADING.PIXEL, MSAA.SHADING.SAMPLE,
//             MSAA.QUAD.HELPER, MSAA.DERIV.FINE, MSAA.DERIV.COARSE, MSAA.RESOLVE.AVERAGE

#include "rastrules/scene.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>

#include "path_scene.hpp"
#include "rastrules/point.hpp"
#include "rastrules/raster/fast.hpp"
#include "rastrules/raster/walk.hpp"
#include "rastrules/raster/walk_msaa.hpp"

namespace rastrules {

Primitive make_triangle(const std::array<FloatPoint, 3>& v) {
  Primitive p;
  p.type = PrimitiveType::kTriangle;
  p.v.assign(v.begin(), v.end());
  return p;
}

Primitive make_path(FloatPath path) {
  Primitive p;
  p.type = PrimitiveType::kPath;
  p.v.clear();
  p.path = std::move(path);
  return p;
}

Primitive coverage_of(const Primitive& p) {
  Primitive out;
  out.type = p.type;
  out.v = p.v;
  out.aa = p.aa;
  out.color = p.color;
  out.path = p.path;
  return out;
}

// rule: SCENE.PIPELINE
std::optional<std::string> first_pipeline_field(const Scene& scene) {
  if (scene.viewport)
    return "viewport";
  if (scene.model)
    return "transform.model";
  if (scene.view)
    return "transform.view";
  if (scene.projection)
    return "transform.projection";
  if (scene.depth)
    return "depth";
  if (!scene.attributes.empty())
    return "attributes";
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    const Primitive& prim = scene.primitives[p];
    const char* key = !prim.pos.empty()    ? "pos"
                      : !prim.z.empty()    ? "z"
                      : !prim.w.empty()    ? "w"
                      : !prim.attr.empty() ? "attr"
                                           : nullptr;
    if (key != nullptr)
      return "primitives[" + std::to_string(p) + "]." + key;
  }
  return std::nullopt;
}

Scene target_of(const Scene& scene) {
  Scene out;
  std::tie(out.width, out.height, out.conventions, out.cull, out.msaa, out.clear_color) = std::tie(
      scene.width, scene.height, scene.conventions, scene.cull, scene.msaa, scene.clear_color);
  return out;
}

std::size_t required_vertex_count(PrimitiveType t) {
  switch (t) {
  case PrimitiveType::kTriangle:
    return 3;
  case PrimitiveType::kPoint:
    return 1;
  case PrimitiveType::kLine:
    return 2;
  case PrimitiveType::kLineStrip:
  case PrimitiveType::kPath:
    return 0;
  }
  return 0;
}

std::optional<std::string> vertex_count_problem(PrimitiveType t, std::size_t n, bool clip_space) {
  // rule: SCENE.PRIM.PATH
  if (t == PrimitiveType::kPath) {
    if (n == 0)
      return std::nullopt;
    return "a path takes no vertices (its points are in \"d\" or \"contours\"), got " +
           std::to_string(n);
  }
  const std::size_t need = required_vertex_count(t);
  if (need == 0 ? n >= 2 : n == need)
    return std::nullopt;
  const std::string count = need == 0   ? "at least 2 vertices"
                            : need == 1 ? "exactly 1 vertex"
                                        : "exactly " + std::to_string(need) + " vertices";
  return "a " + std::string(to_string(t)) + " must have " + count +
         (clip_space ? " [x, y, z] or [x, y, z, w]" : " [x, y]") + ", got " + std::to_string(n);
}

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.PRIM.LINE_STRIP, SCENE.OUTPUT.MSAA
bool fragment_before(const Fragment& a, const Fragment& b) {
  // A missing seg or sample (-1) sorts before every index.
  const std::int64_t sa = a.seg ? std::int64_t{*a.seg} : -1;
  const std::int64_t sb = b.seg ? std::int64_t{*b.seg} : -1;
  const std::int64_t ka = a.sample ? std::int64_t{*a.sample} : -1;
  const std::int64_t kb = b.sample ? std::int64_t{*b.sample} : -1;
  return std::tie(a.prim, a.y, a.x, sa, ka) < std::tie(b.prim, b.y, b.x, sb, kb);
}

namespace {

bool is_line(PrimitiveType t) {
  return t == PrimitiveType::kLine || t == PrimitiveType::kLineStrip;
}

bool is_quad(LineMode m) {
  return m == LineMode::kQuadWide || m == LineMode::kQuadNarrow;
}

std::string field_of(std::size_t p) {
  return "primitives[" + std::to_string(p) + "]";
}

// Returns whether lines of this scene are drawn as quadrilateral lines (two triangles per
// segment): the quadrilateral line modes, and the D3D line mode on a multisampled target with
// D3D's MultisampleEnable set.
// rule: SCENE.LINE_MODE, MSAA.LINE.MODE
bool lines_as_quads(const Conventions& c, bool aa, const MultisampleState& ms) {
  if (is_quad(c.line_mode))
    return !aa;
  return c.line_mode == LineMode::kD3DDiamond && ms.count() > 1 && c.multisample_enable;
}

std::string mask_hex(std::uint32_t m) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string out = "0x";
  for (int shift = 28; shift >= 0; shift -= 4)
    out += kDigits[(m >> shift) & 0xFu];
  return out;
}

// Returns the first error of the multisample state in field order (MSAA.LIMITS).
// rule: MSAA.LIMITS, SCENE.MSAA, MSAA.LINE.MODE, MSAA.SHADING.SAMPLE
std::optional<SceneError> validate_msaa(const Scene& scene) {
  const MultisampleState& ms = scene.msaa;
  const SamplePattern& pat = ms.pattern;
  const std::uint32_t n = pat.count();
  // PROFILE.CONVENTIONS: the pattern is of the kind the conventions name.
  if (pat.kind != scene.conventions.pattern) {
    return SceneError{"sample_pattern", "is a \"" + std::string(to_string(pat.kind)) +
                                            "\" pattern but conventions.pattern is \"" +
                                            std::string(to_string(scene.conventions.pattern)) +
                                            "\""};
  }
  switch (pat.kind) {
  case PatternKind::kStandard:
  case PatternKind::kCenter: {
    if (!is_standard_count(n)) {
      return SceneError{"samples", std::to_string(n) + " has no " +
                                       std::string(to_string(pat.kind)) +
                                       " pattern (1, 2, 4, 8, 16)"};
    }
    const SamplePattern want =
        pat.kind == PatternKind::kCenter ? center_pattern(n) : standard_pattern(n);
    if (pat.positions != want.positions) {
      return SceneError{"sample_pattern", "positions differ from the " +
                                              std::string(to_string(pat.kind)) + " pattern of " +
                                              std::to_string(n) + " samples"};
    }
    break;
  }
  case PatternKind::kCustom:
    if (n < 1 || n > kMaxSamples) {
      return SceneError{"sample_pattern", "must list 1 to " + std::to_string(kMaxSamples) +
                                              " positions, got " + std::to_string(n)};
    }
    for (std::size_t k = 0; k < n; ++k) {
      const SampleOffset o = pat.positions[k];
      const std::int32_t c[2] = {o.x, o.y};
      for (std::size_t a = 0; a < 2; ++a) {
        if (c[a] < kSampleGridMin || c[a] > kSampleGridMax) {
          return SceneError{"sample_pattern[" + std::to_string(k) + "][" + std::to_string(a) + "]",
                            "must be an integer in [" + std::to_string(kSampleGridMin) + ", " +
                                std::to_string(kSampleGridMax) + "] (1/16 px), got " +
                                std::to_string(c[a])};
        }
      }
    }
    break;
  default:
    return SceneError{"sample_pattern", "unknown pattern kind"};
  }
  // rule: MSAA.MASK.AND, MSAA.LIMITS
  // 0xFFFFFFFF is the default "all samples"; any other value must fit the pattern.
  if (ms.sample_mask != 0xFFFFFFFFu && (ms.sample_mask & ~full_mask(n)) != 0u) {
    return SceneError{"sample_mask", "must be an integer in [0, " + std::to_string(full_mask(n)) +
                                         "] (bit k is sample k of " + std::to_string(n) +
                                         "), got " + std::to_string(ms.sample_mask) + " (" +
                                         mask_hex(ms.sample_mask) + ")"};
  }
  if (ms.has_centroid && scene.conventions.centroid != CentroidRule::kD3D11 &&
      scene.conventions.centroid != CentroidRule::kD3D10) {
    return SceneError{"centroid", "must be one of \"d3d11\", \"d3d10\""};
  }
  if (ms.shading != ShadingRate::kPixel && ms.shading != ShadingRate::kSample) {
    return SceneError{"shading", "must be one of \"pixel\", \"sample\""};
  }
  if (ms.derivatives != DerivativeMode::kNone && ms.derivatives != DerivativeMode::kFine &&
      ms.derivatives != DerivativeMode::kCoarse) {
    return SceneError{"derivatives", "must be one of \"fine\", \"coarse\""};
  }
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    const Primitive& prim = scene.primitives[p];
    // rule: SCENE.PRIM.PATH
    if (prim.type == PrimitiveType::kPath) {
      const char* asked = ms.has_centroid                     ? "centroid"
                          : ms.shading != ShadingRate::kPixel ? "shading"
                          : ms.quads                          ? "quads"
                          : ms.wants_quads()                  ? "derivatives"
                                                              : nullptr;
      if (asked != nullptr) {
        return SceneError{asked, "a path is drawn by coverage alone: \"" + std::string(asked) +
                                     "\" cannot be asked for with a path (" + field_of(p) + ")"};
      }
      continue;
    }
    if (!is_line(prim.type) || n <= 1)
      continue;
    // rule: MSAA.SHADING.SAMPLE
    if (ms.shading == ShadingRate::kSample &&
        scene.conventions.line_mode == LineMode::kVulkanBresenham) {
      return SceneError{"shading", "\"sample\" shading is undefined for \"vulkan-bresenham\" "
                                   "lines with more than one sample (" +
                                       field_of(p) + " is a " + std::string(to_string(prim.type)) +
                                       ")"};
    }
    // rule: MSAA.LINE.MODE
    if (pat.kind == PatternKind::kCenter && lines_as_quads(scene.conventions, prim.aa, ms)) {
      return SceneError{"sample_pattern", "a \"center\" pattern of " + std::to_string(n) +
                                              " samples cannot draw quadrilateral lines (" +
                                              field_of(p) + " is a " +
                                              std::string(to_string(prim.type)) + ")"};
    }
  }
  return std::nullopt;
}

} // namespace

// rule: SCENE.TARGET.LIMITS, SNAP.VERTEX.INVALID, SCENE.PRIM.POINT
// rule: SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP, SCENE.LINE_MODE
std::variant<PreparedScene, SceneError> prepare(const Scene& scene) {
  // rule: SCENE.TARGET.LIMITS
  if (scene.width < 1 || scene.width > kMaxTargetSide) {
    return SceneError{"target.width", "must be an integer in [1, " +
                                          std::to_string(kMaxTargetSide) + "], got " +
                                          std::to_string(scene.width)};
  }
  if (scene.height < 1 || scene.height > kMaxTargetSide) {
    return SceneError{"target.height", "must be an integer in [1, " +
                                           std::to_string(kMaxTargetSide) + "], got " +
                                           std::to_string(scene.height)};
  }
  // rule: MSAA.LIMITS
  if (auto err = validate_msaa(scene))
    return *err;
  PreparedScene out;
  std::tie(out.width, out.height, out.conventions, out.msaa, out.clear_color) =
      std::tie(scene.width, scene.height, scene.conventions, scene.msaa, scene.clear_color);
  out.state = raster_state(scene);
  out.primitives.reserve(scene.primitives.size());
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    const Primitive& in = scene.primitives[p];
    const std::size_t n = in.v.size();
    // rule: SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP
    if (auto bad = vertex_count_problem(in.type, n, false))
      return SceneError{field_of(p) + ".v", std::move(*bad)};
    // rule: SCENE.PRIM.PATH
    if (in.path.has_value() != (in.type == PrimitiveType::kPath)) {
      return SceneError{field_of(p) + ".path",
                        in.path ? "only a path primitive takes a path, not a " +
                                      std::string(to_string(in.type))
                                : std::string("is missing: a path primitive needs its path")};
    }
    // rule: SCENE.PRIM.LINE, SCENE.LINE_MODE
    if (in.aa && !is_line(in.type)) {
      return SceneError{field_of(p) + ".aa", "only lines and line strips take \"aa\", not a " +
                                                 std::string(to_string(in.type))};
    }
    if (in.aa && scene.conventions.line_mode != LineMode::kD3DDiamond) {
      return SceneError{field_of(p) + ".aa",
                        "antialiased lines need line_mode \"d3d\" (the D3D reference algorithm)"};
    }
    PreparedPrimitive prim;
    prim.type = in.type;
    prim.aa = in.aa;
    prim.color = in.color;
    // rule: SCENE.PRIM.PATH
    if (in.path) {
      if (auto err = detail::prepare_path(*in.path, p, prim))
        return *err;
    }
    prim.v.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      Subpixel c[2];
      for (std::size_t k = 0; k < 2; ++k) {
        // The field's name is built only for an error (one string per coordinate was a fifth
        // of prepare()'s time on a million small triangles).
        const auto field = [&] {
          return field_of(p) + ".v[" + std::to_string(i) + "][" + std::to_string(k) + "]";
        };
        // rule: SNAP.VERTEX.INVALID
        const SnapResult s = snap_to_subpixel(in.v[i][k]);
        if (s.status != SnapStatus::kOk) {
          return SceneError{field(), std::string("is ") + std::string(to_string(s.status))};
        }
        // rule: SCENE.PRIM.POINT
        if (in.type == PrimitiveType::kPoint &&
            (s.value.raw() < kMinPointRaw || s.value.raw() > kMaxPointRaw)) {
          return SceneError{field(),
                            "is outside the point range [" + std::to_string(kMinPointRaw) + ", " +
                                std::to_string(kMaxPointRaw) +
                                "] / 256 (the point's square must fit in the vertex range)"};
        }
        c[k] = s.value;
      }
      prim.v.push_back(Vec2{c[0], c[1]});
    }
    switch (in.type) {
    case PrimitiveType::kTriangle:
      prim.triangles.push_back(
          PreparedTriangle{setup_triangle({prim.v[0], prim.v[1], prim.v[2]}, out.state), 0});
      break;
    case PrimitiveType::kPath:
      break; // drawn by the path rasterizer from prim.path
    case PrimitiveType::kPoint:
      // rule: SCENE.PRIM.POINT
      for (const TriangleSetup& t : setup_point(prim.v[0], out.state)) {
        prim.triangles.push_back(PreparedTriangle{t, 0});
      }
      break;
    case PrimitiveType::kLine:
    case PrimitiveType::kLineStrip:
      // rule: SCENE.LINE_MODE, MSAA.LINE.MODE
      if (lines_as_quads(scene.conventions, in.aa, scene.msaa)) {
        // D3D lines (aliased or antialiased) on a multisampled target with MultisampleEnable
        // are 1.4 px wide.
        const LineMode mode = scene.conventions.line_mode;
        const LineMode quad_mode = is_quad(mode) ? mode : LineMode::kQuadWide;
        RasterState no_cull = out.state;
        no_cull.cull = CullMode::kNone;
        for (std::size_t s = 0; s + 1 < prim.v.size(); ++s) {
          for (const auto& tri : quad_line_triangles(prim.v[s], prim.v[s + 1], quad_mode)) {
            prim.triangles.push_back(
                PreparedTriangle{setup_triangle(tri, no_cull), static_cast<std::uint32_t>(s)});
          }
        }
      }
      break;
    }
    out.primitives.push_back(std::move(prim));
  }
  return out;
}

namespace {

// Returns whether the scene is single-sample rendering with nothing else asked for: one sample
// at the pixel centre in the mask, pixel shading, no centroid, no quads. Such scenes take the
// single-sample path unchanged (SCENE.MSAA: only what a scene asks for is computed).
// rule: SCENE.MSAA, MSAA.COVER.SAMPLE
// How many entries (fragments, or touched pixels of a multisampled primitive) a primitive that
// must be collected before it is sorted may hold (for_each_fragment_bounded). Null: no bound.
struct CollectBudget {
  std::uint64_t left = 0;
};
struct CollectLimitReached {};

// Counts one collected entry against the budget; throws CollectLimitReached (caught by
// for_each_fragment_bounded, never escaping the kernel) when it is spent.
void take(CollectBudget* budget) {
  if (budget == nullptr)
    return;
  if (budget->left == 0)
    throw CollectLimitReached{};
  --budget->left;
}

// Calls emit(x, y) for the pixel centres t covers, by the traversal of options: both yield the
// same pixels in the same order (FAST.EQUALS.PLAIN).
// rule: FAST.EQUALS.PLAIN, RASTER.WALK.BBOX
template <class Emit>
void walk_centres(const PreparedScene& scene, const TriangleSetup& t, const RenderOptions& options,
                  Emit&& emit) {
  if (options.traversal == Traversal::kFast) {
    raster::walk_triangle_fast(t, scene.width, scene.height, effective_isa(options), emit);
  } else {
    raster::walk_triangle(t, scene.width, scene.height, emit);
  }
}

// walk_centres in the rows [y_first, y_last] only.
// rule: FAST.EQUALS.PLAIN, RASTER.WALK.BBOX
template <class Emit>
void walk_centres_in_rows(const PreparedScene& scene, const TriangleSetup& t,
                          const RenderOptions& options, std::int32_t y_first, std::int32_t y_last,
                          Emit&& emit) {
  if (options.traversal == Traversal::kFast) {
    raster::walk_triangle_fast_rows(t, scene.width, scene.height, y_first, y_last,
                                    effective_isa(options), emit);
  } else {
    raster::walk_triangle_rows(t, scene.width, scene.height, y_first, y_last, emit);
  }
}

// Calls emit(x, y, mask) for the pixels with samples of the pattern t covers, by the traversal
// of options (FAST.EQUALS.PLAIN).
// rule: FAST.EQUALS.PLAIN, MSAA.COVER.SAMPLE
template <class Emit>
void walk_samples(const PreparedScene& scene, const TriangleSetup& t, const RenderOptions& options,
                  Emit&& emit) {
  if (options.traversal == Traversal::kFast) {
    raster::walk_triangle_samples_fast(t, scene.msaa.pattern, scene.width, scene.height,
                                       effective_isa(options), emit);
  } else {
    raster::walk_triangle_samples(t, scene.msaa.pattern, scene.width, scene.height, emit);
  }
}

// Calls put(seg, x, y, coverage) for every pixel each segment of the line primitive prim
// produces, counting each against the budget: an antialiased segment's pixels with their
// antialiasing coverage, an aliased one's (by the scene's line mode) with none.
template <class Put>
void walk_segments(const PreparedScene& scene, const PreparedPrimitive& prim, CollectBudget* budget,
                   Put&& put) {
  for (std::size_t s = 0; s + 1 < prim.v.size(); ++s) {
    const auto seg = static_cast<std::uint32_t>(s);
    if (prim.aa) {
      // rule: SCENE.OUTPUT.COVERAGE
      rasterize_aa_line(prim.v[s], prim.v[s + 1], scene.width, scene.height,
                        [&](std::int32_t x, std::int32_t y, std::uint32_t c) {
                          take(budget);
                          put(seg, x, y, std::optional<std::uint32_t>(c));
                        });
    } else {
      rasterize_aliased_line(prim.v[s], prim.v[s + 1], scene.conventions.line_mode, scene.width,
                             scene.height, [&](std::int32_t x, std::int32_t y) {
                               take(budget);
                               put(seg, x, y, std::optional<std::uint32_t>());
                             });
    }
  }
}

bool is_single_sample(const PreparedScene& scene) {
  return rastrules::is_single_sample(scene.msaa);
}

// The single-sample path (issues #2 and #3).
// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.COVERAGE, SCENE.PRIM.LINE_STRIP
std::vector<Fragment> rasterize_single(const PreparedScene& scene, std::size_t p,
                                       const RenderOptions& options, CollectBudget* budget) {
  const PreparedPrimitive& prim = scene.primitives[p];
  const auto id = static_cast<std::uint32_t>(p);
  const bool strip = prim.type == PrimitiveType::kLineStrip;
  std::vector<Fragment> out;
  auto seg_of = [&](std::uint32_t s) {
    return strip ? std::optional<std::uint32_t>(s) : std::nullopt;
  };
  if (!prim.triangles.empty() || !is_line(prim.type)) {
    // Triangles, points (two triangles that never overlap) and quadrilateral lines.
    for (const PreparedTriangle& t : prim.triangles) {
      walk_centres(scene, t.setup, options, [&](std::int32_t x, std::int32_t y) {
        take(budget);
        out.push_back(Fragment{id, x, y, 1u, seg_of(t.seg), std::nullopt});
      });
    }
  } else {
    walk_segments(
        scene, prim, budget,
        [&](std::uint32_t seg, std::int32_t x, std::int32_t y, std::optional<std::uint32_t> c) {
          out.push_back(Fragment{id, x, y, 1u, seg_of(seg), c});
        });
  }
  // The triangle walk emits (y, x) per triangle; a point's two triangles, quadrilateral line
  // halves, strip segments and aliased lines (travel order) need a sort.
  if (prim.triangles.size() > 1 || prim.type != PrimitiveType::kTriangle) {
    std::stable_sort(out.begin(), out.end(), fragment_before);
  }
  return out;
}

// A pixel a primitive (or one segment of a line strip) touches: its coverage before the sample
// mask, and the antialiasing coverage of an antialiased single-sample line.
struct PixelCoverage {
  std::uint32_t seg = 0;
  std::int32_t y = 0;
  std::int32_t x = 0;
  std::uint32_t coverage = 0;
  std::optional<std::uint32_t> coverage_q16;
};

// Returns the per-sample coverage of primitive p sorted by (y, x, seg), one entry per pixel and
// segment.
// rule: MSAA.COVER.SAMPLE, MSAA.POINT.PER_SAMPLE, MSAA.LINE.MODE
std::vector<PixelCoverage> sample_coverage_of(const PreparedScene& scene,
                                              const PreparedPrimitive& prim,
                                              const RenderOptions& options, CollectBudget* budget) {
  const SamplePattern& pattern = scene.msaa.pattern;
  std::vector<PixelCoverage> cov;
  if (!is_line(prim.type) || lines_as_quads(scene.conventions, prim.aa, scene.msaa)) {
    // Triangles, a point's two triangles and quadrilateral lines: every sample tested.
    // rule: MSAA.COVER.SAMPLE, MSAA.POINT.PER_SAMPLE
    for (const PreparedTriangle& t : prim.triangles) {
      walk_samples(scene, t.setup, options,
                   [&](std::int32_t x, std::int32_t y, std::uint32_t mask) {
                     take(budget);
                     cov.push_back(PixelCoverage{t.seg, y, x, mask, std::nullopt});
                   });
    }
  } else {
    // Vulkan Bresenham lines (any count) and D3D lines with one sample or without
    // MultisampleEnable: every sample of each pixel the line produces, antialiased lines with
    // their coverage.
    // rule: MSAA.LINE.MODE
    const std::uint32_t all = full_mask(pattern.count());
    walk_segments(
        scene, prim, budget,
        [&](std::uint32_t seg, std::int32_t x, std::int32_t y, std::optional<std::uint32_t> c) {
          cov.push_back(PixelCoverage{seg, y, x, all, c});
        });
  }
  std::sort(cov.begin(), cov.end(), [](const PixelCoverage& a, const PixelCoverage& b) {
    return std::tie(a.y, a.x, a.seg) < std::tie(b.y, b.x, b.seg);
  });
  // Merge the halves of a point or of a quadrilateral segment that share a pixel.
  std::vector<PixelCoverage> merged;
  merged.reserve(cov.size());
  for (const PixelCoverage& c : cov) {
    if (!merged.empty() && merged.back().y == c.y && merged.back().x == c.x &&
        merged.back().seg == c.seg) {
      merged.back().coverage |= c.coverage;
    } else {
      merged.push_back(c);
    }
  }
  return merged;
}

// The multisampled path: per-sample coverage, the sample mask, shading rate, centroid, quads
// with helper lanes and derivatives, each only when the scene asks for it.
// rule: MSAA.MASK.AND, MSAA.SHADING.PIXEL, MSAA.SHADING.SAMPLE, MSAA.QUAD.HELPER
// rule: MSAA.DERIV.FINE, MSAA.DERIV.COARSE, SCENE.OUTPUT.MSAA
std::vector<Fragment> rasterize_msaa(const PreparedScene& scene, std::size_t p,
                                     const RenderOptions& options, CollectBudget* budget) {
  const PreparedPrimitive& prim = scene.primitives[p];
  const MultisampleState& ms = scene.msaa;
  const SamplePattern& pattern = ms.pattern;
  const auto id = static_cast<std::uint32_t>(p);
  const bool strip = prim.type == PrimitiveType::kLineStrip;
  const bool per_sample = ms.shading == ShadingRate::kSample;
  const std::uint32_t em = ms.effective_mask();
  auto seg_of = [&](std::uint32_t s) {
    return strip ? std::optional<std::uint32_t>(s) : std::nullopt;
  };
  auto centroid_of = [&](std::uint32_t coverage) {
    return fragment_centroid(coverage, ms, scene.conventions.centroid);
  };

  // rule: MSAA.MASK.AND
  if (em == 0)
    return {}; // the mask removes every sample: no fragment, no quad, no helper
  const std::vector<PixelCoverage> cov = sample_coverage_of(scene, prim, options, budget);
  std::vector<Fragment> out;
  // (seg, y, x) -> (coverage before the mask, after the mask) of pixels with a fragment.
  using LaneKey = std::tuple<std::uint32_t, std::int32_t, std::int32_t>;
  using LaneMasks = std::pair<std::uint32_t, std::uint32_t>;
  std::map<LaneKey, LaneMasks> lanes;
  for (const PixelCoverage& c : cov) {
    // rule: MSAA.MASK.AND
    const std::uint32_t mask = fragment_mask(c.coverage, ms);
    if (mask == 0)
      continue; // the mask removed every covered sample: nothing to write
    if (ms.wants_quads())
      lanes.emplace(LaneKey{c.seg, c.y, c.x}, LaneMasks{c.coverage, mask});
    Fragment f{id, c.x, c.y, mask, seg_of(c.seg), c.coverage_q16};
    if (ms.has_centroid)
      f.centroid = centroid_of(c.coverage);
    if (!per_sample) {
      // rule: MSAA.SHADING.PIXEL
      take(budget);
      out.push_back(f);
      continue;
    }
    // rule: MSAA.SHADING.SAMPLE
    for (std::uint32_t k = 0; k < pattern.count(); ++k) {
      if (((mask >> k) & 1u) == 0u)
        continue;
      Fragment fs = f;
      fs.sample = k;
      fs.mask = std::uint32_t{1} << k;
      take(budget);
      out.push_back(fs);
    }
  }

  if (ms.wants_quads()) {
    // rule: MSAA.QUAD.ALIGN, MSAA.QUAD.LANE, MSAA.QUAD.HELPER
    // A lane of (seg, sample k) runs covered when its pixel has a fragment with sample k (any
    // fragment under pixel shading).
    auto lane_mask = [&](std::uint32_t seg, std::int32_t x, std::int32_t y) -> const LaneMasks* {
      const auto it = lanes.find(LaneKey{seg, y, x});
      return it == lanes.end() ? nullptr : &it->second;
    };
    auto lane_covered = [&](std::uint32_t seg, std::uint32_t k, std::int32_t x, std::int32_t y) {
      const auto* l = lane_mask(seg, x, y);
      return l != nullptr && (!per_sample || ((l->second >> k) & 1u) != 0u);
    };
    // The evaluation point of a lane in 1/16 px from the target origin: the sample under
    // sample shading, else the centroid when asked for (a helper's follows rule 3: nothing
    // covered), else the pixel centre.
    auto eval_point = [&](std::uint32_t seg, std::uint32_t k, std::int32_t x,
                          std::int32_t y) -> std::array<std::int32_t, 2> {
      SampleOffset o{};
      if (per_sample) {
        o = pattern.positions[k];
      } else if (ms.has_centroid) {
        const auto* l = lane_mask(seg, x, y);
        o = centroid_of(l != nullptr ? l->first : 0u).offset;
      }
      return {x * 16 + 8 + o.x, y * 16 + 8 + o.y};
    };
    // Touched quads: (seg, sample index or 0, top-left y, top-left x).
    using QuadKey = std::tuple<std::uint32_t, std::uint32_t, std::int32_t, std::int32_t>;
    std::set<QuadKey> quads;
    for (const Fragment& f : out) {
      quads.emplace(f.seg.value_or(0), f.sample.value_or(0), f.y & ~1, f.x & ~1);
    }
    // Derivatives of every listed lane, keyed like the quads plus the lane's pixel.
    std::map<QuadKey, EvalDerivatives> derivs;
    for (const auto& [seg, k, qy, qx] : quads) {
      std::array<std::int32_t, 4> px{}, py{};
      for (std::uint32_t lane = 0; lane < 4; ++lane) {
        const std::int32_t x = qx + static_cast<std::int32_t>(lane & 1u);
        const std::int32_t y = qy + static_cast<std::int32_t>(lane >> 1u);
        const auto e = eval_point(seg, k, x, y);
        px[lane] = e[0];
        py[lane] = e[1];
      }
      for (std::uint32_t lane = 0; lane < 4; ++lane) {
        const std::int32_t x = qx + static_cast<std::int32_t>(lane & 1u);
        const std::int32_t y = qy + static_cast<std::int32_t>(lane >> 1u);
        if (x >= scene.width || y >= scene.height)
          continue; // helpers outside: not listed
        if (!lane_covered(seg, k, x, y)) {
          Fragment h{id, x, y, 0u, seg_of(seg), std::nullopt};
          h.helper = true;
          if (per_sample)
            h.sample = k;
          if (ms.has_centroid)
            h.centroid = centroid_of(0u);
          take(budget);
          out.push_back(h);
        }
        if (ms.derivatives != DerivativeMode::kNone) {
          // rule: MSAA.DERIV.FINE, MSAA.DERIV.COARSE
          const bool fine = ms.derivatives == DerivativeMode::kFine;
          const Derivatives<std::int32_t> dx =
              fine ? fine_derivatives(px, lane) : coarse_derivatives(px);
          const Derivatives<std::int32_t> dy =
              fine ? fine_derivatives(py, lane) : coarse_derivatives(py);
          derivs.emplace(QuadKey{seg, k, y, x}, EvalDerivatives{dx.ddx, dy.ddx, dx.ddy, dy.ddy});
        }
      }
    }
    if (ms.derivatives != DerivativeMode::kNone) {
      for (Fragment& f : out) {
        f.derivatives = derivs.at(QuadKey{f.seg.value_or(0), f.sample.value_or(0), f.y, f.x});
      }
    }
  }
  // rule: SCENE.OUTPUT.MSAA
  std::sort(out.begin(), out.end(), fragment_before);
  return out;
}

} // namespace

namespace {

// Returns the pixel indices [lo, hi] within 2 of the raw interval [a, b], clipped to [0, n):
// their count (0 when none).
std::uint64_t clipped_span(std::int64_t a, std::int64_t b, std::int32_t n) {
  const std::int64_t lo = std::max<std::int64_t>(floor_div(std::min(a, b), kSubpixelOne) - 2, 0);
  const std::int64_t hi =
      std::min<std::int64_t>(floor_div(std::max(a, b), kSubpixelOne) + 2, std::int64_t{n} - 1);
  return hi < lo ? 0 : static_cast<std::uint64_t>(hi - lo + 1);
}

std::uint64_t area(const raster::PixelRect& r) {
  return r.empty() ? 0
                   : static_cast<std::uint64_t>(r.x1 - r.x0 + 1) *
                         static_cast<std::uint64_t>(r.y1 - r.y0 + 1);
}

} // namespace

// rule: SCENE.INPUT.LIMITS, RASTER.WALK.BBOX
std::uint64_t primitive_work(const PreparedScene& scene, std::size_t p) {
  const PreparedPrimitive& prim = scene.primitives[p];
  if (prim.type == PrimitiveType::kPath)
    return detail::path_work(scene, prim);
  const bool single = is_single_sample(scene);
  // The same choice as rasterize_single and sample_coverage_of: the triangles it draws, or
  // the segments the line rasterizers walk.
  const bool triangles =
      single ? !prim.triangles.empty() || !is_line(prim.type)
             : !is_line(prim.type) || lines_as_quads(scene.conventions, prim.aa, scene.msaa);
  std::uint64_t work = 0;
  if (triangles) {
    for (const PreparedTriangle& t : prim.triangles) {
      work += single ? area(raster::walk_bounds(t.setup, scene.width, scene.height))
                     : area(raster::sample_walk_bounds(t.setup, scene.msaa.pattern, scene.width,
                                                       scene.height)) *
                           scene.msaa.pattern.count();
    }
    return work;
  }
  // A step of a line rasterizer's walk (a column or row, its few candidate pixels) costs
  // about as much as 16 sample tests of the plain triangle walk.
  constexpr std::uint64_t kLineStepWork = 16;
  for (std::size_t s = 0; s + 1 < prim.v.size(); ++s) {
    const Vec2 a = prim.v[s], b = prim.v[s + 1];
    work += kLineStepWork * (clipped_span(a.x.raw(), b.x.raw(), scene.width) +
                             clipped_span(a.y.raw(), b.y.raw(), scene.height));
  }
  return work;
}

// rule: SCENE.INPUT.LIMITS, SCENE.OUTPUT.FRAGMENTS
std::optional<SceneError> stream_within_limits(const PreparedScene& scene,
                                               std::uint64_t max_fragments, std::uint64_t max_work,
                                               const std::function<void(const Fragment&)>& emit) {
  const auto prim = [](std::size_t p) { return "primitives[" + std::to_string(p) + "] "; };
  if (const auto p = first_primitive_over_work(scene, max_work))
    return SceneError{"", prim(*p) + work_limit_problem(max_work), SceneError::Kind::kWorkLimit};
  struct TooManyFragments {};
  std::uint64_t count = 0;
  const auto counted = [&](const Fragment& f) {
    if (++count > max_fragments)
      throw TooManyFragments{};
    emit(f);
  };
  try {
    for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
      if (!for_each_fragment_bounded(scene, p, 2 * max_fragments, counted)) {
        return SceneError{"",
                          prim(p) + "touches more than " + std::to_string(2 * max_fragments) +
                              " pixels or fragments that must be held to be sorted (limit "
                              "SCENE.INPUT.LIMITS, 2 x max_fragments)",
                          SceneError::Kind::kFragmentLimit};
      }
    }
  } catch (const TooManyFragments&) {
    return SceneError{
        "", "more than " + std::to_string(max_fragments) + " fragments (limit SCENE.INPUT.LIMITS)",
        SceneError::Kind::kFragmentLimit};
  }
  return std::nullopt;
}

// rule: SCENE.INPUT.LIMITS
std::optional<std::size_t> first_primitive_over_work(const PreparedScene& scene,
                                                     std::uint64_t max_work) {
  // No overflow: the sum stops as soon as it passes max_work <= 2^60, and one primitive's work
  // is at most 2^62 (a path's saturates there; the others are at most 2^35).
  std::uint64_t total = 0;
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    total += primitive_work(scene, p);
    if (total > max_work)
      return p;
  }
  return std::nullopt;
}

// rule: SCENE.INPUT.LIMITS
std::string work_limit_problem(std::uint64_t max_work) {
  return "brings the work to more than " + std::to_string(max_work) +
         " sample tests (limit SCENE.INPUT.LIMITS)";
}

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.COVERAGE, SCENE.PRIM.LINE_STRIP, SCENE.OUTPUT.MSAA
// rule: FAST.EQUALS.PLAIN
std::vector<Fragment> rasterize_primitive(const PreparedScene& scene, std::size_t p,
                                          const RenderOptions& options) {
  if (scene.primitives[p].type == PrimitiveType::kPath) {
    std::vector<Fragment> out;
    detail::path_fragments(scene, p, [&](Fragment&& f) { out.push_back(std::move(f)); });
    return out;
  }
  if (is_single_sample(scene))
    return rasterize_single(scene, p, options, nullptr);
  return rasterize_msaa(scene, p, options, nullptr);
}

std::vector<Fragment> rasterize_primitive(const PreparedScene& scene, std::size_t p) {
  return rasterize_primitive(scene, p, RenderOptions{});
}

// rule: SCENE.OUTPUT.FRAGMENTS, FAST.EQUALS.PLAIN
void for_each_fragment(const PreparedScene& scene, std::size_t p, const RenderOptions& options,
                       const std::function<void(const Fragment&)>& emit) {
  if (is_streamed(scene, p)) {
    const auto id = static_cast<std::uint32_t>(p);
    walk_centres(scene, scene.primitives[p].triangles[0].setup, options,
                 [&](std::int32_t x, std::int32_t y) {
                   emit(Fragment{id, x, y, 1u});
                 });
    return;
  }
  // rule: SCENE.PRIM.PATH
  if (scene.primitives[p].type == PrimitiveType::kPath) {
    detail::path_fragments(scene, p, [&](Fragment&& f) { emit(f); }); // one row held at a time
    return;
  }
  for (const Fragment& f : rasterize_primitive(scene, p, options))
    emit(f);
}

void for_each_fragment(const PreparedScene& scene, std::size_t p,
                       const std::function<void(const Fragment&)>& emit) {
  for_each_fragment(scene, p, RenderOptions{}, emit);
}

// rule: SCENE.INPUT.LIMITS
bool is_streamed(const PreparedScene& scene, std::size_t p) {
  return scene.primitives[p].type == PrimitiveType::kTriangle && is_single_sample(scene);
}

PixelBounds streamed_bounds(const PreparedScene& scene, std::size_t p) {
  const raster::PixelRect r =
      raster::walk_bounds(scene.primitives[p].triangles[0].setup, scene.width, scene.height);
  return PixelBounds{r.x0, r.y0, r.x1, r.y1};
}

// rule: FAST.THREADS.DETERMINISTIC, FAST.EQUALS.PLAIN
void for_each_fragment_in_rows(const PreparedScene& scene, std::size_t p, std::int32_t y_first,
                               std::int32_t y_last, const RenderOptions& options,
                               const std::function<void(const Fragment&)>& emit) {
  const auto id = static_cast<std::uint32_t>(p);
  walk_centres_in_rows(scene, scene.primitives[p].triangles[0].setup, options, y_first, y_last,
                       [&](std::int32_t x, std::int32_t y) {
                         emit(Fragment{id, x, y, 1u});
                       });
}

// rule: SCENE.INPUT.LIMITS, FAST.EQUALS.PLAIN
bool for_each_fragment_bounded(const PreparedScene& scene, std::size_t p,
                               std::uint64_t max_collected, const RenderOptions& options,
                               const std::function<void(const Fragment&)>& emit) {
  if (is_streamed(scene, p) || scene.primitives[p].type == PrimitiveType::kPath) {
    for_each_fragment(scene, p, options, emit); // streamed: nothing (a path: one row) is held
    return true;
  }
  CollectBudget budget{max_collected};
  std::vector<Fragment> frags;
  try {
    frags = is_single_sample(scene) ? rasterize_single(scene, p, options, &budget)
                                    : rasterize_msaa(scene, p, options, &budget);
  } catch (const CollectLimitReached&) {
    return false;
  }
  for (const Fragment& f : frags)
    emit(f);
  return true;
}

bool for_each_fragment_bounded(const PreparedScene& scene, std::size_t p,
                               std::uint64_t max_collected,
                               const std::function<void(const Fragment&)>& emit) {
  return for_each_fragment_bounded(scene, p, max_collected, RenderOptions{}, emit);
}

// rule: SCENE.OUTPUT.FRAGMENTS
std::vector<Fragment> rasterize(const PreparedScene& scene) {
  std::vector<Fragment> out;
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    std::vector<Fragment> f = rasterize_primitive(scene, p);
    out.insert(out.end(), f.begin(), f.end());
  }
  return out; // primitives in order, each sorted by (y, x, seg, sample)
}

// rule: MSAA.RESOLVE.AVERAGE, MSAA.LIMITS
Resolver::Resolver(const PreparedScene& scene)
    : scene_(&scene), samples_(static_cast<std::size_t>(std::int64_t{scene.width} * scene.height *
                                                        scene.msaa.count()),
                               scene.clear_color) {}

// rule: MSAA.LIMITS
std::optional<std::string> resolve_size_problem(std::int32_t width, std::int32_t height,
                                                std::uint32_t n) {
  const std::int64_t samples = std::int64_t{width} * height * n;
  if (width >= 1 && height >= 1 && n >= 1 && samples <= kMaxResolveSamples)
    return std::nullopt;
  return "the " + std::to_string(width) + "x" + std::to_string(height) + " target with " +
         std::to_string(n) + " samples has " + std::to_string(samples) + " samples, " +
         (samples < 1 ? std::string("none to resolve")
                      : "more than " + std::to_string(kMaxResolveSamples)) +
         " (limit MSAA.LIMITS)";
}

std::variant<Resolver, SceneError> Resolver::start(const PreparedScene& scene) {
  if (auto problem = resolve_size_problem(scene.width, scene.height, scene.msaa.count()))
    return SceneError{"target", std::move(*problem)};
  return Resolver(scene);
}

std::optional<SceneError> Resolver::add(const Fragment& f, std::size_t index) {
  const PreparedScene& scene = *scene_;
  if (f.prim >= scene.primitives.size() || f.x < 0 || f.x >= scene.width || f.y < 0 ||
      f.y >= scene.height) {
    return SceneError{"fragments[" + std::to_string(index) + "]",
                      "names a primitive or pixel outside the scene"};
  }
  if (f.helper)
    return std::nullopt; // helper lanes write nothing (MSAA.QUAD.HELPER)
  const std::uint32_t n = scene.msaa.count();
  const std::size_t base = (static_cast<std::size_t>(f.y) * static_cast<std::size_t>(scene.width) +
                            static_cast<std::size_t>(f.x)) *
                           n;
  for (std::uint32_t k = 0; k < n; ++k) {
    if (((f.mask >> k) & 1u) != 0u)
      samples_[base + k] = scene.primitives[f.prim].color;
  }
  return std::nullopt;
}

ResolvedImage Resolver::finish() const {
  const std::uint32_t n = scene_->msaa.count();
  ResolvedImage img;
  img.width = scene_->width;
  img.height = scene_->height;
  img.pixels.reserve(static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height));
  std::vector<Rgba8> pixel(n);
  for (std::size_t i = 0; i < samples_.size(); i += n) {
    std::copy_n(samples_.begin() + static_cast<std::ptrdiff_t>(i), n, pixel.begin());
    img.pixels.push_back(resolve_pixel(pixel));
  }
  return img;
}

std::variant<ResolvedImage, SceneError> resolve(const PreparedScene& scene,
                                                const std::vector<Fragment>& fragments) {
  auto started = Resolver::start(scene);
  if (auto* e = std::get_if<SceneError>(&started))
    return *e;
  Resolver& r = std::get<Resolver>(started);
  for (std::size_t i = 0; i < fragments.size(); ++i) {
    if (auto e = r.add(fragments[i], i))
      return *e;
  }
  return r.finish();
}

} // namespace rastrules

// SPDX-License-Identifier: MIT
// The fuzz targets' shared code (support.hpp).

#include "support.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <tuple>
#include <utility>

#include "rastrules/check/check.hpp"
#include "rastrules/io/scene_json.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/oracle/line.hpp"
#include "rastrules/oracle/line_aa.hpp"
#include "rastrules/oracle/point.hpp"
#include "rastrules/oracle/triangle.hpp"

namespace rastrules::fuzz {

std::uint8_t ByteReader::byte() {
  return pos_ < size_ ? data_[pos_++] : std::uint8_t{0};
}

std::uint16_t ByteReader::u16() {
  const auto lo = byte();
  const auto hi = byte();
  return static_cast<std::uint16_t>(lo | (hi << 8));
}

std::uint32_t ByteReader::u24() {
  std::uint32_t v = 0;
  for (int i = 0; i < 3; ++i)
    v |= std::uint32_t{byte()} << (8 * i);
  return v;
}

std::uint32_t ByteReader::u32() {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i)
    v |= std::uint32_t{byte()} << (8 * i);
  return v;
}

namespace {

// Every raw value here has |raw| < 2^24, so raw / 256 and (2 raw + 1) / 512 are exact floats.
float coordinate(ByteReader& in) {
  switch (in.byte() % 5) {
  case 0: { // a raw 16.8 value within +-128 px: near the target
    const auto raw = static_cast<std::int16_t>(in.u16());
    return static_cast<float>(raw) / 256.0f;
  }
  case 1: { // any raw 16.8 value of SNAP.VERTEX.RANGE [-2^23, 2^23 - 1]
    const std::int32_t raw = static_cast<std::int32_t>(in.u24()) - (std::int32_t{1} << 23);
    return static_cast<float>(raw) / 256.0f;
  }
  case 2: { // a rounding tie halfway between two raw values near the target
    const auto raw = static_cast<std::int16_t>(in.u16());
    return static_cast<float>(2 * std::int32_t{raw} + 1) / 512.0f;
  }
  case 3: { // a few ulps away from a raw value near the target
    const auto raw = static_cast<std::int16_t>(in.u16());
    const auto steps = static_cast<std::int8_t>(in.byte());
    float v = static_cast<float>(raw) / 256.0f;
    const float toward = steps < 0 ? -INFINITY : INFINITY;
    for (int i = 0; i < std::abs(int{steps}) % 9; ++i)
      v = std::nextafter(v, toward);
    return v;
  }
  default: // arbitrary float32 bits: NaN, infinities, subnormals, out of range
    return std::bit_cast<float>(in.u32());
  }
}

} // namespace

Scene decode_scene(ByteReader& in) {
  Scene s;
  s.width = 1 + in.byte() % kMaxFuzzTarget;
  s.height = 1 + in.byte() % kMaxFuzzTarget;
  const std::uint8_t st = in.byte();
  s.cull = static_cast<CullMode>((st & 3u) % 3u);
  s.conventions.front_face = (st & 4u) != 0 ? FrontFace::kCounterClockwise : FrontFace::kClockwise;
  s.conventions.fill = static_cast<FillConvention>((st >> 3) & 3u);
  s.conventions.line_mode = static_cast<LineMode>((st >> 5) & 3u);
  // Bit 7: keep "aa": true in every line mode (prepare must reject it outside d3d); otherwise
  // aa is dropped outside d3d, so that most antialiased lines get drawn.
  const bool keep_bad_aa = (st & 0x80u) != 0;
  const std::size_t count = in.byte() % (kMaxFuzzPrimitives + 1);
  std::size_t aa_segments = 0;
  for (std::size_t p = 0; p < count && in.remaining() > 0; ++p) {
    const std::uint8_t t = in.byte();
    Primitive prim;
    prim.type = static_cast<PrimitiveType>(t & 3u);
    std::size_t n = required_vertex_count(prim.type);
    if (prim.type == PrimitiveType::kLineStrip)
      n = 2 + ((t >> 4) & 3u) % (kMaxStripVertices - 1);
    const bool is_line =
        prim.type == PrimitiveType::kLine || prim.type == PrimitiveType::kLineStrip;
    prim.aa = is_line && (t & 8u) != 0 &&
              (keep_bad_aa || s.conventions.line_mode == LineMode::kD3DDiamond) &&
              aa_segments + (n - 1) <= kMaxAaSegments;
    if (prim.aa)
      aa_segments += n - 1;
    prim.v.assign(n, FloatPoint{0.0f, 0.0f});
    for (FloatPoint& v : prim.v) {
      v[0] = coordinate(in);
      v[1] = coordinate(in);
    }
    s.primitives.push_back(std::move(prim));
  }
  return s;
}

// rule: SCENE.PRIM.PATH
Scene decode_path_scene(ByteReader& in) {
  Scene s;
  s.width = 1 + in.byte() % kMaxFuzzPathTarget;
  s.height = 1 + in.byte() % kMaxFuzzPathTarget;
  const std::uint8_t st = in.byte();
  s.conventions.fill = static_cast<FillConvention>(st & 3u);
  if ((st & 4u) != 0)
    set_sample_pattern(s, standard_pattern((st & 8u) != 0 ? 16 : 4));
  if ((st & 16u) != 0)
    s.msaa.sample_mask = in.byte() & full_mask(s.msaa.pattern.count());
  const std::size_t count = 1 + in.byte() % kMaxFuzzPaths;
  for (std::size_t p = 0; p < count && in.remaining() > 0; ++p) {
    const std::uint8_t t = in.byte();
    FloatPath fp;
    fp.fill_rule = (t & 1u) != 0 ? path::FillRule::kEvenOdd : path::FillRule::kNonZero;
    // Area coverage of curves is checked within bounds (the oracle's certified ones), slower
    // than exact areas of lines (each run halves the curves into pieces in exact integers and
    // fills their chords in rationals, several runs an input): bit 2 keeps curves in an area
    // path of a target of at most 8 x 8 px (a 16 x 16 one took 9.4 s under the sanitizers,
    // libFuzzer's limit is 10 s).
    const bool area = (t & 2u) != 0;
    const bool curves = !area || ((t & 4u) != 0 && s.width <= 8 && s.height <= 8);
    fp.coverage = area ? path::Coverage::kArea : path::Coverage::kSamples;
    // An area path with curves: one contour of at most three segments (the oracle's certified
    // areas cut each curve into 64 pieces).
    const bool area_curves = area && curves;
    const std::size_t contours = area_curves ? 1 : 1 + ((t >> 3) & 3u) % kMaxFuzzPathContours;
    // A point: mostly raw 16.8 values near the target (ties on centres and samples come from
    // the multiples of 8 and 16 raw these often are), sometimes any coordinate of decode_scene.
    auto point = [&]() {
      FloatPoint q{};
      for (float& c : q) {
        const std::uint8_t k = in.byte();
        if (k < 200) {
          const std::int32_t span = (kMaxFuzzPathTarget + 4) * 256;
          const auto raw =
              static_cast<std::int32_t>(in.u16() % static_cast<std::uint32_t>(span)) - 2 * 256;
          c = static_cast<float>((k & 1u) != 0 ? raw & ~7 : raw) / 256.0f;
        } else {
          c = coordinate(in);
        }
      }
      return q;
    };
    for (std::size_t c = 0; c < contours && in.remaining() > 0; ++c) {
      FloatContour contour;
      contour.start = point();
      const std::size_t segments = 1 + in.byte() % (area_curves ? 3 : kMaxFuzzPathSegments);
      for (std::size_t k = 0; k < segments && in.remaining() > 0; ++k) {
        const std::uint8_t kind = in.byte();
        FloatPathSegment seg;
        seg.kind = !curves || kind % 3 == 0 ? path::SegmentKind::kLine
                   : kind % 3 == 1          ? path::SegmentKind::kQuadratic
                                            : path::SegmentKind::kCubic;
        for (std::size_t i = 0; i < path::point_count(seg.kind); ++i)
          seg.p[i] = point();
        contour.segments.push_back(seg);
      }
      fp.contours.push_back(std::move(contour));
    }
    s.primitives.push_back(make_path(std::move(fp)));
  }
  return s;
}

Scene protocol_scene(std::uint8_t b) {
  static constexpr std::int32_t kSides[4] = {1, 3, 8, 16};
  Scene s;
  s.width = kSides[b & 3u];
  s.height = kSides[(b >> 2) & 3u];
  if ((b & 16u) != 0)
    set_sample_pattern(s, standard_pattern(4));
  const std::size_t prims = 1u + ((b >> 5) & 3u);
  for (std::size_t i = 0; i < prims; ++i) {
    Primitive p;
    p.type = PrimitiveType::kPoint;
    p.v = {FloatPoint{0.5f, 0.5f}};
    s.primitives.push_back(p);
  }
  return s;
}

namespace {

// A path primitive by SCENE.PRIM.PATH's words: no vertices, every control point snaps (the
// oracle's snapping), at most 2^20 segments, and none of centroid,
// sample shading, quads or derivatives in its scene.
std::string path_invalid_reason(const Scene& scene, const Primitive& prim) {
  if (!prim.v.empty())
    return "vertices on a path";
  if (!prim.path)
    return {};
  const MultisampleState& ms = scene.msaa;
  if (ms.has_centroid || ms.shading != ShadingRate::kPixel || ms.quads ||
      ms.derivatives != DerivativeMode::kNone)
    return "a path in a scene that asks for centroid, shading, quads or derivatives";
  std::size_t segments = 0;
  auto snaps = [](const FloatPoint& q) {
    return oracle::snap(q[0]).has_value() && oracle::snap(q[1]).has_value();
  };
  for (const FloatContour& c : prim.path->contours) {
    segments += c.segments.size();
    if (!snaps(c.start))
      return "a control point does not snap";
    for (const FloatPathSegment& seg : c.segments) {
      for (std::size_t k = 0; k < path::point_count(seg.kind); ++k) {
        if (!snaps(seg.p[k]))
          return "a control point does not snap";
      }
    }
  }
  if (segments > (std::size_t{1} << 20))
    return "more than 2^20 segments";
  return {};
}

} // namespace

std::string oracle_invalid_reason(const Scene& scene) {
  if (scene.width < 1 || scene.width > 16384 || scene.height < 1 || scene.height > 16384) {
    return "target size outside [1, 16384]";
  }
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    const Primitive& prim = scene.primitives[p];
    const std::string at = "primitives[" + std::to_string(p) + "]";
    const std::size_t n = prim.v.size();
    switch (prim.type) {
    case PrimitiveType::kTriangle:
      if (n != 3)
        return at + ": not 3 vertices";
      break;
    case PrimitiveType::kPoint:
      if (n != 1)
        return at + ": not 1 vertex";
      break;
    case PrimitiveType::kLine:
      if (n != 2)
        return at + ": not 2 vertices";
      break;
    case PrimitiveType::kLineStrip:
      if (n < 2)
        return at + ": fewer than 2 vertices";
      break;
    case PrimitiveType::kPath:
      if (std::string why = path_invalid_reason(scene, prim); !why.empty())
        return at + ": " + why;
      break;
    }
    if (prim.path.has_value() != (prim.type == PrimitiveType::kPath))
      return at + ": a path without its path, or a path on another primitive";
    if (prim.aa && (prim.type == PrimitiveType::kTriangle || prim.type == PrimitiveType::kPoint)) {
      return at + ": aa on a triangle or point";
    }
    if (prim.aa && scene.conventions.line_mode != LineMode::kD3DDiamond)
      return at + ": aa outside line mode d3d";
    for (std::size_t i = 0; i < n; ++i) {
      const auto x = oracle::snap(prim.v[i][0]);
      const auto y = oracle::snap(prim.v[i][1]);
      if (!x || !y)
        return at + ".v[" + std::to_string(i) + "]: does not snap";
      if (prim.type == PrimitiveType::kPoint && !oracle::point_in_range({*x, *y}))
        return at + ": outside POINT.RANGE";
    }
  }
  // Multisampling, from spec/rules/msaa.md (the reader has already checked each key alone):
  // MSAA.LIMITS: a sample mask other than the default all-ones value holds no bit beyond the
  // pattern's n samples. MSAA.SHADING.SAMPLE: sample shading of "vulkan-bresenham" lines with
  // n > 1 is bad input. MSAA.LINE.MODE: with n > 1 a "quad-wide" or "quad-narrow" line (not
  // antialiased) is a quadrilateral line, and a "d3d" line is one when multisample_enable is
  // true; a centre pattern cannot draw quadrilateral lines.
  const std::size_t n = scene.msaa.pattern.positions.size();
  if (scene.msaa.sample_mask != 0xFFFFFFFFu && n < 32 && (scene.msaa.sample_mask >> n) != 0) {
    return "sample_mask: bits beyond the pattern";
  }
  for (const Primitive& prim : scene.primitives) {
    const bool line = prim.type == PrimitiveType::kLine || prim.type == PrimitiveType::kLineStrip;
    if (!line || n <= 1)
      continue;
    const bool bresenham = scene.conventions.line_mode == LineMode::kVulkanBresenham;
    if (bresenham && scene.msaa.shading == ShadingRate::kSample)
      return "shading: sample shading of Bresenham lines";
    const LineMode mode = scene.conventions.line_mode;
    const bool quad = mode == LineMode::kQuadWide || mode == LineMode::kQuadNarrow
                          ? !prim.aa
                          : mode == LineMode::kD3DDiamond && scene.conventions.multisample_enable;
    if (quad && scene.msaa.pattern.kind == PatternKind::kCenter)
      return "sample_pattern: quad lines on a centre pattern";
  }
  return {};
}

void fail(const std::string& what, const std::vector<std::string>& details, const Scene* scene,
          const std::uint8_t* data, std::size_t size) {
  std::fprintf(stderr, "\n==== rastrules fuzz: %s\n", what.c_str());
  for (std::size_t i = 0; i < details.size() && i < 20; ++i)
    std::fprintf(stderr, "  %s\n", details[i].c_str());
  if (details.size() > 20)
    std::fprintf(stderr, "  ... and %zu more\n", details.size() - 20);
  if (scene != nullptr) {
    std::fprintf(stderr, "---- reproducer scene (rastrules render SCENE.json --fragments -):\n%s\n",
                 io::write_scene(*scene).c_str());
  }
  std::fprintf(stderr, "---- input (%zu bytes):", size);
  for (std::size_t i = 0; i < size && i < 4096; ++i)
    std::fprintf(stderr, "%s%02x", i % 32 == 0 ? "\n  " : " ", data[i]);
  std::fprintf(stderr, "\n");
  std::fflush(stderr);
  std::abort();
}

void check_scene_error(const SceneError& e, const char* stage, const Scene* scene,
                       const std::uint8_t* data, std::size_t size) {
  const bool names_position = e.message.rfind("parse error", 0) == 0;
  if (e.message.empty() || (e.field.empty() && !names_position)) {
    fail(std::string(stage) + " returned an error that names no field or position",
         {"field: \"" + e.field + "\"", "message: \"" + e.message + "\""}, scene, data, size);
  }
}

std::optional<Scene> read_input_scene(const std::uint8_t* data, std::size_t size) {
  if (size > io::kMaxSceneBytes)
    return std::nullopt;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // rule: SCENE.INPUT.FAST_READER
  // The fast path accepts only text the general reader reads to the same scene.
  if (const std::optional<Scene> fast = io::read_scene_fast(text)) {
    const auto general = io::read_scene_general(text);
    if (const auto* err = std::get_if<SceneError>(&general))
      fail("read_scene_fast accepts text read_scene_general rejects", {err->what()}, &*fast, data,
           size);
    if (!io::same_scene(std::get<Scene>(general), *fast))
      fail("read_scene_fast reads a different scene than read_scene_general", {}, &*fast, data,
           size);
  }
  // The coordinates-only form (render --count, --fragments OUT.bin) declines exactly where
  // read_scene_fast does and holds the same coordinates.
  if (const std::optional<io::FastTriangles> t = io::read_triangles_fast(text)) {
    const std::optional<Scene> fast = io::read_scene_fast(text);
    if (!fast)
      fail("read_triangles_fast accepts text read_scene_fast declines", {}, nullptr, data, size);
    std::vector<float> xy;
    for (const Primitive& p : fast->primitives)
      for (const FloatPoint& v : p.v)
        xy.insert(xy.end(), {v[0], v[1]});
    if (xy.size() != t->xy.size() ||
        !std::equal(xy.begin(), xy.end(), t->xy.begin(), [](float a, float b) {
          return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
        }))
      fail("read_triangles_fast reads other coordinates than read_scene_fast", {}, &*fast, data,
           size);
  } else if (io::read_scene_fast(text)) {
    fail("read_triangles_fast declines text read_scene_fast accepts", {}, nullptr, data, size);
  }
  // The list read in parts on three threads (parts of at least 16 bytes, so that small inputs
  // split): the one-thread result.
  {
    const std::optional<io::FastTriangles> one = io::read_triangles_fast(text);
    const std::optional<io::FastTriangles> parts = io::read_triangles_fast(text, 3, 16);
    if (one.has_value() != parts.has_value() ||
        (one &&
         (!io::same_scene(one->scene, parts->scene) || one->xy.size() != parts->xy.size() ||
          !std::equal(one->xy.begin(), one->xy.end(), parts->xy.begin(), [](float a, float b) {
            return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
          }))))
      fail("read_triangles_fast in parts differs from one thread", {}, nullptr, data, size);
  }
  auto read = io::read_scene(text);
  if (const auto* err = std::get_if<SceneError>(&read)) {
    check_scene_error(*err, "read_scene", nullptr, data, size);
    return std::nullopt;
  }
  return std::move(std::get<Scene>(read));
}

void check_round_trip(const Scene& scene, const std::uint8_t* data, std::size_t size) {
  const auto reread = io::read_scene(io::write_scene(scene));
  if (const auto* err = std::get_if<SceneError>(&reread))
    fail("write_scene wrote text that read_scene rejects", {err->what()}, &scene, data, size);
  if (!io::same_scene(std::get<Scene>(reread), scene))
    fail("write_scene wrote text that reads back to a different scene", {}, &scene, data, size);
}

void check_prepare_verdict(const Scene& scene,
                           const std::variant<PreparedScene, SceneError>& prepared,
                           const std::uint8_t* data, std::size_t size) {
  const std::string invalid = oracle_invalid_reason(scene);
  if (const auto* err = std::get_if<SceneError>(&prepared)) {
    if (invalid.empty())
      fail("prepare rejects a scene the oracles find valid", {err->what()}, &scene, data, size);
  } else if (!invalid.empty()) {
    fail("prepare accepts a scene the oracles find invalid", {invalid}, &scene, data, size);
  }
}

std::optional<Drawn> prepare_and_draw(const Scene& scene, const std::uint8_t* data,
                                      std::size_t size) {
  auto prepared = prepare(scene);
  if (const auto* err = std::get_if<SceneError>(&prepared)) {
    if (err->field.empty() || err->message.empty())
      fail("prepare returned an error naming no field", {err->what()}, &scene, data, size);
  }
  check_prepare_verdict(scene, prepared, data, size);
  if (!std::holds_alternative<PreparedScene>(prepared))
    return std::nullopt;
  Drawn d{std::move(std::get<PreparedScene>(prepared)), {}};
  d.fragments = rasterize(d.prepared);
  if (rasterize(d.prepared) != d.fragments)
    fail("two runs of rasterize differ", {}, &scene, data, size);
  const auto rendered = render(scene);
  if (!std::holds_alternative<std::vector<Fragment>>(rendered) ||
      std::get<std::vector<Fragment>>(rendered) != d.fragments) {
    fail("render differs from rasterize(prepare)", {}, &scene, data, size);
  }
  return d;
}

void check_against_oracles(const Scene& scene, const Drawn& drawn, const std::string& what,
                           const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> differences;
  try {
    differences = check::check_against_oracle(scene, drawn.prepared, drawn.fragments).mismatches;
  } catch (const std::exception& e) {
    differences.push_back(std::string("the oracle failed: ") + e.what());
  }
  if (!differences.empty())
    fail(what, differences, &scene, data, size);
}

} // namespace rastrules::fuzz

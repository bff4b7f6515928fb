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
#include <tuple>
#include <utility>

#include "rastrules/io/scene_json.hpp"
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
  s.state.cull = static_cast<CullMode>((st & 3u) % 3u);
  s.state.front_face = (st & 4u) != 0 ? FrontFace::kCounterClockwise : FrontFace::kClockwise;
  s.state.fill = static_cast<FillConvention>((st >> 3) & 3u);
  s.line_mode = static_cast<LineMode>((st >> 5) & 3u);
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
    prim.aa = is_line && (t & 8u) != 0 && (keep_bad_aa || s.line_mode == LineMode::kD3DDiamond) &&
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

namespace {

using Key = std::tuple<std::int32_t, std::int32_t, std::int64_t>; // (y, x, seg or -1)

std::string key_text(std::size_t prim, const Key& k) {
  return "prim " + std::to_string(prim) + " pixel (" + std::to_string(std::get<1>(k)) + ", " +
         std::to_string(std::get<0>(k)) + ")" +
         (std::get<2>(k) >= 0 ? " seg " + std::to_string(std::get<2>(k)) : std::string());
}

std::array<std::int64_t, 2> centre_raw(std::int32_t x, std::int32_t y) {
  return {std::int64_t{x} * 256 + 128, std::int64_t{y} * 256 + 128};
}

// Raw 16.8 by the oracle's own snapping (never the kernel's).
std::array<std::int64_t, 2> oracle_raw(const FloatPoint& v) {
  const auto x = oracle::snap(v[0]);
  const auto y = oracle::snap(v[1]);
  if (!x || !y)
    throw std::invalid_argument("the oracle cannot snap a vertex the kernel accepted");
  return {*x, *y};
}

__extension__ using Int128 = __int128;

// Returns whether point c lies within distance r of the segment a -> b's bounding box grown by
// r and within distance r of its supporting line (all raw 16.8, exact): a superset of the
// pixels within distance r of the segment. The oracles are exact but slow, so only these
// candidates are asked (the full-target scans of aa_pixels and of the per-pixel loops would
// make one input take seconds). Sound because every pixel an oracle can cover is a candidate:
// an aliased line covers a pixel only when it meets the pixel's diamond (LINE.D3D.EXIT,
// LINE.VK.EXIT: within 1/2 px of its centre, the Vulkan endpoint shift is below 1 raw); an
// antialiased line is a rectangle within 1/2 px of its segment (LINE.AA.RECT), so a pixel
// square meeting it has its centre within 1/2 + sqrt(2)/2 < 3/2 px; a quadrilateral line's
// corners lie within 0.7 px + 1 raw of its endpoints (LINE.QUAD.CORNERS), so a covered centre
// lies within 3/2 px; a point's square lies within sqrt(2)/2 px of its centre.
bool near_segment(const std::array<std::int64_t, 2>& a, const std::array<std::int64_t, 2>& b,
                  const std::array<std::int64_t, 2>& c, std::int64_t r) {
  if (c[0] < std::min(a[0], b[0]) - r || c[0] > std::max(a[0], b[0]) + r ||
      c[1] < std::min(a[1], b[1]) - r || c[1] > std::max(a[1], b[1]) + r) {
    return false;
  }
  const std::int64_t dx = b[0] - a[0];
  const std::int64_t dy = b[1] - a[1];
  const Int128 cross = Int128{dx} * (c[1] - a[1]) - Int128{dy} * (c[0] - a[0]);
  const Int128 len2 = Int128{dx} * dx + Int128{dy} * dy;
  return cross * cross <= Int128{r} * r * len2;
}

// 3/2 px in raw units: the candidate radius of near_segment.
constexpr std::int64_t kNearRaw = 384;

void compare_keys(std::size_t prim, std::vector<Key> mine, std::vector<Key> exact,
                  std::vector<std::string>& out) {
  std::sort(mine.begin(), mine.end());
  std::sort(exact.begin(), exact.end());
  std::size_t i = 0, j = 0;
  while (i < mine.size() || j < exact.size()) {
    if (j == exact.size() || (i < mine.size() && mine[i] < exact[j])) {
      out.push_back("only the kernel covers " + key_text(prim, mine[i++]));
    } else if (i == mine.size() || exact[j] < mine[i]) {
      out.push_back("only the oracle covers " + key_text(prim, exact[j++]));
    } else {
      ++i;
      ++j;
    }
  }
}

} // namespace

std::vector<std::string> compare_with_oracles(const Scene& scene, const PreparedScene& ps,
                                              const std::vector<Fragment>& kernel) {
  std::vector<std::string> out;
  const std::string fill(to_string(scene.state.fill));
  // The fragment list itself (SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.COVERAGE).
  for (std::size_t i = 0; i < kernel.size(); ++i) {
    const Fragment& f = kernel[i];
    const std::string at = "fragment " + std::to_string(i) + " (prim " + std::to_string(f.prim) +
                           ", x " + std::to_string(f.x) + ", y " + std::to_string(f.y) + ")";
    if (f.prim >= scene.primitives.size()) {
      out.push_back(at + ": no such primitive");
      return out;
    }
    const Primitive& prim = scene.primitives[f.prim];
    if (f.x < 0 || f.y < 0 || f.x >= scene.width || f.y >= scene.height)
      out.push_back(at + ": outside the target");
    if (f.mask != 1u)
      out.push_back(at + ": mask " + std::to_string(f.mask));
    if (f.seg.has_value() != (prim.type == PrimitiveType::kLineStrip))
      out.push_back(at + ": seg on a non-strip or missing");
    if (f.seg && *f.seg + 1 >= prim.v.size())
      out.push_back(at + ": seg beyond the strip");
    if (f.coverage_q16.has_value() != prim.aa)
      out.push_back(at + ": coverage on an aliased fragment or missing");
    if (f.coverage_q16 && (*f.coverage_q16 < 1 || *f.coverage_q16 > 65536))
      out.push_back(at + ": coverage out of [1, 65536]");
    if (i > 0 && !fragment_before(kernel[i - 1], f))
      out.push_back(at + ": out of (prim, y, x, seg) order or duplicated");
  }

  std::vector<std::vector<Key>> mine(scene.primitives.size());
  std::vector<std::vector<Key>> exact(scene.primitives.size());
  for (const Fragment& f : kernel) {
    mine[f.prim].push_back(Key{f.y, f.x, f.seg ? std::int64_t{*f.seg} : -1});
  }
  // Triangles: one oracle scene holding every triangle primitive.
  oracle::Scene tris;
  tris.width = scene.width;
  tris.height = scene.height;
  tris.state.cull = std::string(to_string(scene.state.cull));
  tris.state.front_face = std::string(to_string(scene.state.front_face));
  tris.state.fill = fill;
  std::vector<std::size_t> tri_prim;
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    const Primitive& prim = scene.primitives[p];
    if (prim.type != PrimitiveType::kTriangle)
      continue;
    tris.triangles.push_back({prim.v[0], prim.v[1], prim.v[2]});
    tri_prim.push_back(p);
  }
  if (!tris.triangles.empty()) {
    for (const oracle::Fragment& f : oracle::render(tris))
      exact[tri_prim[f.prim]].push_back(Key{f.y, f.x, -1});
  }
  for (std::size_t p = 0; p < scene.primitives.size(); ++p) {
    const Primitive& prim = scene.primitives[p];
    switch (prim.type) {
    case PrimitiveType::kTriangle:
      break;
    case PrimitiveType::kPoint: {
      const auto c = oracle_raw(prim.v[0]);
      if (!oracle::point_in_range(c))
        throw std::invalid_argument("the kernel accepted a point outside POINT.RANGE");
      for (std::int32_t y = 0; y < scene.height; ++y) {
        for (std::int32_t x = 0; x < scene.width; ++x) {
          if (!near_segment(c, c, centre_raw(x, y), kNearRaw))
            continue;
          if (oracle::point_covers(c, centre_raw(x, y), fill))
            exact[p].push_back(Key{y, x, -1});
        }
      }
      break;
    }
    case PrimitiveType::kLine:
    case PrimitiveType::kLineStrip: {
      const bool strip = prim.type == PrimitiveType::kLineStrip;
      for (std::size_t s = 0; s + 1 < prim.v.size(); ++s) {
        const std::int64_t seg = strip ? static_cast<std::int64_t>(s) : -1;
        const auto a = oracle_raw(prim.v[s]);
        const auto b = oracle_raw(prim.v[s + 1]);
        if (prim.aa) {
          // The pixels of oracle::aa_pixels (exact coverage > 0), asked only of candidates:
          // aa_check for the kernel's own fragments (positive and coverage in one go),
          // aa_compare with 0 for the others.
          std::vector<std::pair<std::int32_t, std::int32_t>> checked; // (y, x) of kernel fragments
          for (const Fragment& f : kernel) {
            if (f.prim != p || f.seg.value_or(0) != s || !f.coverage_q16)
              continue;
            checked.emplace_back(f.y, f.x);
            const oracle::AACheck c = oracle::aa_check(a, b, f.x, f.y, *f.coverage_q16);
            if (c.positive)
              exact[p].push_back(Key{f.y, f.x, seg});
            if (c.positive && !c.within_bound) {
              out.push_back("coverage " + std::to_string(*f.coverage_q16) + "/65536 at " +
                            key_text(p, Key{f.y, f.x, seg}) +
                            " is not within 1/65536 of the exact " + std::to_string(c.approx));
            }
          }
          std::sort(checked.begin(), checked.end());
          for (std::int32_t y = 0; y < scene.height; ++y) {
            for (std::int32_t x = 0; x < scene.width; ++x) {
              if (std::binary_search(checked.begin(), checked.end(), std::make_pair(y, x)))
                continue;
              if (!near_segment(a, b, centre_raw(x, y), kNearRaw))
                continue;
              if (oracle::aa_compare(a, b, x, y, 0, 1) > 0)
                exact[p].push_back(Key{y, x, seg});
            }
          }
        } else if (ps.line_mode == LineMode::kQuadWide || ps.line_mode == LineMode::kQuadNarrow) {
          const std::string name(io::line_mode_name(ps.line_mode));
          for (std::int32_t y = 0; y < scene.height; ++y) {
            for (std::int32_t x = 0; x < scene.width; ++x) {
              if (!near_segment(a, b, centre_raw(x, y), kNearRaw))
                continue;
              if (oracle::quad_line_covers(a, b, name, centre_raw(x, y), fill))
                exact[p].push_back(Key{y, x, seg});
            }
          }
        } else {
          const std::string name =
              ps.line_mode == LineMode::kD3DDiamond ? "d3d" : "vulkan-bresenham";
          // The pixels of oracle::aliased_line_pixels, asked only of candidates.
          for (std::int32_t y = 0; y < scene.height; ++y) {
            for (std::int32_t x = 0; x < scene.width; ++x) {
              if (!near_segment(a, b, centre_raw(x, y), kNearRaw))
                continue;
              if (oracle::aliased_line_covers(a, b, name, x, y))
                exact[p].push_back(Key{y, x, seg});
            }
          }
        }
      }
      break;
    }
    }
    compare_keys(p, mine[p], exact[p], out);
  }
  return out;
}

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
    }
    if (prim.aa && (prim.type == PrimitiveType::kTriangle || prim.type == PrimitiveType::kPoint)) {
      return at + ": aa on a triangle or point";
    }
    if (prim.aa && scene.line_mode != LineMode::kD3DDiamond)
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
  // n > 1 is bad input. MSAA.LINE.MODE: with n > 1 every line except a "vulkan-bresenham" one
  // is a quadrilateral line, which a centre pattern cannot draw.
  const std::size_t n = scene.msaa.pattern.positions.size();
  if (scene.msaa.sample_mask != 0xFFFFFFFFu && n < 32 && (scene.msaa.sample_mask >> n) != 0) {
    return "sample_mask: bits beyond the pattern";
  }
  for (const Primitive& prim : scene.primitives) {
    const bool line = prim.type == PrimitiveType::kLine || prim.type == PrimitiveType::kLineStrip;
    if (!line || n <= 1)
      continue;
    const bool bresenham = scene.line_mode == LineMode::kVulkanBresenham;
    if (bresenham && scene.msaa.shading == ShadingRate::kSample)
      return "shading: sample shading of Bresenham lines";
    if (!bresenham && scene.msaa.pattern.kind == PatternKind::kCenter)
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

} // namespace rastrules::fuzz

// SPDX-License-Identifier: MIT
// Generators for the multisampling properties: sample patterns (standard, centre, custom, some
// with hulls that miss the centre), tie-heavy vertices (on the 1/16 sample grid, on pixel
// centres and corners), multisampled scenes built twice (the kernel's Scene and the oracle's
// plain Input, from the same description), meshes with vertices on the sample grid, and the
// comparison of the two fragment lists.
// Implements (generators for): MSAA.PATTERN.STANDARD, MSAA.PATTERN.CENTER, MSAA.PATTERN.CUSTOM,
//   MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.LINE.MODE, MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10,
//   MSAA.QUAD.HELPER, MSAA.DERIV.FINE, MSAA.DERIV.COARSE

#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <rapidcheck.h>

#include "rastrules/gen/compare.hpp"
#include "rastrules/gen/triangles.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/oracle/msaa.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::msaa_gen {

namespace om = rastrules::oracle::msaa;
using Raw2 = om::Raw2;

// ---------------------------------------------------------------------------------------------
// Patterns

enum class PatternFamily { kStandard, kCenter, kCustom };

// A pattern as both sides see it: the kernel's (from ITS tables for standard and centre
// patterns) and the oracle's (from ITS tables), plus the family and count for tags.
struct Pattern {
  PatternFamily family = PatternFamily::kStandard;
  SamplePattern kernel;
  std::vector<om::Offset> oracle;
  [[nodiscard]] std::uint32_t count() const { return static_cast<std::uint32_t>(oracle.size()); }
  [[nodiscard]] std::string name() const {
    const char* f = family == PatternFamily::kStandard ? "standard"
                    : family == PatternFamily::kCenter ? "center"
                                                       : "custom";
    return std::string(f) + " " + std::to_string(count());
  }
};

inline Pattern standard(std::uint32_t n) {
  return Pattern{PatternFamily::kStandard, standard_pattern(n), om::standard_pattern(n)};
}
inline Pattern centre(std::uint32_t n) {
  return Pattern{PatternFamily::kCenter, center_pattern(n), om::center_pattern(n)};
}
inline Pattern custom(const std::vector<om::Offset>& offsets) {
  std::vector<SampleOffset> k;
  for (const om::Offset& o : offsets)
    k.push_back(SampleOffset{static_cast<std::int8_t>(o.x), static_cast<std::int8_t>(o.y)});
  return Pattern{PatternFamily::kCustom, custom_pattern(k), offsets};
}

inline const std::vector<std::uint32_t>& standard_counts() {
  static const std::vector<std::uint32_t> k = {1, 2, 4, 8, 16};
  return k;
}

// RapidCheck scales integer ranges with the test's size (small values first); these
// generators run at full size so that early cases are as varied as late ones.
template <class T> rc::Gen<T> full_size(rc::Gen<T> g) {
  return rc::gen::resize(100, std::move(g));
}

// Custom offsets: anywhere on the grid, clustered in one quadrant (hull misses the centre),
// on the grid's limits (-8 and 7), with repeats.
inline rc::Gen<std::vector<om::Offset>> custom_offsets() {
  return full_size<std::vector<om::Offset>>(rc::gen::exec([] {
    const auto n = static_cast<std::size_t>(*rc::gen::inRange(1, 17));
    const int style = *rc::gen::inRange(0, 4);
    std::vector<om::Offset> v;
    for (std::size_t i = 0; i < n; ++i) {
      om::Offset o;
      switch (style) {
      case 0: // anywhere
        o = {*rc::gen::inRange(-8, 8), *rc::gen::inRange(-8, 8)};
        break;
      case 1: // one quadrant, off the axes: the centre is outside the hull
        o = {*rc::gen::inRange(1, 8), *rc::gen::inRange(-8, 0)};
        break;
      case 2: // the corners and edges of the grid
        o = {*rc::gen::element(-8, 7, 0), *rc::gen::element(-8, 7, 0, 3)};
        break;
      default: // repeats of a few positions
        o = i > 0 && *rc::gen::inRange(0, 3) == 0
                ? v[static_cast<std::size_t>(*rc::gen::inRange<std::size_t>(0, i))]
                : om::Offset{*rc::gen::inRange(-8, 8), *rc::gen::inRange(-8, 8)};
      }
      v.push_back(o);
    }
    return v;
  }));
}

inline rc::Gen<Pattern> any_pattern() {
  return full_size(rc::gen::weightedOneOf<Pattern>(
      {{3, rc::gen::map(rc::gen::elementOf(standard_counts()),
                        [](std::uint32_t n) { return standard(n); })},
       {1, rc::gen::map(rc::gen::elementOf(standard_counts()),
                        [](std::uint32_t n) { return centre(n); })},
       {2, rc::gen::map(custom_offsets(),
                        [](const std::vector<om::Offset>& o) { return custom(o); })}}));
}

// A sample mask within the pattern: full (often), random, one bit, empty.
inline rc::Gen<std::uint32_t> sample_mask(std::uint32_t n) {
  const std::uint32_t all = full_mask(n);
  return full_size(rc::gen::weightedOneOf<std::uint32_t>(
      {{3, rc::gen::just(all)},
       {3, rc::gen::map(rc::gen::arbitrary<std::uint32_t>(),
                        [all](std::uint32_t r) { return r & all; })},
       {1, rc::gen::map(rc::gen::inRange<std::uint32_t>(0, n),
                        [](std::uint32_t k) { return 1u << k; })},
       {1, rc::gen::map(rc::gen::inRange<std::uint32_t>(0, n),
                        [all](std::uint32_t k) { return all & ~(1u << k); })}}));
}

// ---------------------------------------------------------------------------------------------
// Vertices and primitives

// One raw coordinate near [0, side] px: on the 1/16 sample grid (samples on edges), on pixel
// centres, on pixel corners, or anywhere on the 1/256 grid.
inline rc::Gen<std::int64_t> coord(std::int32_t side) {
  const std::int64_t lo = -256, hi = (std::int64_t{side} + 1) * 256;
  return full_size(rc::gen::weightedOneOf<std::int64_t>(
      {{4, rc::gen::map(rc::gen::inRange<std::int64_t>(lo / 16, hi / 16 + 1),
                        [](std::int64_t k) { return 16 * k; })},
       {2, rc::gen::map(rc::gen::inRange<std::int64_t>(-1, side + 1),
                        [](std::int64_t k) { return 256 * k + 128; })},
       {1, rc::gen::map(rc::gen::inRange<std::int64_t>(-1, side + 2),
                        [](std::int64_t k) { return 256 * k; })},
       {2, rc::gen::inRange<std::int64_t>(lo, hi + 1)}}));
}

inline rc::Gen<Raw2> vertex(std::int32_t w, std::int32_t h) {
  return rc::gen::map(rc::gen::pair(coord(w), coord(h)),
                      [](const std::pair<std::int64_t, std::int64_t>& p) {
                        return Raw2{p.first, p.second};
                      });
}

struct Prim {
  PrimitiveType type = PrimitiveType::kTriangle;
  std::vector<Raw2> v;
  bool aa = false;
  Rgba8 color = {255, 255, 255, 255};
};

inline rc::Gen<Prim> prim(std::int32_t w, std::int32_t h, bool lines, bool points) {
  return full_size<Prim>(rc::gen::exec([=] {
    Prim p;
    const int t = *rc::gen::weightedElement<int>(
        {{4, 0}, {points ? 2u : 0u, 1}, {lines ? 2u : 0u, 2}, {lines ? 1u : 0u, 3}});
    const auto v = vertex(w, h);
    switch (t) {
    case 0: {
      p.type = PrimitiveType::kTriangle;
      p.v = {*v, *v, *v};
      // A shared axis now and then: horizontal and vertical edges.
      const int tie = *rc::gen::inRange(0, 4);
      if (tie == 1)
        p.v[1][1] = p.v[0][1];
      if (tie == 2)
        p.v[2][0] = p.v[1][0];
      break;
    }
    case 1:
      p.type = PrimitiveType::kPoint;
      p.v = {*v};
      break;
    case 2: {
      p.type = PrimitiveType::kLine;
      const Raw2 a = *v;
      const int shape = *rc::gen::inRange(0, 5);
      Raw2 b = *v;
      if (shape == 1)
        b[1] = a[1]; // horizontal
      if (shape == 2)
        b[0] = a[0]; // vertical
      if (shape == 3)
        b = {a[0] + (b[0] - a[0]), a[1] + (b[0] - a[0])}; // 45 degrees
      if (shape == 4 && *rc::gen::inRange(0, 4) == 0)
        b = a; // zero length
      p.v = {a, b};
      p.aa = *rc::gen::inRange(0, 4) == 0;
      break;
    }
    default: {
      p.type = PrimitiveType::kLineStrip;
      const auto k = *rc::gen::inRange(2, 5);
      for (int i = 0; i < k; ++i)
        p.v.push_back(*v);
      p.aa = *rc::gen::inRange(0, 4) == 0;
    }
    }
    p.color = *rc::gen::arbitrary<std::array<std::uint8_t, 4>>();
    return p;
  }));
}

// ---------------------------------------------------------------------------------------------
// Scenes

struct MsScene {
  std::int32_t width = 1;
  std::int32_t height = 1;
  RasterState state;
  LineMode line_mode = LineMode::kD3DDiamond;
  bool multisample_enable = false; // D3D's MultisampleEnable (MSAA.LINE.MODE)
  Pattern pattern;
  std::uint32_t sample_mask = 0xFFFFFFFFu;
  std::optional<CentroidRule> centroid;
  ShadingRate shading = ShadingRate::kPixel;
  bool quads = false;
  DerivativeMode derivatives = DerivativeMode::kNone;
  Rgba8 clear_color = {0, 0, 0, 0};
  std::vector<Prim> prims;
};

inline bool is_quad_line_mode(LineMode m, std::uint32_t n, bool multisample_enable) {
  return m == LineMode::kQuadWide || m == LineMode::kQuadNarrow ||
         (m == LineMode::kD3DDiamond && n > 1 && multisample_enable);
}

// Makes a scene valid input (spec/rules/msaa.md): no quadrilateral lines on a centre pattern of
// several samples (Bresenham instead), no sample shading of Bresenham lines with several
// samples (pixel shading instead), "aa" only on d3d lines drawn as quadrilaterals (with one
// sample antialiased lines are the line_aa area's; without MultisampleEnable they keep their
// coverage, which check_against_oracle compares: AntialiasedLinesWithoutMultisampleEnable).
inline void make_valid(MsScene& s) {
  const std::uint32_t n = s.pattern.count();
  const bool has_lines = std::any_of(s.prims.begin(), s.prims.end(), [](const Prim& p) {
    return p.type == PrimitiveType::kLine || p.type == PrimitiveType::kLineStrip;
  });
  if (has_lines && s.pattern.family == PatternFamily::kCenter && n > 1 &&
      is_quad_line_mode(s.line_mode, n, s.multisample_enable))
    s.line_mode = LineMode::kVulkanBresenham;
  if (has_lines && n > 1 && s.line_mode == LineMode::kVulkanBresenham)
    s.shading = ShadingRate::kPixel;
  for (Prim& p : s.prims) {
    if (!is_quad_line_mode(s.line_mode, n, s.multisample_enable) ||
        s.line_mode != LineMode::kD3DDiamond)
      p.aa = false;
  }
  s.sample_mask &= full_mask(n);
}

// A random scene on the given pattern; options all random.
inline rc::Gen<MsScene> scene_on(const Pattern& pattern, std::int32_t max_side, bool lines = true,
                                 bool points = true) {
  return full_size<MsScene>(rc::gen::exec([=] {
    MsScene s;
    const auto side = rc::gen::weightedOneOf<std::int32_t>(
        {{1, rc::gen::inRange(1, max_side + 1)},
         {3, rc::gen::inRange(max_side / 2 + 1, max_side + 1)}});
    s.width = *side;
    s.height = *side;
    s.state = *gen::raster_state();
    s.line_mode = *rc::gen::element(LineMode::kD3DDiamond, LineMode::kVulkanBresenham,
                                    LineMode::kQuadWide, LineMode::kQuadNarrow);
    s.multisample_enable = *rc::gen::arbitrary<bool>();
    s.pattern = pattern;
    s.sample_mask = *sample_mask(pattern.count());
    if (*rc::gen::inRange(0, 3) != 0)
      s.centroid = *rc::gen::element(CentroidRule::kD3D11, CentroidRule::kD3D10);
    s.shading = *rc::gen::element(ShadingRate::kPixel, ShadingRate::kPixel, ShadingRate::kSample);
    s.quads = *rc::gen::arbitrary<bool>();
    s.derivatives =
        *rc::gen::element(DerivativeMode::kNone, DerivativeMode::kFine, DerivativeMode::kCoarse);
    s.clear_color = *rc::gen::arbitrary<std::array<std::uint8_t, 4>>();
    const auto k = *rc::gen::inRange(1, 5);
    for (int i = 0; i < k; ++i)
      s.prims.push_back(*prim(s.width, s.height, lines, points));
    make_valid(s);
    return s;
  }));
}

inline FloatPoint to_float(const Raw2& r) {
  return FloatPoint{static_cast<float>(r[0]) / 256.0f, static_cast<float>(r[1]) / 256.0f};
}

inline Scene to_kernel(const MsScene& s) {
  Scene k;
  k.width = s.width;
  k.height = s.height;
  set_raster_state(k, s.state);
  k.conventions.line_mode = s.line_mode;
  k.conventions.multisample_enable = s.multisample_enable;
  set_sample_pattern(k, s.pattern.kernel);
  k.msaa.sample_mask = s.sample_mask;
  k.msaa.has_centroid = s.centroid.has_value();
  k.conventions.centroid = s.centroid.value_or(CentroidRule::kD3D11);
  k.msaa.shading = s.shading;
  k.msaa.quads = s.quads;
  k.msaa.derivatives = s.derivatives;
  k.clear_color = s.clear_color;
  for (const Prim& p : s.prims) {
    Primitive q;
    q.type = p.type;
    q.v.clear();
    for (const Raw2& r : p.v)
      q.v.push_back(to_float(r));
    q.aa = p.aa;
    q.color = p.color;
    k.primitives.push_back(q);
  }
  return k;
}

inline std::string line_mode_name(LineMode m) {
  switch (m) {
  case LineMode::kD3DDiamond:
    return "d3d";
  case LineMode::kVulkanBresenham:
    return "vulkan-bresenham";
  case LineMode::kQuadWide:
    return "quad-wide";
  case LineMode::kQuadNarrow:
    return "quad-narrow";
  }
  return "?";
}

inline om::Input to_oracle(const MsScene& s) {
  om::Input o;
  o.width = s.width;
  o.height = s.height;
  o.state = gen::to_oracle_state(s.state);
  o.line_mode = line_mode_name(s.line_mode);
  o.multisample_enable = s.multisample_enable;
  o.pattern = s.pattern.oracle;
  o.sample_mask = s.sample_mask;
  if (s.centroid)
    o.centroid = *s.centroid == CentroidRule::kD3D11 ? "d3d11" : "d3d10";
  o.shading = s.shading == ShadingRate::kSample ? "sample" : "pixel";
  o.quads = s.quads;
  o.derivatives = s.derivatives == DerivativeMode::kFine     ? "fine"
                  : s.derivatives == DerivativeMode::kCoarse ? "coarse"
                                                             : "none";
  o.clear_color = s.clear_color;
  for (const Prim& p : s.prims) {
    om::Primitive q;
    q.type = std::string(to_string(p.type));
    q.v = p.v;
    q.aa = p.aa;
    q.color = p.color;
    o.primitives.push_back(q);
  }
  return o;
}

inline void show(const MsScene& s, std::ostream& os) {
  os << "scene " << s.width << "x" << s.height << " cull " << to_string(s.state.cull) << " front "
     << to_string(s.state.front_face) << " fill " << to_string(s.state.fill) << " line_mode "
     << line_mode_name(s.line_mode) << " multisample_enable " << s.multisample_enable
     << "\n  pattern " << s.pattern.name() << ":";
  for (const om::Offset& o : s.pattern.oracle)
    os << " (" << o.x << "," << o.y << ")";
  os << "\n  sample_mask 0x" << std::hex << s.sample_mask << std::dec << " centroid "
     << (s.centroid ? std::string(to_string(*s.centroid)) : "none") << " shading "
     << to_string(s.shading) << " quads " << s.quads << " derivatives " << to_string(s.derivatives)
     << "\n";
  for (const Prim& p : s.prims) {
    os << "  " << to_string(p.type) << (p.aa ? " aa" : "") << " raw";
    for (const Raw2& r : p.v)
      os << " (" << r[0] << "," << r[1] << ")";
    os << "\n";
  }
}

// ---------------------------------------------------------------------------------------------
// Comparison

inline om::Branch to_oracle(CentroidBranch b) {
  switch (b) {
  case CentroidBranch::kFullCoverageCenter:
    return om::Branch::kFullCoverageCenter;
  case CentroidBranch::kFirstCovered:
    return om::Branch::kFirstCovered;
  case CentroidBranch::kNearestCovered:
    return om::Branch::kNearestCovered;
  case CentroidBranch::kNoneCoveredMaskSample:
    return om::Branch::kNoneCoveredMaskSample;
  case CentroidBranch::kNoneCoveredCenter:
    return om::Branch::kNoneCoveredCenter;
  }
  return om::Branch::kFullCoverageCenter;
}

inline om::CentroidPoint to_oracle(const Centroid& c) {
  return om::CentroidPoint{om::Offset{c.offset.x, c.offset.y}, to_oracle(c.branch)};
}

} // namespace rastrules::msaa_gen

// SPDX-License-Identifier: MIT
// Comparison of a driver's coverage with the reference kernel, exact or legal.
// Implements: FUZZ.COMPARE.EXACT, FUZZ.COMPARE.LEGAL, FUZZ.COMPARE.LEGAL_LINES

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <tuple>
#include <variant>

#include "rastrules/fuzzer/fuzzer.hpp"

namespace rastrules::fuzzer {

std::vector<Fragment> observable(const std::vector<Fragment>& fragments) {
  std::map<std::tuple<std::uint32_t, std::int32_t, std::int32_t>, std::uint32_t> masks;
  for (const Fragment& f : fragments) {
    if (f.helper || f.mask == 0)
      continue;
    masks[{f.prim, f.y, f.x}] |= f.mask;
  }
  std::vector<Fragment> out;
  out.reserve(masks.size());
  for (const auto& [key, mask] : masks)
    out.emplace_back(std::get<0>(key), std::get<2>(key), std::get<1>(key), mask);
  return out;
}

namespace {

// Both lists observable (sorted by (prim, y, x), one entry each).
void diff(const std::vector<Fragment>& expected, const std::vector<Fragment>& actual,
          Comparison& c) {
  c.missing.clear();
  c.extra.clear();
  std::size_t i = 0, j = 0;
  const auto key = [](const Fragment& f) { return std::tuple(f.prim, f.y, f.x); };
  while (i < expected.size() || j < actual.size()) {
    if (j == actual.size() || (i < expected.size() && key(expected[i]) < key(actual[j]))) {
      const Fragment& e = expected[i++];
      c.missing.push_back({e.prim, e.x, e.y, e.mask});
    } else if (i == expected.size() || key(actual[j]) < key(expected[i])) {
      const Fragment& a = actual[j++];
      c.extra.push_back({a.prim, a.x, a.y, a.mask});
    } else {
      const Fragment& e = expected[i++];
      const Fragment& a = actual[j++];
      if ((e.mask & ~a.mask) != 0)
        c.missing.push_back({e.prim, e.x, e.y, e.mask & ~a.mask});
      if ((a.mask & ~e.mask) != 0)
        c.extra.push_back({a.prim, a.x, a.y, a.mask & ~e.mask});
    }
  }
}

std::optional<std::vector<Fragment>> reference_raw(const Scene& scene, std::string* error) {
  auto r = render(scene);
  if (auto* e = std::get_if<SceneError>(&r)) {
    if (error != nullptr)
      *error = "the reference rejects the scene: " + e->what();
    return std::nullopt;
  }
  return std::get<std::vector<Fragment>>(std::move(r));
}

// The pixels (with their union mask) of one segment of one line primitive.
using SegmentPixels = std::map<std::pair<std::int32_t, std::int32_t>, std::uint32_t>;
// (prim, seg) -> pixels; nullopt when a strip's fragment carries no segment index.
using Segments = std::map<std::pair<std::uint32_t, std::uint32_t>, SegmentPixels>;

bool relaxed_line(const Scene& scene, std::uint32_t prim) {
  if (prim >= scene.primitives.size())
    return false;
  const Primitive& p = scene.primitives[prim];
  return (p.type == PrimitiveType::kLine || p.type == PrimitiveType::kLineStrip) && !p.aa &&
         scene.conventions.line_mode == LineMode::kVulkanBresenham;
}

std::optional<Segments> line_segments(const Scene& scene, const std::vector<Fragment>& fragments) {
  Segments out;
  for (const Fragment& f : fragments) {
    if (f.helper || f.mask == 0 || !relaxed_line(scene, f.prim))
      continue;
    const bool strip = scene.primitives[f.prim].type == PrimitiveType::kLineStrip;
    if (strip && !f.seg)
      return std::nullopt;
    out[{f.prim, strip ? *f.seg : 0u}][{f.x, f.y}] |= f.mask;
  }
  return out;
}

// rule: FUZZ.COMPARE.LEGAL_LINES
// One segment's pixels `got` against the diamond-exit pixels `exact`: the count within one,
// every pixel within one pixel (both axes) of an exact one (of a pixel holding an end point
// when there is none), at most one pixel per column of an x-major segment (row of a y-major
// one; either for a diagonal), and every pixel with the mask the reference gives its pixels.
bool segment_within_allowance(const SegmentPixels& got, const SegmentPixels& exact,
                              std::array<float, 2> a, std::array<float, 2> b,
                              std::uint32_t full_mask) {
  if (got.size() + 1 < exact.size() || exact.size() + 1 < got.size())
    return false;
  const std::uint32_t mask = exact.empty() ? full_mask : exact.begin()->second;
  const auto near = [](std::int64_t px, std::int64_t py, std::int64_t qx, std::int64_t qy) {
    return std::abs(px - qx) <= 1 && std::abs(py - qy) <= 1;
  };
  const auto floor_of = [](float v) { return static_cast<std::int64_t>(std::floor(v)); };
  for (const auto& [xy, m] : got) {
    if (m != mask)
      return false;
    bool ok = false;
    if (exact.empty()) {
      ok = near(xy.first, xy.second, floor_of(a[0]), floor_of(a[1])) ||
           near(xy.first, xy.second, floor_of(b[0]), floor_of(b[1]));
    }
    for (const auto& e : exact) {
      ok = ok || near(xy.first, xy.second, e.first.first, e.first.second);
      if (ok)
        break;
    }
    if (!ok)
      return false;
  }
  const float dx = std::abs(b[0] - a[0]), dy = std::abs(b[1] - a[1]);
  const auto one_per = [&](bool by_x) {
    std::set<std::int32_t> seen;
    for (const auto& entry : got) {
      if (!seen.insert(by_x ? entry.first.first : entry.first.second).second)
        return false;
    }
    return true;
  };
  return (dx >= dy && one_per(true)) || (dy >= dx && one_per(false));
}

// Whether the driver's fragments equal the reference's (both raw) except in Bresenham line
// segments, each of which deviates only as Vulkan and OpenGL allow.
// rule: FUZZ.COMPARE.LEGAL_LINES
bool equal_within_line_allowance(const Scene& scene, const std::vector<Fragment>& expected,
                                 const std::vector<Fragment>& actual) {
  std::vector<Fragment> e_rest, a_rest;
  for (const Fragment& f : expected)
    if (!relaxed_line(scene, f.prim))
      e_rest.push_back(f);
  for (const Fragment& f : actual)
    if (!relaxed_line(scene, f.prim))
      a_rest.push_back(f);
  if (observable(e_rest) != observable(a_rest))
    return false;
  const auto e = line_segments(scene, expected);
  const auto a = line_segments(scene, actual);
  if (!e || !a)
    return false;
  const std::uint32_t full = scene.msaa.effective_mask();
  static const SegmentPixels kNone;
  for (std::uint32_t p = 0; p < scene.primitives.size(); ++p) {
    if (!relaxed_line(scene, p))
      continue;
    const auto& v = scene.primitives[p].v;
    for (std::uint32_t k = 0; k + 1 < v.size(); ++k) {
      const auto ei = e->find({p, k});
      const auto ai = a->find({p, k});
      if (!segment_within_allowance(ai == a->end() ? kNone : ai->second,
                                    ei == e->end() ? kNone : ei->second, {v[k][0], v[k][1]},
                                    {v[k + 1][0], v[k + 1][1]}, full))
        return false;
    }
  }
  // No fragment of a segment the primitive does not have.
  for (const auto& [key, pixels] : *a) {
    if (key.second + 1 >= scene.primitives[key.first].v.size())
      return false;
  }
  return true;
}

} // namespace

// rule: FUZZ.COMPARE.EXACT, FUZZ.COMPARE.LEGAL, FUZZ.COMPARE.LEGAL_LINES
std::optional<Comparison> compare(const Scene& scene, const std::vector<Fragment>& actual,
                                  Profile profile, Mode mode, std::string* error) {
  Comparison c;
  c.actual = observable(actual);
  c.compared_with = scene.conventions.fill;
  auto own_raw = reference_raw(scene, error);
  if (!own_raw)
    return std::nullopt;
  c.expected = observable(*own_raw);
  diff(c.expected, c.actual, c);
  c.match = c.missing.empty() && c.extra.empty();
  if (c.match)
    c.conventions.push_back(scene.conventions.fill);
  // d3d11 requires the top-left rule and the diamond-exit lines: legal is exact there.
  if (mode == Mode::kExact || profile == Profile::kD3D11)
    return c;
  // Vulkan and OpenGL allow any fill convention that is applied consistently (the order of
  // FillConvention), and Bresenham lines within their allowance; the scene's own result stays
  // the one shown when nothing explains the driver's.
  bool lines_relaxed = false;
  for (const FillConvention f : {FillConvention::kTopLeft, FillConvention::kTopRight,
                                 FillConvention::kBottomLeft, FillConvention::kBottomRight}) {
    std::optional<std::vector<Fragment>> raw;
    if (f == scene.conventions.fill) {
      raw = own_raw;
    } else {
      Scene other = scene;
      other.conventions.fill = f;
      raw = reference_raw(other, error);
      if (!raw)
        return std::nullopt;
    }
    std::vector<Fragment> expected = observable(*raw);
    bool explains = expected == c.actual;
    bool by_lines = false;
    if (!explains && equal_within_line_allowance(scene, *raw, actual))
      explains = by_lines = true;
    if (!explains)
      continue;
    if (f != scene.conventions.fill || by_lines)
      c.conventions.push_back(f);
    if (!c.match) {
      c.match = true;
      lines_relaxed = by_lines;
      c.compared_with = f;
      c.expected = std::move(expected);
      c.missing.clear();
      c.extra.clear();
    }
  }
  c.line_allowance = lines_relaxed;
  std::sort(c.conventions.begin(), c.conventions.end());
  c.conventions.erase(std::unique(c.conventions.begin(), c.conventions.end()), c.conventions.end());
  return c;
}

std::optional<Comparison> draw_and_compare(driver::Driver& driver, const Scene& scene,
                                           Profile profile, Mode mode, std::string* error) {
  if (const std::string why = driver.unsupported(scene); !why.empty()) {
    if (error != nullptr)
      *error = "the driver cannot draw the scene: " + why;
    return std::nullopt;
  }
  if (auto prepared = prepare(scene); std::holds_alternative<SceneError>(prepared)) {
    if (error != nullptr)
      *error = "the reference rejects the scene: " + std::get<SceneError>(prepared).what();
    return std::nullopt;
  }
  driver::DrawResult r = driver.draw(scene);
  if (auto* e = std::get_if<driver::DriverError>(&r)) {
    if (error != nullptr)
      *error = e->message;
    return std::nullopt;
  }
  return compare(scene, std::get<std::vector<Fragment>>(r), profile, mode, error);
}

} // namespace rastrules::fuzzer

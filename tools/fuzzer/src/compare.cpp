// SPDX-License-Identifier: MIT
// Comparison of a driver's coverage with the reference kernel, exact or legal.
// Implements: FUZZ.COMPARE.EXACT, FUZZ.COMPARE.LEGAL, FUZZ.COMPARE.LEGAL_LINES,
//             FUZZ.COMPARE.LEGAL_TIES (and, with values.cpp, FUZZ.VALUES.*)

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <tuple>
#include <variant>

#include "rastrules/fuzzer/fuzzer.hpp"
#include "rastrules/pipeline.hpp"

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

// rule: FUZZ.COMPARE.LEGAL_LINES
// Whether primitive p's fragments (raw, of p only) deviate from the reference's only as a
// Bresenham line may, segment by segment.
bool line_within_allowance(const Scene& scene, std::uint32_t p,
                           const std::vector<Fragment>& expected,
                           const std::vector<Fragment>& actual) {
  const auto e = line_segments(scene, expected);
  const auto a = line_segments(scene, actual);
  if (!e || !a)
    return false;
  static const SegmentPixels kNone;
  const auto& v = scene.primitives[p].v;
  for (std::uint32_t k = 0; k + 1 < v.size(); ++k) {
    const auto ei = e->find({p, k});
    const auto ai = a->find({p, k});
    if (!segment_within_allowance(ai == a->end() ? kNone : ai->second,
                                  ei == e->end() ? kNone : ei->second, {v[k][0], v[k][1]},
                                  {v[k + 1][0], v[k + 1][1]}, scene.msaa.effective_mask()))
      return false;
  }
  // No fragment of a segment the primitive does not have.
  for (const auto& [key, pixels] : *a) {
    if (key.second + 1 >= v.size())
      return false;
  }
  return true;
}

// rule: FUZZ.COMPARE.LEGAL_TIES
// Whether primitive p, with some of its coordinates that lie exactly half a subpixel between
// two 16.8 values rounded the other way (up where SNAP.VERTEX.ROUND rounds down to even, and
// the converse), gives the driver's fragments `actual` (observable, of p only).
bool tie_rounding_explains(const Scene& scene, std::uint32_t p,
                           const std::vector<Fragment>& actual) {
  struct Tie {
    std::size_t vertex;
    int axis;
    float other;
  };
  std::vector<Tie> ties;
  const auto& v = scene.primitives[p].v;
  for (std::size_t k = 0; k < v.size(); ++k) {
    for (int axis = 0; axis < 2; ++axis) {
      const double raw = static_cast<double>(v[k][static_cast<std::size_t>(axis)]) * 256.0;
      const double below = std::floor(raw);
      if (raw - below != 0.5)
        continue;
      // Round half to even takes the even neighbour; the other rounding takes the odd one.
      const double odd = std::fmod(below, 2.0) == 0.0 ? below + 1.0 : below;
      ties.push_back({k, axis, static_cast<float>(odd / 256.0)});
    }
  }
  constexpr std::size_t kMaxTies = 8;
  if (ties.empty() || ties.size() > kMaxTies)
    return false;
  for (std::uint32_t pick = 1; pick < (1u << ties.size()); ++pick) {
    Scene other = scene;
    for (std::size_t t = 0; t < ties.size(); ++t) {
      if ((pick >> t & 1u) != 0)
        other.primitives[p].v[ties[t].vertex][static_cast<std::size_t>(ties[t].axis)] =
            ties[t].other;
    }
    auto r = render(other);
    if (!std::holds_alternative<std::vector<Fragment>>(r))
      continue;
    std::vector<Fragment> mine;
    for (const Fragment& f : std::get<std::vector<Fragment>>(r)) {
      if (f.prim == p)
        mine.push_back(f);
    }
    if (observable(mine) == actual)
      return true;
  }
  return false;
}

// Whether the driver's fragments equal the reference's (both raw, the scene under one fill
// convention) primitive by primitive, each exactly, or a Bresenham line within its allowance
// (*lines set), or with ties of its coordinates rounded the other way (*ties set).
// rule: FUZZ.COMPARE.LEGAL_LINES, FUZZ.COMPARE.LEGAL_TIES
bool equal_within_allowances(const Scene& scene, const std::vector<Fragment>& expected,
                             const std::vector<Fragment>& actual, bool* lines, bool* ties) {
  const std::size_t n = scene.primitives.size();
  std::vector<std::vector<Fragment>> e(n), a(n);
  for (const Fragment& f : expected) {
    if (f.prim < n)
      e[f.prim].push_back(f);
  }
  for (const Fragment& f : actual) {
    if (f.prim >= n)
      return false;
    a[f.prim].push_back(f);
  }
  bool used_lines = false, used_ties = false;
  for (std::uint32_t p = 0; p < n; ++p) {
    const std::vector<Fragment> got = observable(a[p]);
    if (observable(e[p]) == got)
      continue;
    if (relaxed_line(scene, p) && line_within_allowance(scene, p, e[p], a[p])) {
      used_lines = true;
      continue;
    }
    if (scene.primitives[p].type != PrimitiveType::kPath && tie_rounding_explains(scene, p, got)) {
      used_ties = true;
      continue;
    }
    return false;
  }
  *lines = used_lines;
  *ties = used_ties;
  return true;
}

} // namespace

// rule: FUZZ.COMPARE.EXACT, FUZZ.COMPARE.LEGAL, FUZZ.COMPARE.LEGAL_LINES
// rule: FUZZ.COMPARE.LEGAL_TIES
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
  bool lines_relaxed = false, ties_relaxed = false;
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
    bool by_lines = false, by_ties = false;
    if (!explains) {
      Scene under = scene;
      under.conventions.fill = f;
      explains = equal_within_allowances(under, *raw, actual, &by_lines, &by_ties);
    }
    if (!explains)
      continue;
    if (f != scene.conventions.fill || by_lines || by_ties)
      c.conventions.push_back(f);
    if (!c.match) {
      c.match = true;
      lines_relaxed = by_lines;
      ties_relaxed = by_ties;
      c.compared_with = f;
      c.expected = std::move(expected);
      c.missing.clear();
      c.extra.clear();
    }
  }
  c.line_allowance = lines_relaxed;
  c.tie_rounding = ties_relaxed;
  std::sort(c.conventions.begin(), c.conventions.end());
  c.conventions.erase(std::unique(c.conventions.begin(), c.conventions.end()), c.conventions.end());
  return c;
}

// rule: FUZZ.VALUES.EXACT, FUZZ.VALUES.LEGAL
std::optional<Comparison> draw_and_compare(driver::Driver& driver, const Scene& scene,
                                           Profile profile, Mode mode, std::string* error) {
  if (const std::string why = driver.unsupported(scene); !why.empty()) {
    if (error != nullptr)
      *error = "the driver cannot draw the scene: " + why;
    return std::nullopt;
  }
  // A pipeline scene is validated (run_pipeline draws it), any other prepared.
  if (auto checked = pipe::check_scene(scene); std::holds_alternative<SceneError>(checked)) {
    if (error != nullptr)
      *error = "the reference rejects the scene: " + std::get<SceneError>(checked).what();
    return std::nullopt;
  }
  // rule: DRIVER.VALUES
  const bool values = driver.info().values && has_pipeline_state(scene);
  driver::ValuesResult r = values ? driver.draw_values(scene) : [&]() -> driver::ValuesResult {
    driver::DrawResult d = driver.draw(scene);
    if (auto* e = std::get_if<driver::DriverError>(&d))
      return std::move(*e);
    return driver::Drawing{std::get<std::vector<Fragment>>(std::move(d)), {}};
  }();
  if (auto* e = std::get_if<driver::DriverError>(&r)) {
    if (error != nullptr)
      *error = e->message;
    return std::nullopt;
  }
  const driver::Drawing& drawing = std::get<driver::Drawing>(r);
  auto c = compare(scene, drawing.fragments, profile, mode, error);
  if (!c || drawing.values.empty())
    return c;
  auto v = compare_values(scene, drawing, profile, mode, error);
  if (!v)
    return std::nullopt;
  c->values = std::move(*v);
  if (c->values->beyond != 0)
    c->match = false;
  return c;
}

} // namespace rastrules::fuzzer

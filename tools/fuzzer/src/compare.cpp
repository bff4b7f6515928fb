// SPDX-License-Identifier: MIT
// Comparison of a driver's coverage with the reference kernel, exact or legal.
// Implements: FUZZ.COMPARE.EXACT, FUZZ.COMPARE.LEGAL

#include <algorithm>
#include <array>
#include <map>
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

std::optional<std::vector<Fragment>> reference(const Scene& scene, std::string* error) {
  auto r = render(scene);
  if (auto* e = std::get_if<SceneError>(&r)) {
    if (error != nullptr)
      *error = "the reference rejects the scene: " + e->what();
    return std::nullopt;
  }
  return observable(std::get<std::vector<Fragment>>(r));
}

} // namespace

// rule: FUZZ.COMPARE.EXACT, FUZZ.COMPARE.LEGAL
std::optional<Comparison> compare(const Scene& scene, const std::vector<Fragment>& actual,
                                  Profile profile, Mode mode, std::string* error) {
  Comparison c;
  c.actual = observable(actual);
  c.compared_with = scene.conventions.fill;
  auto own = reference(scene, error);
  if (!own)
    return std::nullopt;
  c.expected = std::move(*own);
  diff(c.expected, c.actual, c);
  c.match = c.missing.empty() && c.extra.empty();
  if (c.match)
    c.conventions.push_back(scene.conventions.fill);
  // d3d11 requires the top-left rule: legal is exact there.
  if (mode == Mode::kExact || profile == Profile::kD3D11)
    return c;
  // Vulkan and OpenGL allow any fill convention that is applied consistently: try the others
  // (the order of FillConvention), keeping the scene's own result as the one shown.
  for (const FillConvention f : {FillConvention::kTopLeft, FillConvention::kTopRight,
                                 FillConvention::kBottomLeft, FillConvention::kBottomRight}) {
    if (f == scene.conventions.fill)
      continue;
    Scene other = scene;
    other.conventions.fill = f;
    auto expected = reference(other, error);
    if (!expected)
      return std::nullopt;
    if (*expected == c.actual) {
      c.conventions.push_back(f);
      if (!c.match) {
        c.match = true;
        c.compared_with = f;
        c.expected = std::move(*expected);
        c.missing.clear();
        c.extra.clear();
      }
    }
  }
  std::sort(c.conventions.begin(), c.conventions.end());
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

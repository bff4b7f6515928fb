// SPDX-License-Identifier: MIT
// Profiles, the seeded generator and the scene families.
// Implements: FUZZ.PROFILE, FUZZ.GENERATE

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "rastrules/fuzzer/fuzzer.hpp"

namespace rastrules::fuzzer {

std::string_view to_string(Profile p) {
  return name_of(p);
}

std::optional<Profile> parse_profile(std::string_view s) {
  return from_name<Profile>(s);
}

std::string_view to_string(Mode m) {
  return m == Mode::kExact ? "exact" : "legal";
}

std::optional<Mode> parse_mode(std::string_view s) {
  if (s == "exact")
    return Mode::kExact;
  if (s == "legal")
    return Mode::kLegal;
  return std::nullopt;
}

// rule: FUZZ.PROFILE
void apply_profile(Profile p, Scene& scene) {
  const Conventions c = profile(p);
  scene.conventions.fill = c.fill;
  scene.conventions.line_mode = c.line_mode;
}

std::uint64_t Rng::next() {
  std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

std::int64_t Rng::uniform(std::int64_t lo, std::int64_t hi) {
  const auto span = static_cast<std::uint64_t>(hi - lo) + 1;
  if (span == 0)
    return static_cast<std::int64_t>(next());
  // Rejection sampling keeps the distribution exact (and the sequence deterministic).
  const std::uint64_t limit = UINT64_MAX - UINT64_MAX % span;
  std::uint64_t r = next();
  while (r >= limit)
    r = next();
  return lo + static_cast<std::int64_t>(r % span);
}

namespace {

// A coordinate grid: steps of 2^-bits px (0: pixels, 1: halves, 4: 1/16, 8: the subpixel grid).
struct Grid {
  int bits = 0;
  float step() const { return std::ldexp(1.0f, -bits); }
};

Grid pick_grid(Rng& rng) {
  static constexpr std::array<int, 5> kBits = {0, 1, 1, 4, 8};
  return Grid{kBits[static_cast<std::size_t>(rng.uniform(0, kBits.size() - 1))]};
}

// A coordinate on the grid in [lo, hi] px.
float coord(Rng& rng, Grid g, float lo, float hi) {
  const auto scale = std::ldexp(1.0f, g.bits);
  const auto k = rng.uniform(static_cast<std::int64_t>(std::ceil(lo * scale)),
                             static_cast<std::int64_t>(std::floor(hi * scale)));
  return static_cast<float>(k) / scale;
}

FloatPoint point(Rng& rng, Grid g, const Scene& s) {
  return {coord(rng, g, -1.0f, static_cast<float>(s.width) + 1.0f),
          coord(rng, g, -1.0f, static_cast<float>(s.height) + 1.0f)};
}

Primitive triangle(Rng& rng, FloatPoint a, FloatPoint b, FloatPoint c) {
  // Either winding: counter-clockwise triangles are normalised by the rules (TRI.ORIENT.NORMALISE).
  if (rng.chance(50))
    std::swap(b, c);
  return make_triangle({a, b, c});
}

void random_triangles(Rng& rng, Grid g, Scene& s) {
  const auto n = rng.uniform(1, 4);
  for (std::int64_t i = 0; i < n; ++i)
    s.primitives.push_back(triangle(rng, point(rng, g, s), point(rng, g, s), point(rng, g, s)));
}

void shared_edge(Rng& rng, Grid g, Scene& s) {
  const FloatPoint a = point(rng, g, s), b = point(rng, g, s), c = point(rng, g, s),
                   d = point(rng, g, s);
  s.primitives.push_back(triangle(rng, a, b, c));
  s.primitives.push_back(triangle(rng, a, c, d));
}

void fan(Rng& rng, Grid g, Scene& s) {
  const FloatPoint centre = point(rng, g, s);
  const auto n = rng.uniform(3, 6);
  std::vector<FloatPoint> ring;
  const float r = static_cast<float>(rng.uniform(2, 6));
  for (std::int64_t i = 0; i < n; ++i) {
    // Ring points on the grid around the centre (exact directions: multiples of 45 degrees,
    // perturbed on the grid).
    static constexpr std::array<std::array<int, 2>, 8> kDir = {
        {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}}};
    const auto& d = kDir[static_cast<std::size_t>((i * 8) / n)];
    ring.push_back({centre[0] + r * static_cast<float>(d[0]) + coord(rng, g, -0.5f, 0.5f),
                    centre[1] + r * static_cast<float>(d[1]) + coord(rng, g, -0.5f, 0.5f)});
  }
  for (std::size_t i = 0; i < ring.size(); ++i)
    s.primitives.push_back(triangle(rng, centre, ring[i], ring[(i + 1) % ring.size()]));
}

void grid_mesh(Rng& rng, Grid g, Scene& s) {
  const float cell =
      g.bits == 0 ? static_cast<float>(rng.uniform(1, 3)) : coord(rng, g, 1.0f, 3.0f);
  const FloatPoint origin = {coord(rng, g, -0.5f, 1.0f), coord(rng, g, -0.5f, 1.0f)};
  const auto cols = rng.uniform(1, 3), rows = rng.uniform(1, 3);
  const bool flip = rng.chance(50);
  for (std::int64_t j = 0; j < rows; ++j) {
    for (std::int64_t i = 0; i < cols; ++i) {
      const float x0 = origin[0] + cell * static_cast<float>(i),
                  y0 = origin[1] + cell * static_cast<float>(j);
      const FloatPoint a{x0, y0}, b{x0 + cell, y0}, c{x0 + cell, y0 + cell}, d{x0, y0 + cell};
      if (flip) {
        s.primitives.push_back(triangle(rng, a, b, d));
        s.primitives.push_back(triangle(rng, b, c, d));
      } else {
        s.primitives.push_back(triangle(rng, a, b, c));
        s.primitives.push_back(triangle(rng, a, c, d));
      }
    }
  }
}

void sliver(Rng& rng, Grid g, Scene& s) {
  const FloatPoint a = point(rng, g, s), far = point(rng, g, s);
  const Grid fine{std::max(g.bits, 4)};
  const FloatPoint b = {a[0] + coord(rng, fine, -0.25f, 0.25f),
                        a[1] + coord(rng, fine, -0.25f, 0.25f)};
  s.primitives.push_back(triangle(rng, a, b, far));
}

void points(Rng& rng, Scene& s) {
  const auto n = rng.uniform(1, 4);
  for (std::int64_t i = 0; i < n; ++i) {
    Primitive p;
    p.type = PrimitiveType::kPoint;
    // On pixel boundaries and centres: integers and halves.
    p.v = {{coord(rng, Grid{1}, 0.0f, static_cast<float>(s.width)),
            coord(rng, Grid{1}, 0.0f, static_cast<float>(s.height))}};
    s.primitives.push_back(p);
  }
}

void lines(Rng& rng, Grid g, Scene& s) {
  const auto n = rng.uniform(1, 3);
  for (std::int64_t i = 0; i < n; ++i) {
    Primitive p;
    p.type = PrimitiveType::kLine;
    const FloatPoint a = point(rng, g, s);
    const float len = static_cast<float>(rng.uniform(1, 8));
    static constexpr std::array<std::array<int, 2>, 8> kDir = {
        {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}}};
    const auto& d = kDir[static_cast<std::size_t>(rng.uniform(0, 7))];
    FloatPoint b = {a[0] + len * static_cast<float>(d[0]), a[1] + len * static_cast<float>(d[1])};
    if (rng.chance(30))
      b = point(rng, g, s); // any direction
    p.v = {a, b};
    s.primitives.push_back(p);
  }
}

} // namespace

// rule: FUZZ.GENERATE
std::vector<std::pair<std::string, std::string>>
families_not_generated(Profile profile, const driver::Driver& driver,
                       const std::vector<std::string>& only) {
  const driver::DriverInfo& info = driver.info();
  std::vector<std::pair<std::string, std::string>> out;
  // rule: FUZZ.FAMILIES
  if (!only.empty()) {
    for (const std::string_view f : kFamilies) {
      if (std::find(only.begin(), only.end(), f) == only.end())
        out.emplace_back(std::string(f), "not selected (--families)");
    }
  }
  const auto selected = [&](std::string_view f) {
    return only.empty() || std::find(only.begin(), only.end(), f) != only.end();
  };
  if (!info.triangles) {
    for (const char* f : {"random", "shared-edge", "fan", "grid", "sliver"}) {
      if (selected(f))
        out.emplace_back(f, "the driver does not draw triangles");
    }
  }
  if (!selected("points")) {
  } else if (!info.points)
    out.emplace_back("points", "the driver does not draw points");
  if (!selected("lines")) {
  } else if (profile == Profile::kD3D11 && !info.lines_d3d)
    out.emplace_back("lines", "the driver does not draw d3d lines (profile d3d11)");
  else if (profile != Profile::kD3D11 && !info.lines_bresenham)
    out.emplace_back("lines", "the driver does not draw vulkan-bresenham lines (profile " +
                                  std::string(to_string(profile)) + ")");
  return out;
}

// rule: FUZZ.GENERATE
std::optional<Case> generate_case(std::uint64_t seed, std::uint64_t index, Profile profile,
                                  const driver::Driver& driver,
                                  const std::vector<std::string>& only) {
  const driver::DriverInfo& info = driver.info();
  std::vector<std::string> families;
  if (info.triangles) // rule: DRIVER.EXTERNAL.CAPABILITIES (a driver may declare no triangles)
    families = {"random", "shared-edge", "fan", "grid", "sliver"};
  if (info.points)
    families.emplace_back("points");
  if (profile == Profile::kD3D11 ? info.lines_d3d : info.lines_bresenham)
    families.emplace_back("lines");
  if (!only.empty()) { // rule: FUZZ.FAMILIES
    std::erase_if(families, [&](const std::string& f) {
      return std::find(only.begin(), only.end(), f) == only.end();
    });
  }
  if (families.empty())
    return std::nullopt;
  const bool msaa4 = std::find(info.sample_counts.begin(), info.sample_counts.end(), 4u) !=
                     info.sample_counts.end();
  for (std::uint64_t attempt = 0; attempt < 16; ++attempt) {
    Rng rng(seed * 0x9E3779B97F4A7C15ull ^ (index + 1) * 0xD1B54A32D192ED03ull ^
            attempt * 0x8CB92BA72F3D8DD7ull);
    rng.next();
    Case c;
    Scene& s = c.scene;
    s.width = static_cast<std::int32_t>(rng.uniform(4, 16));
    s.height = static_cast<std::int32_t>(rng.uniform(4, 16));
    apply_profile(profile, s);
    c.family = families[static_cast<std::size_t>(
        rng.uniform(0, static_cast<std::int64_t>(families.size()) - 1))];
    const Grid g = pick_grid(rng);
    if (c.family == "random")
      random_triangles(rng, g, s);
    else if (c.family == "shared-edge")
      shared_edge(rng, g, s);
    else if (c.family == "fan")
      fan(rng, g, s);
    else if (c.family == "grid")
      grid_mesh(rng, g, s);
    else if (c.family == "sliver")
      sliver(rng, g, s);
    else if (c.family == "points")
      points(rng, s);
    else
      lines(rng, g, s);
    if (msaa4 && rng.chance(25)) {
      // The standard 4x pattern (MSAA.PATTERN.STANDARD).
      set_sample_pattern(s, standard_pattern(4));
    }
    if (driver.unsupported(s).empty())
      return c;
  }
  return std::nullopt;
}

} // namespace rastrules::fuzzer

// SPDX-License-Identifier: MIT
// The 2D campaign's path families (FUZZ.PATH.GENERATE): each aims at one class of difference
// that 2D libraries are known to have (conflation, winding overflow, flattening, ties), every
// coordinate on the library's grid.
// Implements: FUZZ.PATH.GENERATE

#include <algorithm>

#include <filesystem>

#include "rastrules/fuzzer/fuzzer.hpp"
#include "rastrules/fuzzer/paths.hpp"
#if defined(RASTRULES_FUZZ_GLYPHS)
#include "rastrules/io/glyph.hpp"
#endif

namespace rastrules::fuzzer::paths {

namespace {

constexpr std::int32_t kOne = kSubpixelOne; // raw units per pixel

struct RawPoint {
  std::int64_t x = 0, y = 0;
};

// Builds one path in raw units, rounded to the grid, then as the scene's float32 (exact: every
// raw value below 2^24 is a float32 multiple of 1/256).
class Builder {
public:
  Builder(Rng& rng, std::int32_t grid, std::int32_t w, std::int32_t h)
      : rng_(rng), grid_(grid), w_(w), h_(h) {}

  // A point uniform in the target grown by `margin` px.
  RawPoint any(std::int32_t margin = 1) {
    return {rng_.uniform(-margin * kOne, (w_ + margin) * kOne),
            rng_.uniform(-margin * kOne, (h_ + margin) * kOne)};
  }
  // A point within r raw units of c.
  RawPoint near(RawPoint c, std::int64_t r) {
    return {c.x + rng_.uniform(-r, r), c.y + rng_.uniform(-r, r)};
  }
  // A pixel centre of the target.
  RawPoint centre() {
    return {rng_.uniform(0, w_ - 1) * kOne + kOne / 2, rng_.uniform(0, h_ - 1) * kOne + kOne / 2};
  }

  void move(RawPoint p) {
    FloatContour c;
    c.start = f(p);
    path_.contours.push_back(c);
  }
  void line(RawPoint p) { add(path::SegmentKind::kLine, {p}); }
  void quad(RawPoint c, RawPoint p) { add(path::SegmentKind::kQuadratic, {c, p}); }
  void cubic(RawPoint c1, RawPoint c2, RawPoint p) { add(path::SegmentKind::kCubic, {c1, c2, p}); }
  void polygon(const std::vector<RawPoint>& pts) {
    move(pts.front());
    for (std::size_t i = 1; i < pts.size(); ++i)
      line(pts[i]);
  }

  FloatPath take() { return std::move(path_); }

private:
  std::int64_t snap(std::int64_t v) const {
    const std::int64_t q = (v >= 0 ? v + grid_ / 2 : v - grid_ / 2) / grid_;
    return q * grid_;
  }
  FloatPoint f(RawPoint p) const {
    return {static_cast<float>(snap(p.x)) / static_cast<float>(kOne),
            static_cast<float>(snap(p.y)) / static_cast<float>(kOne)};
  }
  void add(path::SegmentKind kind, std::initializer_list<RawPoint> pts) {
    FloatPathSegment s;
    s.kind = kind;
    std::size_t i = 0;
    for (const RawPoint& p : pts)
      s.p[i++] = f(p);
    path_.contours.back().segments.push_back(s);
  }

  Rng& rng_;
  std::int32_t grid_, w_, h_;
  FloatPath path_;
};

std::vector<RawPoint> random_polygon(Builder& b, Rng& rng, int lo, int hi) {
  const auto n = static_cast<std::size_t>(rng.uniform(lo, hi));
  std::vector<RawPoint> pts;
  for (std::size_t i = 0; i < n; ++i)
    pts.push_back(b.any());
  return pts;
}

// A triangle around c with c strictly inside: one vertex in each third of the turn, at 0 or
// 40, 120 or 160, 240 or 280 degrees, so that no two consecutive vertices are half a turn apart
// (an edge through c would leave it to the tie rule).
std::vector<RawPoint> around(Rng& rng, RawPoint c, std::int64_t lo, std::int64_t hi, bool ccw) {
  // Directions as integer vectors (1000 cos, 1000 sin): no floating point in generation.
  static constexpr std::array<std::array<std::int64_t, 2>, 6> kDirs = {
      {{1000, 0}, {766, 643}, {-500, 866}, {-940, 342}, {-500, -866}, {174, -985}}};
  std::vector<RawPoint> t;
  for (int k = 0; k < 3; ++k) {
    const auto& d = kDirs[static_cast<std::size_t>(2 * k + rng.uniform(0, 1))];
    const std::int64_t r = rng.uniform(lo, hi);
    t.push_back({c.x + d[0] * r / 1000, c.y + d[1] * r / 1000});
  }
  if (ccw)
    std::swap(t[1], t[2]);
  return t;
}

bool draw_family(std::string_view family, Builder& b, Rng& rng, const driver::PathSupport& ps,
                 std::int32_t w, std::int32_t h) {
  const bool curves = ps.quadratics || ps.cubics;
  auto curve_to = [&](RawPoint c1, RawPoint c2, RawPoint p) {
    if (ps.cubics && (!ps.quadratics || rng.chance(50)))
      b.cubic(c1, c2, p);
    else
      b.quad(c1, p);
  };
  if (family == "polygon") {
    b.polygon(random_polygon(b, rng, 3, 8));
  } else if (family == "overlap") {
    const RawPoint c = b.centre();
    const int n = static_cast<int>(rng.uniform(2, 3));
    for (int k = 0; k < n; ++k) {
      std::vector<RawPoint> pts;
      for (int i = 0; i < 3 + static_cast<int>(rng.uniform(0, 1)); ++i)
        pts.push_back(b.near(c, 2 * kOne));
      b.polygon(pts);
    }
  } else if (family == "twice") {
    std::vector<RawPoint> pts = random_polygon(b, rng, 3, 5);
    b.polygon(pts);
    if (rng.chance(50))
      std::reverse(pts.begin(), pts.end());
    b.polygon(pts);
  } else if (family == "doubled") {
    // p0 -> p1 -> p2 -> p1: the edge p1 p2 is drawn there and back; with a fourth point the
    // contour goes on past it.
    const RawPoint c = b.centre();
    std::vector<RawPoint> pts = {b.near(c, 3 * kOne), b.near(c, 3 * kOne), b.near(c, 3 * kOne)};
    pts.push_back(pts[1]);
    if (rng.chance(50))
      pts.push_back(b.near(c, 3 * kOne));
    b.polygon(pts);
  } else if (family == "stack") {
    const RawPoint c = b.centre();
    // 16 contours make a winding of 16, which a 4-bit accumulator holds as 0.
    const int n = rng.chance(40) ? 16 : static_cast<int>(rng.uniform(6, 20));
    const bool mixed = rng.chance(25);
    for (int k = 0; k < n; ++k)
      b.polygon(around(rng, c, kOne / 2, 3 * kOne, mixed && rng.chance(30)));
  } else if (family == "cusp") {
    if (!curves)
      return false;
    const RawPoint c = b.centre();
    const RawPoint p0 = b.near(c, 3 * kOne), p3 = b.near(c, 3 * kOne);
    b.move(p0);
    if (ps.cubics) {
      // Control points swapped across the chord: a loop or, at the limit, a cusp.
      const RawPoint c1 = b.near({p3.x + (p3.x - p0.x), p3.y + (p3.y - p0.y)}, kOne);
      const RawPoint c2 = b.near({p0.x - (p3.x - p0.x), p0.y - (p3.y - p0.y)}, kOne);
      b.cubic(c1, c2, p3);
    } else {
      // A quadratic folded back: its end near its start, its control point far away.
      b.quad(b.any(), b.near(p0, kOne / 2));
    }
    if (rng.chance(50))
      b.line(b.near(c, 3 * kOne));
  } else if (family == "near-flat") {
    if (!curves)
      return false;
    const RawPoint p0 = b.any(0), p3 = b.any(0);
    auto on_chord = [&](std::int64_t num) {
      return RawPoint{p0.x + (p3.x - p0.x) * num / 3 + rng.uniform(-2, 2),
                      p0.y + (p3.y - p0.y) * num / 3 + rng.uniform(-2, 2)};
    };
    b.move(p0);
    curve_to(on_chord(1), on_chord(2), p3);
    b.line(b.any(0));
  } else if (family == "ties") {
    // Vertices on pixel centres and corners: edges through centres, horizontal and diagonal.
    const auto n = static_cast<std::size_t>(rng.uniform(3, 6));
    std::vector<RawPoint> pts;
    for (std::size_t i = 0; i < n; ++i) {
      const std::int64_t x = rng.uniform(0, w) * kOne + (rng.chance(60) ? kOne / 2 : 0);
      const std::int64_t y = rng.uniform(0, h) * kOne + (rng.chance(60) ? kOne / 2 : 0);
      pts.push_back({x, y});
    }
    b.polygon(pts);
  } else {
    return false;
  }
  return true;
}

// The font of the "glyph" family for a driver: DejaVu Sans (TrueType: quadratics) when it draws
// quadratics, else Nimbus Sans (Type 1: cubics) when it draws cubics; empty when the build has
// no glyph reader or the file is not there.
std::string glyph_font(const driver::PathSupport& ps) {
#if defined(RASTRULES_FUZZ_GLYPHS)
  for (const auto& [has, file] : {std::pair{ps.quadratics, RASTRULES_FUZZ_FONT_QUADRATIC},
                                  std::pair{ps.cubics, RASTRULES_FUZZ_FONT_CUBIC}})
    if (has && std::filesystem::exists(file))
      return file;
#else
  (void)ps;
#endif
  return {};
}

// A glyph as a path scene: a letter, digit or sign at 6-14 px in its own target (PATH.GLYPH.*).
std::optional<Scene> random_glyph([[maybe_unused]] Rng& rng, const std::string& font,
                                  [[maybe_unused]] std::int32_t limit) {
#if defined(RASTRULES_FUZZ_GLYPHS)
  static constexpr std::string_view kChars =
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789&@%$?#";
  const char32_t ch = static_cast<unsigned char>(kChars[static_cast<std::size_t>(
      rng.uniform(0, static_cast<std::int64_t>(kChars.size()) - 1))]);
  const int size = static_cast<int>(rng.uniform(6, 14));
  auto g = io::load_glyph(font, ch, size);
  if (!std::holds_alternative<io::Glyph>(g))
    return std::nullopt;
  const io::Glyph& glyph = std::get<io::Glyph>(g);
  if (glyph.width > limit || glyph.height > limit)
    return std::nullopt;
  return io::glyph_scene(glyph, path::Coverage::kSamples);
#else
  (void)font;
  return std::nullopt;
#endif
}

} // namespace

// rule: FUZZ.PATH.GENERATE
std::vector<std::string_view> available_path_families(const driver::DriverInfo& info,
                                                      const std::vector<std::string>& only) {
  const driver::PathSupport& ps = info.paths;
  std::vector<std::string_view> families;
  if (!ps.any() || (!ps.nonzero && !ps.evenodd))
    return families;
  const bool curves = ps.quadratics || ps.cubics;
  for (std::string_view f : kPathFamilies) {
    if (!only.empty() && std::find(only.begin(), only.end(), f) == only.end())
      continue;
    if (!curves && (f == "cusp" || f == "near-flat" || f == "glyph"))
      continue;
    if (f == "glyph" && glyph_font(ps).empty())
      continue;
    families.push_back(f);
  }
  return families;
}

// rule: FUZZ.PATH.GENERATE
std::optional<PathCase> generate_path_case(std::uint64_t seed, std::uint64_t index,
                                           const driver::DriverInfo& info,
                                           const std::vector<std::string>& only) {
  const driver::PathSupport& ps = info.paths;
  const std::vector<std::string_view> families = available_path_families(info, only);
  if (families.empty())
    return std::nullopt;
  Rng rng(seed * 0x9E3779B97F4A7C15ull ^ (index + 1) * 0xD1B54A32D192ED03ull);
  const std::string_view family = families[static_cast<std::size_t>(
      rng.uniform(0, static_cast<std::int64_t>(families.size()) - 1))];
  const std::int32_t side = static_cast<std::int32_t>(rng.uniform(4, 12));
  const std::int32_t limit = info.max_target_side > 0 ? info.max_target_side : side;
  Scene scene;
  scene.width = std::min(side, limit);
  scene.height = std::min(static_cast<std::int32_t>(rng.uniform(4, 12)), limit);
  FloatPath p;
  if (family == "glyph") {
    // A glyph keeps its own target and fill rule; its points are on 26.6, every library's grid.
    auto g = random_glyph(rng, glyph_font(ps), limit);
    if (!g)
      return std::nullopt;
    scene.width = g->width;
    scene.height = g->height;
    p = std::move(*g->primitives[0].path);
  } else {
    Builder b(rng, std::max<std::int32_t>(ps.grid_raw, 1), scene.width, scene.height);
    if (!draw_family(family, b, rng, ps, scene.width, scene.height))
      return std::nullopt;
    p = b.take();
  }
  const path::FillRule own_rule = p.fill_rule;
  if (ps.samples && ps.area)
    p.coverage = index % 2 == 0 ? path::Coverage::kArea : path::Coverage::kSamples;
  else
    p.coverage = ps.area ? path::Coverage::kArea : path::Coverage::kSamples;
  if (family == "glyph" && (own_rule == path::FillRule::kNonZero ? ps.nonzero : ps.evenodd))
    p.fill_rule = own_rule;
  else if (ps.nonzero && ps.evenodd)
    p.fill_rule = rng.chance(50) ? path::FillRule::kNonZero : path::FillRule::kEvenOdd;
  else
    p.fill_rule = ps.nonzero ? path::FillRule::kNonZero : path::FillRule::kEvenOdd;
  // Overflow of a 4-bit winding needs the nonzero rule: stacks keep it more often.
  if (family == "stack" && ps.nonzero && rng.chance(75))
    p.fill_rule = path::FillRule::kNonZero;
  scene.primitives.push_back(make_path(std::move(p)));
  return PathCase{std::move(scene), std::string(family)};
}

} // namespace rastrules::fuzzer::paths

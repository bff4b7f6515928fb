// SPDX-License-Identifier: MIT
// The ladder's scenes (BENCH.LADDER.SCENES): seeded jittered meshes that cover a rectangle
// exactly, the tie-heavy mesh, and translations.
// Implements: BENCH.LADDER.SCENES

#include <cmath>
#include <random>
#include <utility>

#include "rastrules/bench/ladder.hpp"

namespace rastrules::bench {

namespace {

// Rounds to the 1/256 grid.
double grid256(double v) {
  return std::round(v * 256.0) / 256.0;
}

FloatTriangle tri_of(const std::array<double, 2>& a, const std::array<double, 2>& b,
                     const std::array<double, 2>& c) {
  const auto f = [](const std::array<double, 2>& p) {
    return std::array<float, 2>{static_cast<float>(p[0]), static_cast<float>(p[1])};
  };
  return {f(a), f(b), f(c)};
}

// Splits the grid cells into two clockwise triangles each (y down): along a -> c (the
// top-left to bottom-right diagonal) or b -> d.
void split_cells(const std::vector<std::vector<std::array<double, 2>>>& g, std::int32_t cols,
                 std::int32_t rows,
                 const std::function<bool(std::int32_t, std::int32_t)>& main_diag,
                 std::vector<FloatTriangle>& out) {
  for (std::int32_t j = 0; j < rows; ++j) {
    for (std::int32_t i = 0; i < cols; ++i) {
      const auto uj = static_cast<std::size_t>(j), ui = static_cast<std::size_t>(i);
      const auto& a = g[uj][ui];
      const auto& b = g[uj][ui + 1];
      const auto& c = g[uj + 1][ui + 1];
      const auto& d = g[uj + 1][ui];
      if (main_diag(i, j)) {
        out.push_back(tri_of(a, b, c));
        out.push_back(tri_of(a, c, d));
      } else {
        out.push_back(tri_of(a, b, d));
        out.push_back(tri_of(b, c, d));
      }
    }
  }
}

} // namespace

// rule: BENCH.LADDER.SCENES
LadderScene make_mesh(std::string name, std::uint64_t seed, std::int32_t cols, std::int32_t rows,
                      double cell, double jitter, double x0, double y0, std::int32_t width,
                      std::int32_t height) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-jitter * cell, jitter * cell);
  std::vector<std::vector<std::array<double, 2>>> g(
      static_cast<std::size_t>(rows) + 1,
      std::vector<std::array<double, 2>>(static_cast<std::size_t>(cols) + 1));
  for (std::int32_t j = 0; j <= rows; ++j) {
    for (std::int32_t i = 0; i <= cols; ++i) {
      double x = x0 + cell * i, y = y0 + cell * j;
      const double jx = u(rng), jy = u(rng);
      // Interior vertices move freely; boundary ones only along their side; corners stay.
      if (i > 0 && i < cols)
        x = grid256(x + jx);
      if (j > 0 && j < rows)
        y = grid256(y + jy);
      g[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)] = {x, y};
    }
  }
  std::bernoulli_distribution coin(0.5);
  std::vector<std::vector<bool>> diag(static_cast<std::size_t>(rows),
                                      std::vector<bool>(static_cast<std::size_t>(cols)));
  for (auto& row : diag)
    for (std::size_t i = 0; i < row.size(); ++i)
      row[i] = coin(rng);
  LadderScene s;
  s.name = std::move(name);
  s.width = width;
  s.height = height;
  s.is_mesh = true;
  s.rect_x0 = x0;
  s.rect_y0 = y0;
  s.rect_x1 = x0 + cell * cols;
  s.rect_y1 = y0 + cell * rows;
  split_cells(
      g, cols, rows,
      [&](std::int32_t i, std::int32_t j) {
        return static_cast<bool>(diag[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)]);
      },
      s.triangles);
  flatten(s);
  return s;
}

std::vector<float> flat_coordinates(const std::vector<FloatTriangle>& triangles) {
  std::vector<float> xy;
  xy.reserve(6 * triangles.size());
  for (const auto& tri : triangles)
    for (const auto& v : tri) {
      xy.push_back(v[0]);
      xy.push_back(v[1]);
    }
  return xy;
}

void flatten(LadderScene& s) {
  s.xy = flat_coordinates(s.triangles);
}

// rule: BENCH.LADDER.SCENES
LadderScene make_hard_mesh(std::int32_t cols, std::int32_t rows, std::int32_t cell) {
  // Column lines on pixel centres; row lines on pixel centres, with a sliver row 1/256, 3/256
  // or 1/16 px tall after every third one.
  const double base = 2.5;
  std::vector<double> xs, ys;
  for (std::int32_t i = 0; i <= cols; ++i)
    xs.push_back(base + cell * i);
  const double slivers[3] = {1.0 / 256.0, 3.0 / 256.0, 1.0 / 16.0};
  for (std::int32_t j = 0; j <= rows; ++j) {
    ys.push_back(base + cell * j);
    if (j < rows && j % 3 == 1)
      ys.push_back(base + cell * j + slivers[j % 9 / 3]);
  }
  const auto nrows = static_cast<std::int32_t>(ys.size()) - 1;
  std::vector<std::vector<std::array<double, 2>>> g;
  for (const double y : ys) {
    g.emplace_back();
    for (const double x : xs)
      g.back().push_back({x, y});
  }
  LadderScene s;
  s.name = "hard";
  s.width = static_cast<std::int32_t>(std::ceil(xs.back())) + 3;
  s.height = static_cast<std::int32_t>(std::ceil(ys.back())) + 3;
  s.is_mesh = true;
  s.rect_x0 = xs.front();
  s.rect_y0 = ys.front();
  s.rect_x1 = xs.back();
  s.rect_y1 = ys.back();
  split_cells(
      g, cols, nrows, [](std::int32_t i, std::int32_t j) { return (i + j) % 2 == 0; }, s.triangles);
  flatten(s);
  return s;
}

// rule: BENCH.LADDER.SCENES, BENCH.METRIC.TRANSLATION
LadderScene translated(const LadderScene& s, std::int32_t t, std::int32_t width,
                       std::int32_t height) {
  LadderScene out = s;
  out.width = width;
  out.height = height;
  const float ft = static_cast<float>(t);
  for (auto& tri : out.triangles)
    for (auto& v : tri) {
      v[0] += ft;
      v[1] += ft;
    }
  out.rect_x0 += t;
  out.rect_y0 += t;
  out.rect_x1 += t;
  out.rect_y1 += t;
  flatten(out);
  return out;
}

// rule: BENCH.LADDER.SCENES
LadderScenes make_scenes(const LadderConfig& c) {
  LadderScenes s;
  const bool q = c.quick;
  // about 50 px, 1000 px and 20000 px triangles (half a cell each)
  s.timed.push_back(make_mesh("small", c.seed * 4 + 0, q ? 16 : 48, q ? 16 : 48, 10, 0.2, 8, 8,
                              q ? 176 : 496, q ? 176 : 496));
  s.timed.push_back(make_mesh("medium", c.seed * 4 + 1, q ? 4 : 12, q ? 4 : 12, 45, 0.2, 8, 8,
                              q ? 196 : 556, q ? 196 : 556));
  s.timed.push_back(make_mesh("large", c.seed * 4 + 2, q ? 2 : 3, q ? 1 : 3, 200, 0.2, 8, 8,
                              q ? 416 : 616, q ? 216 : 616));
  s.timed.push_back(make_hard_mesh(q ? 12 : 40, q ? 12 : 40, 4));
  // The translation sweep: t = 0 and 2^k up to 8192 in a target of kMaxTargetSide (16384)
  // pixels a side: 2^14 would put the mesh outside the largest target the kernel accepts.
  s.translate_base =
      make_mesh("translate", c.seed * 4 + 3, q ? 4 : 8, q ? 4 : 8, 12, 0.2, 4, 4, 16384, 16384);
  s.sweep.push_back(0);
  for (std::int32_t k = 0; k <= 13; ++k)
    s.sweep.push_back(std::int32_t{1} << k);
  return s;
}

} // namespace rastrules::bench

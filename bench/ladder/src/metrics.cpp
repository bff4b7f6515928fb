// SPDX-License-Identifier: MIT
// The ladder's metrics: error against the exact answer, watertightness on meshes, translation
// invariance and the exact range, medians.
// Implements: BENCH.METRIC.ERROR, BENCH.METRIC.WATERTIGHT, BENCH.METRIC.TRANSLATION

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rastrules/bench/ladder.hpp"

namespace rastrules::bench {

// rule: BENCH.METRIC.ERROR
std::uint64_t symmetric_difference(const Coverage& a, const Coverage& b) {
  std::uint64_t n = 0;
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (a[i] == b[j]) {
      ++i;
      ++j;
    } else if (a[i] < b[j]) {
      ++n;
      ++i;
    } else {
      ++n;
      ++j;
    }
  }
  return n + (a.size() - i) + (b.size() - j);
}

// rule: BENCH.METRIC.WATERTIGHT
std::uint64_t watertight_violations(const LadderScene& s, const Coverage& c) {
  if (!s.is_mesh)
    throw std::invalid_argument("watertight_violations: not a mesh");
  // The pixels whose centre lies in [x0, x1) x [y0, y1).
  const auto lo = [](double v) { return static_cast<std::int64_t>(std::ceil(v - 0.5)); };
  const std::int64_t px0 = lo(s.rect_x0), px1 = lo(s.rect_x1); // [px0, px1)
  const std::int64_t py0 = lo(s.rect_y0), py1 = lo(s.rect_y1);
  if (px1 <= px0 || py1 <= py0)
    return 0;
  const auto nx = static_cast<std::size_t>(px1 - px0), ny = static_cast<std::size_t>(py1 - py0);
  std::vector<std::uint8_t> count(nx * ny, 0);
  for (const std::uint64_t k : c) {
    const auto x = static_cast<std::int64_t>(k & 0xffffu);
    const auto y = static_cast<std::int64_t>((k >> 16) & 0xffffu);
    if (x < px0 || x >= px1 || y < py0 || y >= py1)
      continue;
    auto& n = count[static_cast<std::size_t>(y - py0) * nx + static_cast<std::size_t>(x - px0)];
    if (n < 2)
      ++n;
  }
  return static_cast<std::uint64_t>(
      std::count_if(count.begin(), count.end(), [](std::uint8_t n) { return n != 1; }));
}

// rule: BENCH.METRIC.TRANSLATION
Coverage shifted_back(const Coverage& c, std::int32_t t) {
  Coverage out;
  out.reserve(c.size());
  for (const std::uint64_t k : c) {
    const auto x = static_cast<std::int64_t>(k & 0xffffu) - t;
    const auto y = static_cast<std::int64_t>((k >> 16) & 0xffffu) - t;
    if (x < 0 || y < 0)
      continue;
    out.push_back(coverage_key(static_cast<std::uint32_t>(k >> 32), static_cast<std::int32_t>(x),
                               static_cast<std::int32_t>(y)));
  }
  return out;
}

// rule: BENCH.METRIC.TRANSLATION
std::optional<std::int64_t> exact_range(const std::vector<SweepPoint>& sweep) {
  std::optional<std::int64_t> range;
  for (const SweepPoint& p : sweep) {
    if (p.errors != 0 || p.watertight != 0 || p.translation != 0)
      break;
    range = p.t;
  }
  return range;
}

double median(std::vector<double> v) {
  if (v.empty())
    throw std::invalid_argument("median of nothing");
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2.0;
}

} // namespace rastrules::bench

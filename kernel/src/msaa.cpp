// SPDX-License-Identifier: MIT
// Sample patterns, per-sample coverage, centroid rules and resolve (rastrules/msaa.hpp).
// Implements: MSAA.PATTERN.STANDARD, MSAA.PATTERN.CENTER, MSAA.PATTERN.CUSTOM,
//             MSAA.COVER.SAMPLE, MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10,
//             MSAA.RESOLVE.AVERAGE

#include "rastrules/msaa.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace rastrules {

namespace {

// The tables of MSAA.PATTERN.STANDARD, in sample-index order (1/16 px from the centre, +y down).
constexpr SampleOffset kStandard1[] = {{0, 0}};
constexpr SampleOffset kStandard2[] = {{4, 4}, {-4, -4}};
constexpr SampleOffset kStandard4[] = {{-2, -6}, {6, -2}, {-6, 2}, {2, 6}};
constexpr SampleOffset kStandard8[] = {{1, -3}, {-1, 3},  {5, 1}, {-3, -5},
                                       {-5, 5}, {-7, -1}, {3, 7}, {7, -7}};
constexpr SampleOffset kStandard16[] = {{1, 1},  {-1, -3}, {-3, 2}, {4, -1}, {-5, -2}, {2, 5},
                                        {5, 3},  {3, -5},  {-2, 6}, {0, -7}, {-4, -6}, {-6, 4},
                                        {-8, 0}, {7, -4},  {6, 7},  {-7, -8}};

template <std::size_t N> SamplePattern make_standard(const SampleOffset (&table)[N]) {
  return SamplePattern{PatternKind::kStandard, std::vector<SampleOffset>(table, table + N)};
}

// Returns the index of the lowest set bit of a non-zero mask.
std::uint32_t lowest_bit(std::uint32_t m) {
  std::uint32_t k = 0;
  while ((m & 1u) == 0u) {
    m >>= 1u;
    ++k;
  }
  return k;
}

} // namespace

// rule: MSAA.PATTERN.STANDARD
SamplePattern standard_pattern(std::uint32_t n) {
  switch (n) {
  case 2:
    return make_standard(kStandard2);
  case 4:
    return make_standard(kStandard4);
  case 8:
    return make_standard(kStandard8);
  case 16:
    return make_standard(kStandard16);
  default:
    return make_standard(kStandard1); // n == 1 (the precondition excludes others)
  }
}

// rule: MSAA.PATTERN.CENTER
SamplePattern center_pattern(std::uint32_t n) {
  return SamplePattern{PatternKind::kCenter, std::vector<SampleOffset>(n, SampleOffset{0, 0})};
}

// rule: MSAA.PATTERN.CUSTOM
SamplePattern custom_pattern(std::vector<SampleOffset> positions) {
  return SamplePattern{PatternKind::kCustom, std::move(positions)};
}

// rule: MSAA.COVER.SAMPLE
std::uint32_t sample_coverage(const TriangleSetup& t, std::int32_t px, std::int32_t py,
                              const SamplePattern& pattern) {
  std::uint32_t mask = 0;
  for (std::uint32_t k = 0; k < pattern.count(); ++k) {
    if (covers(t, sample_position(px, py, pattern.positions[k])))
      mask |= std::uint32_t{1} << k;
  }
  return mask;
}

std::vector<std::uint32_t> outward_order(const SamplePattern& pattern) {
  std::vector<std::uint32_t> order(pattern.count());
  for (std::uint32_t k = 0; k < pattern.count(); ++k)
    order[k] = k;
  auto dist2 = [&](std::uint32_t k) {
    const std::int32_t x = pattern.positions[k].x, y = pattern.positions[k].y;
    return x * x + y * y;
  };
  // Stable: equal distances keep the lower index first.
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return dist2(a) < dist2(b); });
  return order;
}

// rule: MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
Centroid centroid(CentroidRule rule, std::uint32_t coverage, std::uint32_t sample_mask,
                  const SamplePattern& pattern) {
  const std::uint32_t full = full_mask(pattern.count());
  const std::uint32_t c = coverage & full;
  const std::uint32_t m = sample_mask & full;
  const std::uint32_t cm = c & m;
  const SampleOffset center{0, 0};
  if (rule == CentroidRule::kD3D11) {
    // rule: MSAA.CENTROID.D3D11
    // The mask is applied first: a masked-out sample is never "covered" (MSAA.CENTROID.D3D11).
    if (cm == full)
      return Centroid{center, CentroidBranch::kFullCoverageCenter}; // (1)
    if (cm != 0) {                                                  // (2)
      return Centroid{pattern.positions[lowest_bit(cm)], CentroidBranch::kFirstCovered};
    }
    if (m != full && m != 0) { // (3)
      return Centroid{pattern.positions[lowest_bit(m)], CentroidBranch::kNoneCoveredMaskSample};
    }
    return Centroid{center, CentroidBranch::kNoneCoveredCenter};
  }
  // rule: MSAA.CENTROID.D3D10
  if (c == full && m == full)
    return Centroid{center, CentroidBranch::kFullCoverageCenter}; // (1)
  if (cm == 0 && (m == full || m == 0)) {                         // (2)
    return Centroid{center, CentroidBranch::kNoneCoveredCenter};
  }
  // (3) the covered samples after the mask, or (2) the mask's samples; never empty here.
  const std::uint32_t pick = cm != 0 ? cm : m;
  const std::vector<std::uint32_t> order = outward_order(pattern);
  const auto k = std::find_if(order.begin(), order.end(),
                              [&](std::uint32_t i) { return ((pick >> i) & 1u) != 0u; });
  return Centroid{pattern.positions[*k], cm != 0 ? CentroidBranch::kNearestCovered
                                                 : CentroidBranch::kNoneCoveredMaskSample};
}

// rule: MSAA.RESOLVE.AVERAGE
Rgba8 resolve_pixel(const std::vector<Rgba8>& samples) {
  const auto n = static_cast<std::uint32_t>(samples.size());
  Rgba8 out{};
  for (std::size_t ch = 0; ch < 4; ++ch) {
    std::uint32_t sum = 0;
    for (const Rgba8& s : samples)
      sum += s[ch];
    // Nearest integer to sum / n, ties to even: q = floor, r = remainder; round up when
    // 2r > n, or 2r == n and q is odd.
    const std::uint32_t q = sum / n, r = sum % n;
    const std::uint32_t v = (2 * r > n || (2 * r == n && (q & 1u) != 0u)) ? q + 1 : q;
    out[ch] = static_cast<std::uint8_t>(v);
  }
  return out;
}

} // namespace rastrules

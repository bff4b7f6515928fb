// SPDX-License-Identifier: MIT
// The slab method's per-row accumulation of exact areas (PATH.AREA.EXACT), shared by the areas
// of lines (path_area.cpp) and of curves (path_area_curve.cpp, PATH.AREA.CURVE): columns of one
// pixel row, integrals of clamped linear edges over a slab, runs between two edges.

#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>

#include "rastrules/fixed.hpp"

namespace rastrules::path::detail {

using Rational = boost::multiprecision::cpp_rational;
using BigInt = boost::multiprecision::cpp_int;

// Returns floor(q) for a rational q.
inline std::int64_t floor_of(const Rational& q) {
  const BigInt n = boost::multiprecision::numerator(q);
  const BigInt d = boost::multiprecision::denominator(q); // > 0
  BigInt f = n / d;                                       // truncates toward zero
  if (n < 0 && f * d != n)
    f -= 1;
  return f.convert_to<std::int64_t>();
}

// Returns the integral over y in [ya, yb] (length hgt) of clamp(X(y), lo, lo + 256) - lo, where
// X is linear from xa (at ya) to xb (at yb). Units: raw squared.
inline Rational column_integral(const Rational& xa, const Rational& xb, const Rational& hgt,
                                std::int64_t lo) {
  const std::int64_t hi = lo + kSubpixelOne;
  const Rational& xmin = xa < xb ? xa : xb;
  const Rational& xmax = xa < xb ? xb : xa;
  if (xmax <= lo)
    return Rational(0);
  if (xmin >= hi)
    return Rational(kSubpixelOne) * hgt;
  if (xmin >= lo && xmax <= hi)
    return ((xa + xb) / 2 - lo) * hgt;
  // X crosses lo or hi inside the slab: split at those parameters; clamp(X) is linear between.
  auto clamped = [&](const Rational& x) {
    if (x <= lo)
      return Rational(0);
    if (x >= hi)
      return Rational(kSubpixelOne);
    return Rational(x - lo);
  };
  std::vector<Rational> us{Rational(0), Rational(1)};
  for (const std::int64_t v : {lo, hi}) {
    const Rational u = (Rational(v) - xa) / (xb - xa);
    if (u > 0 && u < 1)
      us.push_back(u);
  }
  std::sort(us.begin(), us.end());
  Rational sum = 0;
  for (std::size_t k = 0; k + 1 < us.size(); ++k) {
    const Rational x0 = xa + (xb - xa) * us[k];
    const Rational x1 = xa + (xb - xa) * us[k + 1];
    sum += (clamped(x0) + clamped(x1)) / 2 * (us[k + 1] - us[k]);
  }
  return sum * hgt;
}

// One pixel row's areas (raw squared units): the partial columns' areas, and the columns a
// run covers for the whole height of a slab as a difference array (one add at each end of the
// run instead of one per column).
struct RowAreas {
  std::vector<Rational> partial;
  std::vector<Rational> full_diff; // one longer than the row
  std::int64_t touched_lo = 0, touched_hi = -1;

  explicit RowAreas(std::int32_t w)
      : partial(static_cast<std::size_t>(w)), full_diff(static_cast<std::size_t>(w) + 1),
        touched_lo(w) {}
};

// Accumulates the area between edges l (left) and r (right) over the slab [ya, yb] of one
// pixel row into the row's columns (raw squared units).
inline void add_run(RowAreas& row, std::int32_t w, const Rational& la, const Rational& lb,
                    const Rational& ra, const Rational& rb, const Rational& hgt) {
  const std::int64_t c0 = std::max<std::int64_t>(0, floor_of(std::min(la, lb) / kSubpixelOne));
  const std::int64_t c1 =
      std::min<std::int64_t>(std::int64_t{w} - 1, floor_of(std::max(ra, rb) / kSubpixelOne));
  if (c0 > c1)
    return;
  // Columns [f0, f1] lie entirely between the two edges: covered for the whole slab.
  const std::int64_t f0 = std::max(c0, -floor_of(-std::max(la, lb) / kSubpixelOne));
  const std::int64_t f1 = std::min(c1, floor_of(std::min(ra, rb) / kSubpixelOne) - 1);
  if (f0 <= f1) {
    const Rational full = Rational(kSubpixelOne) * hgt;
    row.full_diff[static_cast<std::size_t>(f0)] += full;
    row.full_diff[static_cast<std::size_t>(f1 + 1)] -= full;
  }
  for (std::int64_t c = c0; c <= c1; ++c) {
    if (f0 <= f1 && c == f0) {
      c = f1; // skip the full columns
      continue;
    }
    const std::int64_t lo = c * kSubpixelOne;
    const Rational a = column_integral(ra, rb, hgt, lo) - column_integral(la, lb, hgt, lo);
    if (a != 0)
      row.partial[static_cast<std::size_t>(c)] += a;
  }
  row.touched_lo = std::min(row.touched_lo, c0);
  row.touched_hi = std::max(row.touched_hi, c1);
}

} // namespace rastrules::path::detail

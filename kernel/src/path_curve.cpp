// SPDX-License-Identifier: MIT
// 2D paths: the crossings of quadratic and cubic Bézier curves with a sample row.

#include <stdexcept>
#include <vector>

#include "path_detail.hpp"

namespace rastrules::path::detail {

std::vector<Crossing> curve_crossings(const Curve& /*c*/, std::int64_t /*sy*/, Tie /*t*/) {
  throw std::invalid_argument("path: curves are not implemented yet (PATH.SAMPLE.TIE)");
}

} // namespace rastrules::path::detail

// SPDX-License-Identifier: MIT
// The kernel's point formula as the proofs see it: KernelModel (support/kernel_model.hpp) plus
// the two triangles of a point, forwarded to rastrules::formula::point_z_triangles (the
// template kernel/src/point.cpp instantiates with std::int64_t), with kSubpixelHalf and the
// POINT.RANGE bounds of rastrules/point.hpp.

#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "rastrules/fixed.hpp"
#include "rastrules/formula/point.hpp"
#include "rastrules/point.hpp"
#include "support/kernel_model.hpp"
#include "support/prover.hpp"

namespace rastrules::proofs {

// Returns the triangle with the raw corners of a formula triangle.
template <class S> Triangle<S> to_triangle(const formula::PointTriangle<S>& t) {
  return Triangle<S>{Point<S>{t[0][0], t[0][1]}, Point<S>{t[1][0], t[1][1]},
                     Point<S>{t[2][0], t[2][1]}};
}

struct PointKernelModel : KernelModel {
  static constexpr const char* kName = "kernel";

  // Assumes: POINT.RANGE
  static constexpr std::int64_t kMinPointCentreRaw = kMinPointRaw;
  static constexpr std::int64_t kMaxPointCentreRaw = kMaxPointRaw;

  static std::vector<Constant> constants() {
    return kernel_constants_and({{"kMinPointRaw", kMinPointRaw, Unit::kCoordRaw},
                                 {"kMaxPointRaw", kMaxPointRaw, Unit::kCoordRaw}});
  }

  // The kernel's two triangles of the point with centre c (point_triangles in point.cpp).
  template <class S> static std::array<Triangle<S>, 2> point_triangles(const Point<S>& c) {
    const auto t = formula::point_z_triangles<S>(c.x, c.y, S(kSubpixelHalf));
    return {to_triangle<S>(t[0]), to_triangle<S>(t[1])};
  }
};

} // namespace rastrules::proofs

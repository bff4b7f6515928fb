// SPDX-License-Identifier: MIT
// Properties of vertex snapping: the kernel's integer bit-pattern snapping equals exact
// rational rounding (the oracle) for every float32, including NaN payloads, infinities,
// subnormals, exact ties and the range limits; D3D's saturating conversion likewise.
// Implements (properties for): SNAP.VERTEX.ROUND, SNAP.VERTEX.RANGE, SNAP.VERTEX.INVALID,
//   SNAP.D3D.SATURATE

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "rastrules/gen/floats.hpp"
#include "rastrules/gen/triangles.hpp"
#include "rastrules/oracle/triangle.hpp"
#include "rastrules/scene.hpp"
#include "rastrules/snap.hpp"

namespace {

using rastrules::gen::FloatCase;

// rule: SNAP.VERTEX.FORMAT, SNAP.VERTEX.ROUND, SNAP.VERTEX.RANGE
RC_GTEST_PROP(SnapVertex, SnapToSubpixelEqualsExactRationalRounding, (const FloatCase& f)) {
  RC_TAG(std::string(to_string(f.cls)));
  const rastrules::SnapResult k = rastrules::snap_to_subpixel(f.v);
  const std::optional<std::int64_t> o = rastrules::oracle::snap(f.v);
  if (o) {
    RC_ASSERT(k.status == rastrules::SnapStatus::kOk);
    RC_ASSERT(std::int64_t{k.value.raw()} == *o);
  } else if (std::isnan(f.v)) {
    RC_ASSERT(k.status == rastrules::SnapStatus::kNaN);
  } else if (std::isinf(f.v)) {
    RC_ASSERT(k.status == rastrules::SnapStatus::kInfinite);
  } else {
    RC_ASSERT(k.status == rastrules::SnapStatus::kOutOfRange);
  }
}

// rule: SNAP.VERTEX.ROUND
RC_GTEST_PROP(SnapVertex, SnappingIsOddSymmetric, (const FloatCase& f)) {
  RC_PRE(!std::isnan(f.v));
  const rastrules::SnapResult a = rastrules::snap_to_subpixel(f.v);
  const rastrules::SnapResult b = rastrules::snap_to_subpixel(-f.v);
  // Round half to even is symmetric; the range is not (-2^23 is in, 2^23 is out).
  const bool ok_a = a.status == rastrules::SnapStatus::kOk;
  const bool ok_b = b.status == rastrules::SnapStatus::kOk;
  if (ok_a && ok_b) {
    RC_ASSERT(a.value.raw() == -b.value.raw());
  } else if (ok_a) {
    RC_ASSERT(a.value.raw() == rastrules::kMinVertexRaw);
  } else if (ok_b) {
    RC_ASSERT(b.value.raw() == rastrules::kMinVertexRaw);
  } else {
    RC_ASSERT(a.status == b.status);
  }
}

// rule: SNAP.D3D.SATURATE
RC_GTEST_PROP(SnapD3D, SaturateEqualsExactD3DConversion, (const FloatCase& f)) {
  RC_TAG(std::string(to_string(f.cls)));
  RC_ASSERT(std::int64_t{rastrules::snap_d3d_saturate(f.v).raw()} ==
            rastrules::oracle::snap_d3d_saturate(f.v));
}

// rule: SNAP.D3D.SATURATE
RC_GTEST_PROP(SnapD3D, SaturateIsMonotoneAndAgreesWithSnapInsideTheRange,
              (const FloatCase& f, const FloatCase& g)) {
  RC_PRE(!std::isnan(f.v) && !std::isnan(g.v));
  const auto sf = rastrules::snap_d3d_saturate(f.v).raw();
  const auto sg = rastrules::snap_d3d_saturate(g.v).raw();
  if (f.v <= g.v)
    RC_ASSERT(sf <= sg);
  if (g.v <= f.v)
    RC_ASSERT(sg <= sf);
  const rastrules::SnapResult s = rastrules::snap_to_subpixel(f.v);
  if (s.status == rastrules::SnapStatus::kOk)
    RC_ASSERT(s.value.raw() == sf);
}

// rule: SNAP.VERTEX.INVALID
RC_GTEST_PROP(SnapVertex, SceneIsRejectedIffACoordinateDoesNotSnapNamingTheFirst, ()) {
  rastrules::gen::TriScene s = *rastrules::gen::tri_scene(8, 4);
  const std::size_t bad = *rc::gen::inRange<std::size_t>(0, 2);
  for (std::size_t n = 0; n < bad + 1; ++n) {
    const auto p = *rc::gen::inRange<std::size_t>(0, s.triangles.size());
    const auto i = *rc::gen::inRange<std::size_t>(0, 3);
    const auto k = *rc::gen::inRange<std::size_t>(0, 2);
    s.triangles[p].v[i][k] = (*rc::gen::arbitrary<FloatCase>()).v;
  }
  std::string first_bad;
  for (std::size_t p = 0; p < s.triangles.size() && first_bad.empty(); ++p) {
    for (std::size_t i = 0; i < 3 && first_bad.empty(); ++i) {
      for (std::size_t k = 0; k < 2 && first_bad.empty(); ++k) {
        if (!rastrules::oracle::snap(s.triangles[p].v[i][k])) {
          first_bad = "primitives[" + std::to_string(p) + "].v[" + std::to_string(i) + "][" +
                      std::to_string(k) + "]";
        }
      }
    }
  }
  RC_CLASSIFY(first_bad.empty(), "valid scene");
  const auto r = rastrules::render(rastrules::gen::to_kernel_scene(s));
  if (first_bad.empty()) {
    RC_ASSERT(std::holds_alternative<std::vector<rastrules::Fragment>>(r));
  } else {
    RC_ASSERT(std::holds_alternative<rastrules::SceneError>(r));
    RC_ASSERT(std::get<rastrules::SceneError>(r).field == first_bad);
  }
}

} // namespace

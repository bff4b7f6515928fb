// SPDX-License-Identifier: MIT
// Property: the bounding-box traversal yields exactly the pixels of the target whose centres
// covers() accepts, in row-major order, checked by brute force over the whole target.
// Implements (properties for): RASTER.WALK.BBOX, RASTER.TARGET.CLIP, FIX.BIAS.FORM,
//   FIX.STEP.INCREMENTAL

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "rastrules/gen/triangles.hpp"
#include "rastrules/raster/walk.hpp"
#include "rastrules/snap.hpp"
#include "rastrules/triangle.hpp"

namespace {

namespace gen = rastrules::gen;

// rule: RASTER.WALK.BBOX, RASTER.TARGET.CLIP, FIX.BIAS.FORM, FIX.STEP.INCREMENTAL
RC_GTEST_PROP(RasterWalk, WalkYieldsExactlyTheCoveredPixelCentres, ()) {
  const std::int32_t w = *rc::gen::inRange<std::int32_t>(1, 65);
  const std::int32_t h = *rc::gen::inRange<std::int32_t>(1, 65);
  const rastrules::RasterState state = *gen::raster_state();
  const gen::GenTriangle t = *gen::triangle_anywhere(w, h);
  RC_TAG(std::string(to_string(t.kind)));
  std::array<rastrules::Vec2, 3> v{};
  for (std::size_t i = 0; i < 3; ++i) {
    const rastrules::SnapResult x = rastrules::snap_to_subpixel(t.v[i][0]);
    const rastrules::SnapResult y = rastrules::snap_to_subpixel(t.v[i][1]);
    RC_ASSERT(x.status == rastrules::SnapStatus::kOk);
    RC_ASSERT(y.status == rastrules::SnapStatus::kOk);
    v[i] = rastrules::Vec2{x.value, y.value};
  }
  const rastrules::TriangleSetup setup = rastrules::setup_triangle(v, state);
  std::vector<std::pair<std::int32_t, std::int32_t>> walked, brute;
  rastrules::raster::walk_triangle(
      setup, w, h, [&walked](std::int32_t x, std::int32_t y) { walked.emplace_back(y, x); });
  for (std::int32_t y = 0; y < h; ++y) {
    for (std::int32_t x = 0; x < w; ++x) {
      if (rastrules::covers(setup, rastrules::pixel_center(x, y)))
        brute.emplace_back(y, x);
    }
  }
  RC_CLASSIFY(!brute.empty(), "covers some pixel");
  RC_CLASSIFY(brute.size() == static_cast<std::size_t>(w) * static_cast<std::size_t>(h),
              "covers the whole target");
  RC_ASSERT(walked == brute);
}

} // namespace

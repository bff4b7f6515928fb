// SPDX-License-Identifier: MIT
// Metamorphic properties: whole-pixel translation moves coverage exactly; reversing the
// vertex order with culling off changes nothing; culling keeps exactly the triangles of the
// other winding.
// Implements (properties for): TRI.INVARIANCE.TRANSLATION, TRI.CULL.MODE, SNAP.CULL.AFTER_SNAP

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "rastrules/gen/compare.hpp"
#include "rastrules/gen/triangles.hpp"
#include "rastrules/oracle/triangle.hpp"
#include "rastrules/scene.hpp"
#include "rastrules/triangle.hpp"

namespace {

namespace gen = rastrules::gen;

rastrules::Vec2 sample(std::int64_t x, std::int64_t y) {
  return rastrules::Vec2{rastrules::Subpixel::from_raw(static_cast<std::int32_t>(x)),
                         rastrules::Subpixel::from_raw(static_cast<std::int32_t>(y))};
}

bool in_range(std::int64_t v) {
  return v >= rastrules::kMinVertexRaw && v <= rastrules::kMaxVertexRaw;
}

std::vector<rastrules::Fragment> render_ok(const gen::TriScene& s) {
  auto r = rastrules::render(gen::to_kernel_scene(s));
  if (const auto* err = std::get_if<rastrules::SceneError>(&r)) {
    RC_FAIL("kernel rejected a valid scene: " + err->what());
  }
  return std::get<std::vector<rastrules::Fragment>>(std::move(r));
}

// rule: TRI.INVARIANCE.TRANSLATION
RC_GTEST_PROP(TriInvariance, WholePixelTranslationMovesCoverageExactly, ()) {
  const rastrules::RasterState state = *gen::raster_state();
  const gen::RawTriangle t = *gen::nondegenerate_raw_triangle_near(24, 24);
  std::int64_t minx = t[0][0], maxx = minx, miny = t[0][1], maxy = miny;
  for (const gen::RawPoint& v : t) {
    minx = std::min<std::int64_t>(minx, v[0]);
    maxx = std::max<std::int64_t>(maxx, v[0]);
    miny = std::min<std::int64_t>(miny, v[1]);
    maxy = std::max<std::int64_t>(maxy, v[1]);
  }
  // Any whole-pixel translation that keeps every vertex in SNAP.VERTEX.RANGE.
  // Both distances to the range ends are >= 0, so the divisions round towards the inside.
  const auto dx = *rc::gen::inRange<std::int64_t>(-((minx - rastrules::kMinVertexRaw) / 256),
                                                  (rastrules::kMaxVertexRaw - maxx) / 256 + 1);
  const auto dy = *rc::gen::inRange<std::int64_t>(-((miny - rastrules::kMinVertexRaw) / 256),
                                                  (rastrules::kMaxVertexRaw - maxy) / 256 + 1);
  gen::RawTriangle moved = t;
  for (gen::RawPoint& v : moved) {
    v[0] = static_cast<std::int32_t>(v[0] + 256 * dx);
    v[1] = static_cast<std::int32_t>(v[1] + 256 * dy);
  }
  const rastrules::TriangleSetup a = rastrules::setup_triangle(gen::to_vec2(t), state);
  const rastrules::TriangleSetup b = rastrules::setup_triangle(gen::to_vec2(moved), state);
  RC_ASSERT(a.status == b.status);
  // Pixel centres of a window of up to 48 x 48 pixels from the top-left of the bounding box
  // (one pixel outside it on every side), and the same centres moved.
  const std::int64_t px0 = minx / 256 - 2, py0 = miny / 256 - 2;
  const std::int64_t px1 = std::min(maxx / 256 + 2, px0 + 48);
  const std::int64_t py1 = std::min(maxy / 256 + 2, py0 + 48);
  std::size_t covered = 0;
  for (std::int64_t py = py0; py <= py1; ++py) {
    for (std::int64_t px = px0; px <= px1; ++px) {
      const std::int64_t sx = 256 * px + 128, sy = 256 * py + 128;
      const std::int64_t mx = sx + 256 * dx, my = sy + 256 * dy;
      if (!in_range(sx) || !in_range(sy) || !in_range(mx) || !in_range(my))
        continue;
      const bool ca = rastrules::covers(a, sample(sx, sy));
      const bool cb = rastrules::covers(b, sample(mx, my));
      if (ca != cb) {
        std::ostringstream msg;
        msg << "pixel (" << px << ", " << py << "): " << ca << ", moved pixel (" << px + dx << ", "
            << py + dy << "): " << cb;
        RC_FAIL(msg.str());
      }
      covered += ca ? 1u : 0u;
    }
  }
  RC_CLASSIFY(covered == 0, "no pixel covered");
}

// rule: TRI.INVARIANCE.TRANSLATION, TRI.ORIENT.NORMALISE
RC_GTEST_PROP(TriInvariance, ReversingTheWindingWithCullNoneChangesNothing, ()) {
  gen::TriScene s = *gen::tri_scene(32, 6);
  s.state.cull = rastrules::CullMode::kNone;
  gen::TriScene r = s;
  for (gen::GenTriangle& t : r.triangles) {
    // Reverse the order, and rotate by a random amount.
    const auto rot = static_cast<std::size_t>(*rc::gen::inRange(0, 3));
    const gen::FloatTriangle rev{t.v[0], t.v[2], t.v[1]};
    for (std::size_t i = 0; i < 3; ++i)
      t.v[i] = rev[(i + rot) % 3];
  }
  const std::string diff =
      gen::describe_difference(render_ok(r), rastrules::oracle::render(gen::to_oracle_scene(s)));
  if (!diff.empty())
    RC_FAIL("reversed (kernel) vs original (oracle): " + diff);
  RC_ASSERT(render_ok(r) == render_ok(s));
}

// rule: TRI.INVARIANCE.TRANSLATION, TRI.CULL.MODE, TRI.ORIENT.AREA, SNAP.CULL.AFTER_SNAP, TRI.DEGENERATE.ZERO_AREA
RC_GTEST_PROP(TriInvariance, CullingKeepsExactlyTheTrianglesOfTheOtherWinding, ()) {
  gen::TriScene s = *gen::tri_scene(32, 8);
  s.state.cull = rastrules::CullMode::kNone;
  const std::vector<rastrules::Fragment> all = render_ok(s);
  // Winding of each primitive from the snapped vertices, by the oracle (CGAL).
  std::vector<int> winding;
  for (const gen::GenTriangle& t : s.triangles) {
    std::array<std::array<std::int64_t, 2>, 3> r{};
    for (std::size_t i = 0; i < 3; ++i) {
      r[i] = {*rastrules::oracle::snap(t.v[i][0]), *rastrules::oracle::snap(t.v[i][1])};
    }
    winding.push_back(rastrules::oracle::winding(r));
  }
  const int front = s.state.front_face == rastrules::FrontFace::kClockwise ? 1 : -1;
  for (const rastrules::CullMode cull : {rastrules::CullMode::kBack, rastrules::CullMode::kFront}) {
    gen::TriScene c = s;
    c.state.cull = cull;
    std::vector<rastrules::Fragment> expected;
    for (const rastrules::Fragment& f : all) {
      const int w = winding[f.prim];
      // Cull back keeps front faces; cull front keeps back faces (never zero area, which
      // covers nothing anyway).
      if (cull == rastrules::CullMode::kBack ? w == front : w == -front)
        expected.push_back(f);
    }
    RC_ASSERT(render_ok(c) == expected);
  }
  RC_CLASSIFY(std::count(winding.begin(), winding.end(), 1) > 0 &&
                  std::count(winding.begin(), winding.end(), -1) > 0,
              "both windings in the scene");
}

} // namespace

// SPDX-License-Identifier: MIT
// Path primitives through the whole flow (SCENE.PRIM.PATH, SCENE.OUTPUT.AREA): random paths of
// the path generators become scene primitives (float32 points that snap back to themselves),
// are written and read back, rendered with other primitives under random sample patterns and
// masks, and checked by check_against_oracle (the one kernel-against-oracle comparison, also
// used by the showcase and fuzz_path); the decision records agree with the fragments.

#include <algorithm>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "path_checks.hpp"
#include "path_gen.hpp"
#include "rastrules/check/check.hpp"
#include "rastrules/decision.hpp"
#include "rastrules/io/scene_json.hpp"

namespace {

namespace pg = rastrules::path_gen;
using rastrules::FloatPath;
using rastrules::FloatPoint;

FloatPoint fpt(const pg::Raw2& r) {
  // raw / 256 is exact in float32 and snaps back to raw; the generators reach 2^23, one past
  // SNAP.VERTEX.RANGE's top, which a scene cannot hold: it becomes 2^23 - 1.
  auto c = [](std::int64_t v) {
    return static_cast<float>(std::min<std::int64_t>(v, (std::int64_t{1} << 23) - 1)) / 256.0f;
  };
  return FloatPoint{c(r[0]), c(r[1])};
}

FloatPath float_path(const pg::GPath& g, rastrules::path::Coverage coverage) {
  FloatPath fp;
  fp.fill_rule =
      g.evenodd ? rastrules::path::FillRule::kEvenOdd : rastrules::path::FillRule::kNonZero;
  fp.coverage = coverage;
  for (const pg::GContour& c : g.contours) {
    rastrules::FloatContour fc;
    fc.start = fpt(c.start);
    for (const pg::GPiece& q : c.pieces) {
      rastrules::FloatPathSegment s;
      s.kind = q.degree == 1   ? rastrules::path::SegmentKind::kLine
               : q.degree == 2 ? rastrules::path::SegmentKind::kQuadratic
                               : rastrules::path::SegmentKind::kCubic;
      for (std::size_t k = 0; k < q.pts.size(); ++k)
        s.p[k] = fpt(q.pts[k]);
      fc.segments.push_back(s);
    }
    fp.contours.push_back(std::move(fc));
  }
  return fp;
}

// rule: SCENE.PRIM.PATH, SCENE.OUTPUT.AREA, PATH.COVER.SAMPLE, PATH.AREA.EXACT, MSAA.MASK.AND
RC_GTEST_PROP(PathScene, RenderedPathsAgreeWithTheOracleThroughTheChecker, ()) {
  using namespace rastrules;
  const std::int32_t side = rastrules::path_checks::kSide;
  Scene s;
  s.width = side;
  s.height = side;
  s.conventions.fill = *rc::gen::element(FillConvention::kTopLeft, FillConvention::kTopRight,
                                         FillConvention::kBottomLeft, FillConvention::kBottomRight);
  const std::uint32_t n = *rc::gen::element(1u, 4u, 16u);
  set_sample_pattern(s, standard_pattern(n));
  if (*rc::gen::inRange(0, 4) == 0)
    s.msaa.sample_mask = *rc::gen::inRange<std::uint32_t>(0, full_mask(n) + 1);
  const std::size_t count = *rc::gen::inRange<std::size_t>(1, 3);
  for (std::size_t k = 0; k < count; ++k) {
    const bool curves = *rc::gen::arbitrary<bool>();
    const pg::GPath g = *pg::path(side, curves);
    const path::Coverage coverage =
        !curves && *rc::gen::arbitrary<bool>() ? path::Coverage::kArea : path::Coverage::kSamples;
    if (k == 0)
      RC_TAG(pg::name(g.kind), to_string(coverage), n);
    s.primitives.push_back(make_path(float_path(g, coverage)));
  }
  if (*rc::gen::arbitrary<bool>()) // a triangle among the paths, checked as before
    s.primitives.push_back(
        make_triangle({FloatPoint{0.5f, 0.25f}, FloatPoint{3.75f, 1.5f}, FloatPoint{1.25f, 3.5f}}));
  const auto reread = io::read_scene(io::write_scene(s));
  RC_ASSERT(std::holds_alternative<Scene>(reread));
  RC_ASSERT(io::same_scene(std::get<Scene>(reread), s));
  const auto prepared = prepare(s);
  RC_ASSERT(std::holds_alternative<PreparedScene>(prepared));
  const PreparedScene& ps = std::get<PreparedScene>(prepared);
  const std::vector<Fragment> f = rasterize(ps);
  const check::Mismatches m = check::check_against_oracle(s, ps, f);
  if (!m.agree())
    RC_FAIL(m.mismatches.front() + " (" + std::to_string(m.count) + " in all)\n" +
            io::write_scene(s));
  // The decision record of every pixel of the first path (explain) agrees with its fragments.
  for (std::int32_t y = 0; y < side; ++y) {
    for (std::int32_t x = 0; x < side; ++x) {
      const PixelDecision d = decide_pixel(ps, 0, x, y);
      const Fragment* hit = nullptr;
      for (const Fragment& g : f)
        hit = g.prim == 0 && g.x == x && g.y == y ? &g : hit;
      RC_ASSERT(d.covered == (hit != nullptr));
      if (hit != nullptr) {
        RC_ASSERT(d.path->mask == hit->mask);
        RC_ASSERT(d.path->area == hit->area);
      }
    }
  }
}

} // namespace

// SPDX-License-Identifier: MIT
// Property: threads change the time, not the result. On random scenes of triangles, points,
// lines and line strips (tie-heavy vertices, every line mode), single-sample (the streamed
// path) or multisampled with random patterns, masks, shading, centroids, quads and derivatives,
// rasterize() with 2 to 8 threads yields exactly the fragments of one thread, for the plain and
// the fast traversal.
// Implements (properties for): FAST.THREADS.DETERMINISTIC

#include <cstdint>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "msaa_gen.hpp"
#include "rastrules/isa.hpp"
#include "rastrules/scene.hpp"

namespace {

namespace mg = rastrules::msaa_gen;

constexpr std::int32_t kMaxSide = 16;

// A scene of 1 to 24 primitives: one sample at the centre with nothing else asked for (half the
// time) or a random multisample state.
rc::Gen<mg::MsScene> scene() {
  return rc::gen::exec([] {
    const bool single = *rc::gen::arbitrary<bool>();
    mg::MsScene s = *mg::scene_on(single ? mg::standard(1) : *mg::any_pattern(), kMaxSide);
    if (single) {
      s.sample_mask = 0xFFFFFFFFu;
      s.centroid.reset();
      s.shading = rastrules::ShadingRate::kPixel;
      s.quads = false;
      s.derivatives = rastrules::DerivativeMode::kNone;
    }
    const auto more = *rc::gen::inRange(0, 21);
    for (int i = 0; i < more; ++i)
      s.prims.push_back(*mg::prim(s.width, s.height, true, true));
    mg::make_valid(s);
    return s;
  });
}

// rule: FAST.THREADS.DETERMINISTIC
RC_GTEST_PROP(ThreadsProps, AnyThreadCountGivesTheSingleThreadedFragments, ()) {
  const mg::MsScene s = *scene();
  const auto prepared = rastrules::prepare(mg::to_kernel(s));
  if (const auto* err = std::get_if<rastrules::SceneError>(&prepared)) {
    std::ostringstream os;
    mg::show(s, os);
    RC_FAIL("kernel rejected a valid scene: " + err->what() + "\n" + os.str());
  }
  const auto& ps = std::get<rastrules::PreparedScene>(prepared);
  RC_CLASSIFY(s.pattern.count() == 1, "one sample");
  RC_CLASSIFY(s.prims.size() > 8, "more than 8 primitives");
  for (const rastrules::Traversal t : {rastrules::Traversal::kPlain, rastrules::Traversal::kFast}) {
    rastrules::RenderOptions one;
    one.traversal = t;
    const std::vector<rastrules::Fragment> base = rastrules::rasterize(ps, one);
    for (unsigned n = 2; n <= 8; ++n) {
      rastrules::RenderOptions o = one;
      o.threads = n;
      if (rastrules::rasterize(ps, o) != base) {
        std::ostringstream os;
        mg::show(s, os);
        RC_FAIL("traversal " + std::string(rastrules::to_string(t)) + ", " + std::to_string(n) +
                " threads differ from one thread\n" + os.str());
      }
    }
  }
}

} // namespace

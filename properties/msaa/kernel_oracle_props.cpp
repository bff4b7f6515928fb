// SPDX-License-Identifier: MIT
// Property: the kernel's rasterize() and resolve() equal the exact oracle (oracle/msaa.hpp) on
// random multisampled scenes of triangles, points, lines and line strips with tie-heavy
// vertices (on the 1/16 sample grid, so samples lie on edges), for EVERY standard pattern (each
// case renders the same scene with all five), for centre patterns and random custom patterns,
// with random sample masks, shading rates, centroid profiles, quads and derivatives.
// Implements (properties for): MSAA.PATTERN.STANDARD, MSAA.PATTERN.CENTER, MSAA.PATTERN.CUSTOM,
//   MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.POINT.PER_SAMPLE, MSAA.LINE.MODE,
//   MSAA.SHADING.PIXEL, MSAA.SHADING.SAMPLE, MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10,
//   MSAA.QUAD.ALIGN, MSAA.QUAD.LANE, MSAA.QUAD.HELPER, MSAA.DERIV.FINE, MSAA.DERIV.COARSE,
//   MSAA.RESOLVE.AVERAGE

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "msaa_gen.hpp"
#include "rastrules/check/check.hpp"
#include "rastrules/oracle/msaa.hpp"
#include "rastrules/scene.hpp"

namespace {

namespace mg = rastrules::msaa_gen;
namespace om = rastrules::oracle::msaa;

constexpr std::int32_t kMaxSide = 7;

// Renders s with the kernel and checks it with the one checker (check::check_against_oracle:
// every fragment field against the multisampling oracle, antialiased coverage against its
// own, and the resolved target), failing with the scene and the first differences.
void check_scene(const mg::MsScene& s) {
  const rastrules::Scene scene = mg::to_kernel(s);
  const auto prepared = rastrules::prepare(scene);
  std::ostringstream os;
  mg::show(s, os);
  if (const auto* err = std::get_if<rastrules::SceneError>(&prepared))
    RC_FAIL("kernel rejected a valid scene: " + err->what() + "\n" + os.str());
  const auto& ps = std::get<rastrules::PreparedScene>(prepared);
  const rastrules::check::Mismatches m =
      rastrules::check::check_against_oracle(scene, ps, rastrules::rasterize(ps), {12});
  if (!m.agree()) {
    for (const std::string& d : m.mismatches)
      os << "  " << d << "\n";
    RC_FAIL(std::to_string(m.count) + " differences\n" + os.str());
  }
}

// What a scene's oracle fragments contain, for the classification output.
struct Seen {
  bool helper = false, partial = false, empty = true;
};
Seen seen(const mg::MsScene& s) {
  Seen r;
  for (const om::Fragment& f : om::render(mg::to_oracle(s))) {
    r.helper = r.helper || f.helper;
    r.empty = r.empty && f.helper;
    r.partial = r.partial || (!f.helper && f.mask != rastrules::full_mask(s.pattern.count()));
  }
  return r;
}

void classify(const Seen& r) {
  RC_CLASSIFY(r.helper, "helper lanes");
  RC_CLASSIFY(r.partial, "partially covered pixels");
  RC_CLASSIFY(r.empty, "no covered pixel");
}

// rule: MSAA.PATTERN.STANDARD, MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.POINT.PER_SAMPLE, MSAA.LINE.MODE
// rule: MSAA.SHADING.PIXEL, MSAA.SHADING.SAMPLE, MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
// rule: MSAA.QUAD.ALIGN, MSAA.QUAD.LANE, MSAA.QUAD.HELPER, MSAA.DERIV.FINE, MSAA.DERIV.COARSE
// rule: MSAA.RESOLVE.AVERAGE, MSAA.SAMPLE.POSITION, MSAA.PATTERN.GRID, SCENE.MSAA, SCENE.OUTPUT.MSAA
RC_GTEST_PROP(MsaaKernelOracle, EqualOnRandomScenesForEveryStandardPattern, ()) {
  // Generated valid for 16 samples (keeps "aa" on d3d lines), re-validated for each count.
  const mg::MsScene base = *mg::scene_on(mg::standard(16), kMaxSide);
  const std::uint32_t raw_mask = *rc::gen::arbitrary<std::uint32_t>();
  const bool full = *rc::gen::inRange(0, 3) == 0;
  for (const std::uint32_t n : mg::standard_counts()) {
    mg::MsScene s = base;
    s.pattern = mg::standard(n);
    s.sample_mask = full ? 0xFFFFFFFFu : raw_mask;
    mg::make_valid(s);
    check_scene(s);
    if (n == 16)
      classify(seen(s));
  }
}

// rule: MSAA.PATTERN.CENTER, MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.LINE.MODE
RC_GTEST_PROP(MsaaKernelOracle, EqualOnRandomScenesWithCentrePatterns, ()) {
  const std::uint32_t n = *rc::gen::elementOf(mg::standard_counts());
  const mg::MsScene s = *mg::scene_on(mg::centre(n), kMaxSide);
  RC_TAG("center " + std::to_string(n));
  check_scene(s);
  classify(seen(s));
}

// rule: MSAA.PATTERN.CUSTOM, MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
RC_GTEST_PROP(MsaaKernelOracle, EqualOnRandomScenesWithCustomPatterns, ()) {
  const mg::Pattern p = mg::custom(*mg::custom_offsets());
  const mg::MsScene s = *mg::scene_on(p, kMaxSide);
  RC_CLASSIFY(!om::centre_in_hull(p.oracle), "centre outside the pattern's hull");
  check_scene(s);
  classify(seen(s));
}

// Without D3D's MultisampleEnable a d3d line keeps its own rasterizer on a multisampled
// target: an antialiased one hits every sample of each pixel of positive coverage and keeps
// that coverage, an aliased one every sample of its diamond-exit pixels. Checked by the one
// checker (check::check_against_oracle: the oracle's fragments, and each coverage within
// LINE.AA.PRECISION of the exact one), with every pattern, mask, centroid and shading rate.
// rule: MSAA.LINE.MODE, LINE.AA.FRAGMENT, MSAA.MASK.AND, MSAA.SHADING.SAMPLE
RC_GTEST_PROP(MsaaKernelOracle, D3DLinesWithoutMultisampleEnableKeepTheirRasterizer, ()) {
  const mg::Pattern p = *rc::gen::element(mg::standard(2), mg::standard(4), mg::standard(8),
                                          mg::standard(16), mg::custom(*mg::custom_offsets()));
  mg::MsScene s = *mg::scene_on(p, kMaxSide);
  s.line_mode = rastrules::LineMode::kD3DDiamond;
  s.multisample_enable = false;
  const bool aa = *rc::gen::arbitrary<bool>();
  for (mg::Prim& prim : s.prims)
    prim.aa = aa && (prim.type == rastrules::PrimitiveType::kLine ||
                     prim.type == rastrules::PrimitiveType::kLineStrip);
  check_scene(s);
  const auto frags = rastrules::render(mg::to_kernel(s));
  RC_ASSERT(std::holds_alternative<std::vector<rastrules::Fragment>>(frags));
  const auto& list = std::get<std::vector<rastrules::Fragment>>(frags);
  RC_CLASSIFY(aa, "antialiased lines");
  RC_CLASSIFY(s.shading == rastrules::ShadingRate::kSample, "sample shading");
  RC_CLASSIFY(std::any_of(list.begin(), list.end(),
                          [](const rastrules::Fragment& f) { return f.coverage_q16.has_value(); }),
              "fragments with coverage");
}

} // namespace

// SPDX-License-Identifier: MIT
// Property: bad multisample input is rejected with an error naming the field, and only bad
// input. A valid random scene is prepared; then exactly one thing is broken (a custom pattern
// of 0 or 17 positions, an offset off the [-8, 7] grid, a standard or centre pattern of a
// count without one, a mask bit beyond the pattern, quadrilateral lines on a centre pattern of
// several samples, sample shading of Bresenham lines with several samples, a resolve larger
// than 2^26 samples) and prepare() or resolve() must name the field.
// Implements (properties for): MSAA.LIMITS, MSAA.LINE.MODE, MSAA.SHADING.SAMPLE

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "msaa_gen.hpp"
#include "rastrules/scene.hpp"

namespace {

namespace mg = rastrules::msaa_gen;
using rastrules::SceneError;

std::string error_field(const rastrules::Scene& s) {
  const auto r = rastrules::prepare(s);
  if (const auto* e = std::get_if<SceneError>(&r))
    return e->field;
  return "";
}

rastrules::Primitive line_prim() {
  rastrules::Primitive p;
  p.type = rastrules::PrimitiveType::kLine;
  p.v = {{0.5f, 0.5f}, {3.25f, 2.0f}};
  return p;
}

// rule: MSAA.LIMITS, MSAA.LINE.MODE, MSAA.SHADING.SAMPLE
RC_GTEST_PROP(MsaaLimits, EachBrokenFieldIsNamedAndValidScenesPass, ()) {
  const mg::Pattern pat = *mg::any_pattern();
  const mg::MsScene valid = *mg::scene_on(pat, 5);
  rastrules::Scene s = mg::to_kernel(valid);
  RC_ASSERT(error_field(s).empty());
  const std::uint32_t n = pat.count();
  const int what = *rc::gen::inRange(0, 7);
  std::string want;
  switch (what) {
  case 0: { // a custom pattern of 0 or 17 positions
    const std::size_t count = *rc::gen::element<std::size_t>(0, 17);
    set_sample_pattern(s, rastrules::SamplePattern{rastrules::PatternKind::kCustom,
                                                   std::vector<rastrules::SampleOffset>(count)});
    s.msaa.sample_mask = 0xFFFFFFFFu;
    want = "sample_pattern";
    break;
  }
  case 1: { // one offset off the grid
    std::vector<rastrules::SampleOffset> o = pat.kernel.positions;
    const std::size_t k = *rc::gen::inRange<std::size_t>(0, o.size());
    const auto bad = static_cast<std::int8_t>(*rc::gen::element(-9, 8, -128, 127));
    const bool y = *rc::gen::arbitrary<bool>();
    (y ? o[k].y : o[k].x) = bad;
    set_sample_pattern(s, rastrules::SamplePattern{rastrules::PatternKind::kCustom, o});
    s.primitives.clear(); // only the pattern is wrong
    want = "sample_pattern[" + std::to_string(k) + "][" + (y ? "1" : "0") + "]";
    break;
  }
  case 2: { // a standard or centre kind with a count that has no pattern
    const std::size_t count = *rc::gen::element<std::size_t>(3, 5, 6, 7, 9, 15, 17);
    set_sample_pattern(s,
                       rastrules::SamplePattern{*rc::gen::element(rastrules::PatternKind::kStandard,
                                                                  rastrules::PatternKind::kCenter),
                                                std::vector<rastrules::SampleOffset>(count)});
    s.msaa.sample_mask = 0xFFFFFFFFu;
    want = "samples";
    break;
  }
  case 3: { // a mask bit beyond the pattern
    s.msaa.sample_mask = rastrules::full_mask(n) | (1u << *rc::gen::inRange(n, 31u));
    want = "sample_mask";
    break;
  }
  case 4: { // quadrilateral lines on a centre pattern of several samples
    const std::uint32_t c = *rc::gen::element(2u, 4u, 8u, 16u);
    set_sample_pattern(s, rastrules::center_pattern(c));
    s.msaa.sample_mask = 0xFFFFFFFFu;
    s.msaa.shading = rastrules::ShadingRate::kPixel;
    s.conventions.line_mode =
        *rc::gen::element(rastrules::LineMode::kD3DDiamond, rastrules::LineMode::kQuadWide,
                          rastrules::LineMode::kQuadNarrow);
    s.conventions.multisample_enable = true; // d3d lines are quadrilaterals only with it
    for (auto& p : s.primitives)
      p.aa = false;
    s.primitives.push_back(line_prim());
    want = "sample_pattern";
    break;
  }
  case 5: { // sample shading of Bresenham lines with several samples
    RC_PRE(n > 1u);
    s.msaa.shading = rastrules::ShadingRate::kSample;
    s.conventions.line_mode = rastrules::LineMode::kVulkanBresenham;
    for (auto& p : s.primitives)
      p.aa = false;
    s.primitives.push_back(line_prim());
    want = "shading";
    break;
  }
  default: { // a resolve of more than 2^26 samples
    rastrules::Scene big;
    big.width = 2049;
    big.height = 2048;
    set_sample_pattern(big, rastrules::standard_pattern(16));
    const auto prepared = rastrules::prepare(big);
    RC_ASSERT(std::holds_alternative<rastrules::PreparedScene>(prepared));
    const auto r = rastrules::resolve(std::get<rastrules::PreparedScene>(prepared), {});
    RC_ASSERT(std::holds_alternative<SceneError>(r));
    RC_ASSERT(std::get<SceneError>(r).field == "target");
    return;
  }
  }
  RC_TAG(want.substr(0, want.find('[')));
  RC_ASSERT(error_field(s) == want);
}

} // namespace

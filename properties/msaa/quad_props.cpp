// SPDX-License-Identifier: MIT
// Properties of 2x2 quads, from the kernel's own covered fragments: helper lanes are exactly
// the uncovered in-target lanes of even-aligned quads that hold a covered fragment of the same
// primitive (segment, sample index), with mask 0; asking for quads adds helpers and changes no
// covered fragment; helpers write nothing (the resolve is unchanged); derivatives of fixed
// evaluation points are one pixel; coarse derivatives are lane 0's in every lane; fine ddx is
// shared along a row and ddy along a column.
// Implements (properties for): MSAA.QUAD.ALIGN, MSAA.QUAD.LANE, MSAA.QUAD.HELPER,
//   MSAA.DERIV.FINE, MSAA.DERIV.COARSE

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "msaa_gen.hpp"
#include "rastrules/scene.hpp"

namespace {

namespace mg = rastrules::msaa_gen;
using rastrules::Fragment;

// (prim, seg, sample) identifies the quads a fragment belongs to; x, y its pixel.
using Group = std::tuple<std::uint32_t, std::int64_t, std::int64_t>;
Group group_of(const Fragment& f) {
  return {f.prim, f.seg ? std::int64_t{*f.seg} : -1, f.sample ? std::int64_t{*f.sample} : -1};
}

std::vector<Fragment> render_ok(const rastrules::Scene& s) {
  auto r = rastrules::render(s);
  if (const auto* err = std::get_if<rastrules::SceneError>(&r)) {
    RC_FAIL("kernel rejected a valid scene: " + err->what());
  }
  return std::get<std::vector<Fragment>>(r);
}

// Strips the quad-only fields so that lists with and without quads compare.
Fragment bare(Fragment f) {
  f.derivatives.reset();
  return f;
}

// rule: MSAA.QUAD.HELPER, MSAA.QUAD.ALIGN, MSAA.QUAD.LANE
RC_GTEST_PROP(MsaaQuads, HelperLanesAreExactlyTheUncoveredLanesOfTouchedQuads, ()) {
  const mg::Pattern p = *mg::any_pattern();
  mg::MsScene s = *mg::scene_on(p, 9);
  s.quads = true;
  const std::vector<Fragment> with = render_ok(mg::to_kernel(s));
  mg::MsScene t = s;
  t.quads = false;
  t.derivatives = rastrules::DerivativeMode::kNone;
  const std::vector<Fragment> without = render_ok(mg::to_kernel(t));

  std::map<Group, std::set<std::pair<std::int32_t, std::int32_t>>> covered, helpers;
  std::vector<Fragment> covered_list;
  for (const Fragment& f : with) {
    const auto key = std::make_pair(f.x, f.y);
    if (f.helper) {
      RC_ASSERT(f.mask == 0u);
      RC_ASSERT(helpers[group_of(f)].insert(key).second); // listed once
    } else {
      RC_ASSERT(f.mask != 0u);
      RC_ASSERT(covered[group_of(f)].insert(key).second);
      covered_list.push_back(bare(f));
    }
  }
  // Quads change no covered fragment.
  std::vector<Fragment> without_bare;
  for (const Fragment& f : without) {
    RC_ASSERT(!f.helper);
    without_bare.push_back(bare(f));
  }
  RC_ASSERT(covered_list == without_bare);
  // Expected helpers: per group, the in-target lanes of touched even-aligned quads without a
  // covered fragment.
  std::map<Group, std::set<std::pair<std::int32_t, std::int32_t>>> expect;
  for (const auto& [g, pixels] : covered) {
    for (const auto& [x, y] : pixels) {
      const std::int32_t qx = x & ~1, qy = y & ~1;
      for (std::int32_t lane = 0; lane < 4; ++lane) {
        // Lane order (x & 1) + 2 (y & 1).
        const std::int32_t lx = qx + (lane & 1), ly = qy + (lane >> 1);
        RC_ASSERT(rastrules::quad_lane(lx, ly) == static_cast<std::uint32_t>(lane));
        if (lx >= s.width || ly >= s.height)
          continue;
        if (pixels.count({lx, ly}) == 0)
          expect[g].insert({lx, ly});
      }
    }
  }
  RC_ASSERT(helpers == expect);
  // Helpers write nothing.
  const auto ps = std::get<rastrules::PreparedScene>(rastrules::prepare(mg::to_kernel(s)));
  const auto a = rastrules::resolve(ps, with);
  const auto b = rastrules::resolve(ps, without);
  RC_ASSERT(std::holds_alternative<rastrules::ResolvedImage>(a));
  RC_ASSERT(std::holds_alternative<rastrules::ResolvedImage>(b));
  RC_ASSERT(std::get<rastrules::ResolvedImage>(a).pixels ==
            std::get<rastrules::ResolvedImage>(b).pixels);
  RC_CLASSIFY(!helpers.empty(), "helper lanes");
}

// rule: MSAA.DERIV.FINE, MSAA.DERIV.COARSE, MSAA.QUAD.LANE
RC_GTEST_PROP(MsaaQuads, DerivativesFollowTheLaneStructure, ()) {
  const mg::Pattern p = *mg::any_pattern();
  mg::MsScene s = *mg::scene_on(p, 9);
  s.derivatives =
      *rc::gen::element(rastrules::DerivativeMode::kFine, rastrules::DerivativeMode::kCoarse);
  const std::vector<Fragment> frags = render_ok(mg::to_kernel(s));
  const bool fixed_point = !s.centroid || s.shading == rastrules::ShadingRate::kSample;
  // Per (group, quad): the derivatives of each listed lane.
  std::map<std::tuple<Group, std::int32_t, std::int32_t>,
           std::array<std::optional<rastrules::EvalDerivatives>, 4>>
      quads;
  for (const Fragment& f : frags) {
    RC_ASSERT(f.derivatives.has_value());
    const rastrules::EvalDerivatives d = *f.derivatives;
    if (fixed_point)
      RC_ASSERT((d == rastrules::EvalDerivatives{16, 0, 0, 16}));
    quads[{group_of(f), f.x & ~1, f.y & ~1}][rastrules::quad_lane(f.x, f.y)] = d;
  }
  for (const auto& [key, lanes] : quads) {
    for (std::size_t i = 0; i < 4; ++i) {
      for (std::size_t j = 0; j < 4; ++j) {
        if (!lanes[i] || !lanes[j])
          continue;
        if (s.derivatives == rastrules::DerivativeMode::kCoarse) {
          RC_ASSERT(*lanes[i] == *lanes[j]);
        } else {
          const bool same_row = (i & 2u) == (j & 2u), same_col = (i & 1u) == (j & 1u);
          if (same_row)
            RC_ASSERT(lanes[i]->ddx_x == lanes[j]->ddx_x && lanes[i]->ddx_y == lanes[j]->ddx_y);
          if (same_col)
            RC_ASSERT(lanes[i]->ddy_x == lanes[j]->ddy_x && lanes[i]->ddy_y == lanes[j]->ddy_y);
        }
      }
    }
  }
  RC_CLASSIFY(!fixed_point, "centroid evaluation points");
}

// rule: MSAA.DERIV.FINE, MSAA.DERIV.COARSE
TEST(MsaaQuads, FineAndCoarseTemplatesOnAQuad) {
  const std::array<int, 4> v = {1, 10, 100, 1000};
  EXPECT_EQ(rastrules::fine_derivatives(v, 0), (rastrules::Derivatives<int>{9, 99}));
  EXPECT_EQ(rastrules::fine_derivatives(v, 1), (rastrules::Derivatives<int>{9, 990}));
  EXPECT_EQ(rastrules::fine_derivatives(v, 2), (rastrules::Derivatives<int>{900, 99}));
  EXPECT_EQ(rastrules::fine_derivatives(v, 3), (rastrules::Derivatives<int>{900, 990}));
  EXPECT_EQ(rastrules::coarse_derivatives(v), (rastrules::Derivatives<int>{9, 99}));
}

} // namespace

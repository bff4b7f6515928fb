// SPDX-License-Identifier: MIT
// Glue between the kernel and the oracle for pairwise comparison (CGAL's Kernel_checker
// pattern): the same scene in both models, and a readable difference of two fragment lists.

#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "rastrules/gen/triangles.hpp"
#include "rastrules/oracle/triangle.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::gen {

[[nodiscard]] oracle::State to_oracle_state(const RasterState& s);
[[nodiscard]] oracle::Scene to_oracle_scene(const TriScene& s);
[[nodiscard]] std::array<std::array<std::int64_t, 2>, 3> to_oracle_raw(const RawTriangle& t);

// Returns "" when the lists are equal (as (prim, x, y) sequences, every kernel mask == 1),
// otherwise the counts, the fragments only the kernel produced and those only the oracle
// produced (at most 40 of each).
[[nodiscard]] std::string describe_difference(const std::vector<Fragment>& kernel,
                                              const std::vector<oracle::Fragment>& oracle);

} // namespace rastrules::gen

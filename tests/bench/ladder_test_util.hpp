// SPDX-License-Identifier: MIT
// Helpers for the precision-ladder tests.

#pragma once

#include <algorithm>
#include <vector>

#include "rastrules/bench/ladder.hpp"

namespace rastrules::bench::test {

// Whether this build has the reference-fast rung; the tests that run it skip without it.
inline bool has_reference_fast() {
  const std::vector<Rung>& rungs = all_rungs();
  return std::find(rungs.begin(), rungs.end(), Rung::kReferenceFast) != rungs.end();
}

} // namespace rastrules::bench::test

// SPDX-License-Identifier: MIT
// Shared by tests/check: whether any mismatch of a check names a given text.

#pragma once

#include <algorithm>
#include <string>

#include "rastrules/check/check.hpp"

namespace rastrules::check::test_support {

inline bool mentions(const Mismatches& m, const std::string& what) {
  return std::any_of(m.mismatches.begin(), m.mismatches.end(),
                     [&](const std::string& s) { return s.find(what) != std::string::npos; });
}

} // namespace rastrules::check::test_support

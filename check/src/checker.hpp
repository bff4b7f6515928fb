// SPDX-License-Identifier: MIT
// Internal to check/: how check.cpp and pipeline.cpp collect what they find.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "rastrules/check/check.hpp"

namespace rastrules::check::detail {

// The raw 16.8 position of the centre of pixel (x, y) (COORD.PIXEL.CENTER).
// rule: COORD.PIXEL.CENTER
inline std::array<std::int64_t, 2> centre_raw(std::int32_t x, std::int32_t y) {
  return {std::int64_t{x} * 256 + 128, std::int64_t{y} * 256 + 128};
}

// Collects mismatches (up to CheckOptions::max_mismatches, counting all) and the oracles used.
class Checker {
public:
  explicit Checker(const CheckOptions& o) : options_(o) {}
  void note(std::string what) {
    ++out_.count;
    if (out_.mismatches.size() < options_.max_mismatches)
      out_.mismatches.push_back(std::move(what));
  }
  void used(const std::string& oracle) {
    if (std::find(out_.oracles.begin(), out_.oracles.end(), oracle) == out_.oracles.end())
      out_.oracles.push_back(oracle);
  }
  Mismatches take() { return std::move(out_); }

private:
  CheckOptions options_;
  Mismatches out_;
};

// Compares the fragments of path primitive p (mine, in order) with the path oracle's samples
// or exact areas (check/src/path.cpp).
// rule: SCENE.PRIM.PATH, SCENE.OUTPUT.AREA
void check_path(const Scene& scene, std::size_t p, const std::vector<const Fragment*>& mine,
                Checker& c);

} // namespace rastrules::check::detail

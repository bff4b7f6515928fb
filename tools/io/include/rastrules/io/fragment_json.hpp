// SPDX-License-Identifier: MIT
// The fragment list output (spec/scene.md), written as a stream.
// Implements: SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.COVERAGE, SCENE.OUTPUT.MSAA

#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "rastrules/scene.hpp"

namespace rastrules::io {

// Writes {"fragments": [...]} to a FILE*, one fragment per line, without holding the list in
// memory. The caller emits fragments in (prim, y, x, seg) order (SCENE.OUTPUT.FRAGMENTS); the
// writer checks that order and refuses fragments that break it. Fragments with a seg get a
// "seg" field, fragments with a coverage a "coverage" field (SCENE.OUTPUT.COVERAGE); the
// multisampling fields "sample", "helper", "centroid", "ddx" and "ddy" appear only when the
// fragment has them (SCENE.OUTPUT.MSAA).
// rule: SCENE.OUTPUT.FRAGMENTS
class FragmentWriter {
 public:
  explicit FragmentWriter(std::FILE* out);
  FragmentWriter(const FragmentWriter&) = delete;
  FragmentWriter& operator=(const FragmentWriter&) = delete;

  // Appends one fragment. Returns false (and writes nothing) when it does not come after the
  // previous one in (prim, y, x, seg) order.
  bool add(const Fragment& f);

  // Closes the list. Returns false when any write failed.
  bool finish();

  [[nodiscard]] std::uint64_t count() const { return count_; }

 private:
  void flush_buffer();

  std::FILE* out_;
  std::string buffer_;
  std::uint64_t count_ = 0;
  Fragment last_{};
  bool failed_ = false;
};

// Returns coverage_q16 / 65536 as its exact decimal: "0.5", "0.0000152587890625", "1.0"
// (always a point and at least one fraction digit; no trailing zeros otherwise).
// rule: SCENE.OUTPUT.COVERAGE
[[nodiscard]] std::string format_coverage(std::uint32_t coverage_q16);

// Returns v / 16 as its exact decimal: "3.5625", "-0.25", "1.0" (always a point and at least one
// fraction digit). Centroids and derivatives are multiples of 1/16 px (SCENE.OUTPUT.MSAA).
// rule: SCENE.OUTPUT.MSAA
[[nodiscard]] std::string format_sixteenths(std::int64_t sixteenths);

// Returns the centroid of a fragment of pixel (x, y) at offset o from its centre, in 1/16 px
// from the target's origin: (16 x + 8 + o.x, 16 y + 8 + o.y).
[[nodiscard]] std::array<std::int64_t, 2> centroid_sixteenths(std::int32_t x, std::int32_t y,
                                                              SampleOffset o);

// Returns the fragment list as one string (for small lists and tests).
[[nodiscard]] std::string fragments_to_json(const std::vector<Fragment>& fragments);

}  // namespace rastrules::io

// SPDX-License-Identifier: MIT
// A deliberately imprecise built-in rasterizer with planted bugs, so that the fuzzer can be
// shown to find and shrink each one (spec/driver.md DRIVER.IMPRECISE). It draws triangles
// only, one sample per pixel, with its own code (never the kernel's coverage functions).
// Implements: DRIVER.IMPRECISE

#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "rastrules/driver/driver.hpp"

namespace rastrules::driver {

// The planted bugs.
struct ImpreciseBugs {
  bool float_edges = false;       // edge functions in float32, any sample with E >= 0 inside
  bool fill_bottom_right = false; // bottom-right tie rule whatever the scene's fill says
  bool four_bit_subpixel = false; // vertices snapped to 1/16 px instead of 1/256 px
  // Value bugs (DRIVER.IMPRECISE.VALUES): coverage is the reference's, the values are not.
  bool screen_space = false;    // perspective attributes interpolated linearly in screen space
  bool wrong_provoking = false; // flat attributes from the other end of the primitive
  bool d24_truncate = false;    // D24 depths stored by truncation instead of rounding
};

// Returns the bugs of a variant name: "imprecise" (the three coverage bugs),
// "imprecise:float-edges", "imprecise:fill-bottom-right", "imprecise:4-bit-subpixel", and the
// value bugs "imprecise:screen-space", "imprecise:provoking-vertex", "imprecise:d24-truncate";
// false when unknown.
[[nodiscard]] bool parse_imprecise_variant(std::string_view name, ImpreciseBugs* bugs);

// Opens the imprecise driver named `name` (see parse_imprecise_variant). On failure returns
// nullptr and sets *error.
[[nodiscard]] std::unique_ptr<Driver> open_imprecise_driver(std::string_view name,
                                                            std::string* error);

// The names open_imprecise_driver accepts.
[[nodiscard]] std::vector<std::string> imprecise_driver_names();

} // namespace rastrules::driver

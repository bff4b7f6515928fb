// SPDX-License-Identifier: MIT
// Pictures of the path ladder (spec/bench.md BENCH.PATH.PICTURES): the conflation cases filled
// by the exact kernel beside FreeType's gray rasterizer (an accumulation rasterizer) with their
// difference, and the ladder's time against error. Drawing is for people only: no figure of the
// ladder is read back from a picture.
// Implements: BENCH.PATH.PICTURES

#pragma once

#include <string>
#include <vector>

#include "rastrules/io/image.hpp"

namespace rastrules::bench::paths {

// One rung of one scene of the ladder, as the plot needs it.
struct PlotPoint {
  std::string scene;
  std::string rung;
  double seconds = 0;    // median time of the rung on the scene
  double mean_error = 0; // mean |coverage - exact area| over the pixels either side covers
};

// The conflation cases (a square drawn twice under even-odd, two triangles of opposite
// orientation sharing a diagonal under nonzero, pentagrams under both rules, a hole of the same
// orientation), each in its own target: row 1 the exact areas (cover_area), row 2 FreeType's
// gray raster of the same outline, row 3 their difference in 8-bit alpha (red: FreeType
// higher, blue: lower; white: equal within one level), every pixel magnified, outlines drawn,
// labelled. Also returns, per case, the pixels that differ by more than one level.
// rule: BENCH.PATH.PICTURES
[[nodiscard]] io::Image conflation_picture(std::vector<std::string>& differing);

// Time (relative to FreeType's gray raster on the same scene, log scale) against mean error
// (log scale; 0 on its own line at the bottom), one colour per rung, one point per scene.
// rule: BENCH.PATH.PICTURES
[[nodiscard]] io::Image ladder_plot(const std::vector<PlotPoint>& points);

} // namespace rastrules::bench::paths

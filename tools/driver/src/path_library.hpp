// SPDX-License-Identifier: MIT
// Private to the driver library: what every 2D library adapter shares (DRIVER.PATH.LIBRARY).
// An adapter draws one snapped path into an 8-bit coverage raster of the target; the base class
// checks what the library supports, draws every path primitive of a scene on its own raster and
// turns the rasters into fragments: an aliased pixel with nonzero coverage is a fragment with
// mask 1, an antialiased pixel with alpha A > 0 a fragment whose area is exactly A / 255.
// Implements: DRIVER.PATH.LIBRARY

#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rastrules/driver/driver.hpp"
#include "rastrules/path_types.hpp"

namespace rastrules::driver::detail {

// One path as an adapter draws it: the kernel's snapped path (raw 16.8, y down, the fill rule
// set), the target, and whether to antialias (coverage "area") or not ("samples").
struct PathJob {
  const path::Path* path = nullptr;
  std::int32_t width = 0;
  std::int32_t height = 0;
  bool antialiased = false;
};

class PathLibraryDriver : public Driver {
public:
  [[nodiscard]] const DriverInfo& info() const override { return info_; }
  // Why the library cannot draw the scene: a primitive that is not a path, multisampling, a fill
  // rule, coverage kind or curve it does not draw, a control point off its grid, a target
  // larger than it takes.
  // rule: DRIVER.PATH.LIBRARY
  [[nodiscard]] std::string unsupported(const Scene& scene) const override;
  // rule: DRIVER.PATH.LIBRARY
  [[nodiscard]] DrawResult draw(const Scene& scene) override;

protected:
  explicit PathLibraryDriver(DriverInfo info) : info_(std::move(info)) {}
  // Draws job.path into alpha (job.width * job.height bytes, row by row from the top, set to 0
  // before the call): 0 uncovered, anything else covered (aliased), or the 8-bit alpha
  // (antialiased). Returns an error message on failure.
  virtual std::optional<std::string> raster(const PathJob& job,
                                            std::vector<std::uint8_t>& alpha) = 0;

  DriverInfo info_;
};

// Why a driver named `name` that draws paths as `paths` says cannot draw the scene's paths, or an
// empty string: multisampling (one sample at the pixel centre only), pipeline state, a coverage
// kind, fill rule or curve it does not draw, a control point off its grid; with paths_only, a
// primitive that is not a path too. The 2D library adapters (PathLibraryDriver::unsupported) and
// the external driver's path scenes (DRIVER.EXTERNAL.PATHS) share it.
// rule: DRIVER.PATH.LIBRARY, DRIVER.EXTERNAL.PATHS
[[nodiscard]] std::string path_unsupported(const PathSupport& paths, const std::string& name,
                                           const Scene& scene, bool paths_only);

// The area of a pixel whose 8-bit alpha is a (1..255), exactly a / 255 px^2 with bound 0, as an
// antialiased path's fragment carries it (DRIVER.PATH.LIBRARY): one value per alpha, made once
// and shared by every fragment that has it.
// rule: DRIVER.PATH.LIBRARY, DRIVER.EXTERNAL.PATHS
[[nodiscard]] ExactArea alpha_area(std::uint8_t a);

// The info of a 2D library driver: no triangles, points or lines; one sample; `paths` as given.
[[nodiscard]] DriverInfo path_library_info(std::string name, std::string description,
                                           PathSupport paths, std::int32_t max_target_side);

} // namespace rastrules::driver::detail

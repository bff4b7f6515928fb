// SPDX-License-Identifier: MIT
// The driver interface: draw a scene with some rasterizer (lavapipe, an external process, a
// deliberately imprecise built-in one, or the reference kernel itself) and return its
// coverage as a fragment list in the kernel's own format, so the two compare directly.
// Implements: DRIVER.INTERFACE (spec/driver.md)

#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "rastrules/pipeline.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::driver {

// What a driver draws of 2D paths (SCENE.PRIM.PATH) and how (DRIVER.PATH.LIBRARY): a 2D
// library draws "samples" paths aliased (one sample at the pixel centre) and "area" paths
// antialiased, reporting 8-bit alpha.
// rule: DRIVER.PATH.LIBRARY
struct PathSupport {
  bool samples = false;    // coverage "samples": aliased, one sample at the pixel centre
  bool area = false;       // coverage "area": antialiased, 8-bit alpha
  bool nonzero = false;    // fill_rule "nonzero"
  bool evenodd = false;    // fill_rule "evenodd"
  bool quadratics = false; // quadratic Béziers (else only paths of lines)
  bool cubics = false;     // cubic Béziers
  // Control points must be multiples of grid_raw raw 16.8 units (FreeType: 4, its 26.6 grid);
  // grid names the library's own coordinates ("26.6", "24.8", "float").
  std::int32_t grid_raw = 1;
  std::string grid;
  std::string aliased_method;     // how it decides an aliased pixel, as its documentation says
  std::string antialiased_method; // how it computes alpha ("exact area", "signed-area cells", ...)
  [[nodiscard]] bool any() const { return samples || area; }
};

// What a driver reports about itself, and what it can draw.
struct DriverInfo {
  std::string name;        // "lavapipe", "opengl", "imprecise", "reference", "external"
  std::string description; // device name and version, or the command line
  int subpixel_bits = -1;  // as the driver reports it (-1: unknown)
  std::vector<std::uint32_t> sample_counts; // supported rasterization sample counts
  bool triangles = true;
  bool points = false;
  bool lines_bresenham = false;   // line_mode "vulkan-bresenham"
  bool lines_rectangular = false; // line_mode "quad-narrow" (Vulkan rectangular, 1.0 wide)
  bool lines_d3d = false;         // line_mode "d3d" (diamond exit)
  bool sample_mask = false;
  bool sample_shading = false;
  std::int32_t max_target_side = 0; // largest width or height it accepts
  // Whether draw_values() reports depth and attribute values of pipeline scenes
  // (DRIVER.VALUES); false: it reports coverage only.
  bool values = false;
  // 2D paths (DRIVER.PATH.LIBRARY): none unless set.
  PathSupport paths;
  // How an external driver's capabilities were learnt (DRIVER.EXTERNAL.CAPABILITIES):
  // "declared", or "none declared (WHY)"; empty for the built-in drivers.
  std::string capabilities;
};

// A driver failure (not a difference): could not start, device lost, unsupported scene, ...
struct DriverError {
  std::string message;
};

// Coverage as the driver produced it: one fragment per (prim, x, y[, seg][, sample]) with the
// per-sample mask, sorted like SCENE.OUTPUT.FRAGMENTS. Fields the driver cannot observe (seg,
// coverage_q16, centroid, derivatives, helper lanes) are left empty; compare() ignores them.
using DrawResult = std::variant<std::vector<Fragment>, DriverError>;

// The values a driver reports for one fragment of a pipeline scene (DRIVER.VALUES): what its
// fragment shader saw and what it would store, each list empty when not reported (and for a
// fragment the depth test killed, PIPE.DEPTH.KILL).
struct FragmentValues {
  std::optional<std::uint32_t> part;   // the clipped part (PIPE.CLIP.*), when the driver knows it
  std::vector<float> attr;             // one per declared attribute, in declaration order
  std::vector<pipe::DepthValue> depth; // one per sample of the mask, ascending sample index
  friend bool operator==(const FragmentValues&, const FragmentValues&) = default;
};

// Coverage with values: fragments as draw() returns them, and values empty (no values
// reported) or one entry per fragment.
struct Drawing {
  std::vector<Fragment> fragments;
  std::vector<FragmentValues> values;
};
using ValuesResult = std::variant<Drawing, DriverError>;

class Driver {
public:
  virtual ~Driver() = default;
  [[nodiscard]] virtual const DriverInfo& info() const = 0;
  // Returns an empty string when the driver can draw the scene, else the reason it cannot
  // (for example "4 samples not supported", "antialiased lines not supported").
  [[nodiscard]] virtual std::string unsupported(const Scene& scene) const = 0;
  // Draws the scene. Preconditions: unsupported(scene).empty(); prepare(scene) succeeds.
  [[nodiscard]] virtual DrawResult draw(const Scene& scene) = 0;
  // Draws the scene and returns its values too (DRIVER.VALUES). The default reports none:
  // draw()'s fragments with empty values.
  // rule: DRIVER.VALUES
  [[nodiscard]] virtual ValuesResult draw_values(const Scene& scene);
};

// Sorts fragments like SCENE.OUTPUT.FRAGMENTS (then by part), keeping values (empty, or one
// per fragment) with their fragments.
// rule: DRIVER.VALUES
void sort_drawing(Drawing& d);

// Opens a driver by name: "reference" (the kernel), "imprecise" (built-in planted bugs, see
// imprecise.hpp), "lavapipe" (Mesa's Vulkan CPU driver, when built with Vulkan), "opengl"
// (Mesa's llvmpipe through EGL surfaceless, when built with EGL and OpenGL), or
// "external:COMMAND" (spec/driver.md DRIVER.EXTERNAL.PROTOCOL). On failure returns nullptr and
// sets *error to a one-line reason.
[[nodiscard]] std::unique_ptr<Driver> open_driver(std::string_view name, std::string* error);

// Returns the names open_driver accepts in this build, for usage messages.
[[nodiscard]] std::vector<std::string> driver_names();

} // namespace rastrules::driver

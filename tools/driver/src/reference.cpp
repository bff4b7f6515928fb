// SPDX-License-Identifier: MIT
// The reference driver: the kernel itself behind the driver interface (prepare + rasterize),
// reporting only what a driver can observe.
// Implements: DRIVER.REFERENCE

#include <algorithm>
#include <utility>

#include "drivers.hpp"
#include "rastrules/fixed.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::driver {
namespace detail {

// rule: DRIVER.INTERFACE
std::vector<Fragment> observable(std::vector<Fragment> fragments) {
  std::erase_if(fragments, [](const Fragment& f) { return f.helper; });
  for (Fragment& f : fragments) {
    f.coverage_q16.reset();
    f.centroid.reset();
    f.derivatives.reset();
  }
  return fragments;
}

// rule: DRIVER.INTERFACE
DriverInfo full_capabilities(std::string name, std::string description, int subpixel_bits) {
  DriverInfo info;
  info.name = std::move(name);
  info.description = std::move(description);
  info.subpixel_bits = subpixel_bits;
  info.sample_counts = {1, 2, 4, 8, 16};
  info.points = true;
  info.lines_bresenham = true;
  info.lines_rectangular = true;
  info.lines_d3d = true;
  info.sample_mask = true;
  info.sample_shading = true;
  info.max_target_side = kMaxTargetSide;
  return info;
}

} // namespace detail

namespace {

class ReferenceDriver final : public Driver {
public:
  ReferenceDriver()
      : info_(detail::full_capabilities("reference",
                                        "rastrules reference kernel (fixed point, 16.8 snapping)",
                                        kSubpixelBits)) {}

  [[nodiscard]] const DriverInfo& info() const override { return info_; }

  // Everything the kernel accepts; an invalid scene is reported by draw() with the field.
  [[nodiscard]] std::string unsupported(const Scene&) const override { return {}; }

  // rule: DRIVER.REFERENCE
  [[nodiscard]] DrawResult draw(const Scene& scene) override {
    auto prepared = prepare(scene);
    if (const auto* e = std::get_if<SceneError>(&prepared)) {
      return DriverError{"invalid scene: " + e->what()};
    }
    return detail::observable(rasterize(std::get<PreparedScene>(prepared)));
  }

private:
  DriverInfo info_;
};

} // namespace

namespace detail {

std::unique_ptr<Driver> open_reference(std::string_view arg, std::string* error) {
  if (!arg.empty()) {
    *error = "driver 'reference' takes no argument";
    return nullptr;
  }
  return std::make_unique<ReferenceDriver>();
}

} // namespace detail
} // namespace rastrules::driver

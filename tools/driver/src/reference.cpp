// SPDX-License-Identifier: MIT
// The reference driver: the kernel itself behind the driver interface (prepare + rasterize),
// reporting only what a driver can observe; for pipeline scenes the pipeline (run_pipeline),
// with the exact depth and attribute values of every fragment.
// Implements: DRIVER.REFERENCE, DRIVER.VALUES

#include <algorithm>
#include <numeric>
#include <utility>

#include "drivers.hpp"
#include "rastrules/fixed.hpp"
#include "rastrules/pipeline.hpp"
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

// rule: DRIVER.VALUES
Drawing observable_drawing(pipe::PipeResult result) {
  Drawing out;
  const bool with_data = !result.data.empty();
  for (std::size_t i = 0; i < result.fragments.size(); ++i) {
    if (result.fragments[i].helper)
      continue;
    out.fragments.push_back(result.fragments[i]);
    if (!with_data)
      continue;
    pipe::FragmentData& d = result.data[i];
    out.values.push_back({d.part, std::move(d.attr), std::move(d.depth)});
  }
  out.fragments = observable(std::move(out.fragments));
  sort_drawing(out);
  return out;
}

// rule: DRIVER.VALUES
DrawResult coverage_of(ValuesResult r) {
  if (auto* e = std::get_if<DriverError>(&r))
    return std::move(*e);
  return std::move(std::get<Drawing>(r).fragments);
}

} // namespace detail

// rule: DRIVER.VALUES
ValuesResult Driver::draw_values(const Scene& scene) {
  DrawResult r = draw(scene);
  if (auto* e = std::get_if<DriverError>(&r))
    return std::move(*e);
  return Drawing{std::get<std::vector<Fragment>>(std::move(r)), {}};
}

// rule: DRIVER.VALUES
void sort_drawing(Drawing& d) {
  if (d.values.empty()) {
    std::stable_sort(d.fragments.begin(), d.fragments.end(), fragment_before);
    return;
  }
  std::vector<std::size_t> order(d.fragments.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (fragment_before(d.fragments[a], d.fragments[b]))
      return true;
    if (fragment_before(d.fragments[b], d.fragments[a]))
      return false;
    return d.values[a].part < d.values[b].part;
  });
  Drawing sorted;
  sorted.fragments.reserve(order.size());
  sorted.values.reserve(order.size());
  for (const std::size_t i : order) {
    sorted.fragments.push_back(std::move(d.fragments[i]));
    sorted.values.push_back(std::move(d.values[i]));
  }
  d = std::move(sorted);
}

namespace {

class ReferenceDriver final : public Driver {
public:
  ReferenceDriver()
      : info_(detail::full_capabilities("reference",
                                        "rastrules reference kernel (fixed point, 16.8 snapping)",
                                        kSubpixelBits)) {
    info_.values = true;
    info_.paths = {true,
                   true,
                   true,
                   true,
                   true,
                   true,
                   1,
                   "16.8",
                   "PATH.COVER.SAMPLE (exact)",
                   "PATH.AREA.EXACT (exact area)"};
  }

  [[nodiscard]] const DriverInfo& info() const override { return info_; }

  // Everything the kernel accepts; an invalid scene is reported by draw() with the field.
  [[nodiscard]] std::string unsupported(const Scene&) const override { return {}; }

  // rule: DRIVER.REFERENCE
  [[nodiscard]] DrawResult draw(const Scene& scene) override {
    if (has_pipeline_state(scene)) {
      return detail::coverage_of(draw_values(scene));
    }
    auto prepared = prepare(scene);
    if (const auto* e = std::get_if<SceneError>(&prepared)) {
      return DriverError{"invalid scene: " + e->what()};
    }
    return detail::observable(rasterize(std::get<PreparedScene>(prepared)));
  }

  // rule: DRIVER.REFERENCE, DRIVER.VALUES
  [[nodiscard]] ValuesResult draw_values(const Scene& scene) override {
    if (!has_pipeline_state(scene))
      return Driver::draw_values(scene);
    auto result = pipe::run_pipeline(scene);
    if (const auto* e = std::get_if<SceneError>(&result))
      return DriverError{"invalid scene: " + e->what()};
    return detail::observable_drawing(std::get<pipe::PipeResult>(std::move(result)));
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

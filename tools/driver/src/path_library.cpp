// SPDX-License-Identifier: MIT
// The 2D library adapters' shared part: support checks, one raster per path, fragments.
// Implements: DRIVER.PATH.LIBRARY

#include "path_library.hpp"

#include <array>
#include <memory>
#include <variant>

#include "rastrules/path.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::driver::detail {

namespace {

// The first control point of the path that is not a multiple of grid raw units, as text.
std::optional<std::string> off_grid(const path::Path& p, std::int32_t grid) {
  auto off = [&](path::Point q) { return q.x % grid != 0 || q.y % grid != 0; };
  auto text = [](path::Point q) {
    return "(" + std::to_string(q.x) + ", " + std::to_string(q.y) + ") raw";
  };
  for (const path::Contour& c : p.contours) {
    if (off(c.start))
      return text(c.start);
    for (const path::Segment& s : c.segments)
      for (std::size_t i = 0; i < path::point_count(s.kind); ++i)
        if (off(s.p[i]))
          return text(s.p[i]);
  }
  return std::nullopt;
}

} // namespace

// rule: DRIVER.PATH.LIBRARY
DriverInfo path_library_info(std::string name, std::string description, PathSupport paths,
                             std::int32_t max_target_side) {
  DriverInfo info;
  info.name = std::move(name);
  info.description = std::move(description);
  info.subpixel_bits = -1;
  info.sample_counts = {1};
  info.triangles = false;
  info.max_target_side = max_target_side;
  info.paths = std::move(paths);
  return info;
}

// rule: DRIVER.PATH.LIBRARY, DRIVER.EXTERNAL.PATHS
ExactArea alpha_area(std::uint8_t a) {
  static const std::array<ExactArea, 256> areas = [] {
    std::array<ExactArea, 256> t;
    for (unsigned k = 1; k < t.size(); ++k)
      t[k] = ExactArea(std::make_shared<const path::AreaValue>(
          path::AreaValue{boost::multiprecision::cpp_rational(k, 255), 0}));
    return t;
  }();
  return areas[a];
}

// rule: DRIVER.PATH.LIBRARY, DRIVER.EXTERNAL.PATHS
std::string path_unsupported(const PathSupport& ps, const std::string& name, const Scene& scene,
                             bool paths_only) {
  if (scene.msaa.pattern.count() != 1 || scene.msaa.pattern.positions[0] != SampleOffset{})
    return name + " draws one sample at the pixel centre";
  if (has_pipeline_state(scene))
    return name + " draws window-space paths only";
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const Primitive& p = scene.primitives[i];
    const std::string at = "primitives[" + std::to_string(i) + "]: ";
    if (p.type != PrimitiveType::kPath || !p.path) {
      if (paths_only)
        return at + name + " draws paths only";
      continue;
    }
    const FloatPath& fp = *p.path;
    if (fp.coverage == path::Coverage::kSamples && !ps.samples)
      return at + name + " draws no aliased paths (coverage \"samples\")";
    if (fp.coverage == path::Coverage::kArea && !ps.area)
      return at + name + " draws no antialiased paths (coverage \"area\")";
    if (fp.fill_rule == path::FillRule::kNonZero ? !ps.nonzero : !ps.evenodd)
      return at + name + " has no fill rule " + std::string(to_string(fp.fill_rule));
    for (const FloatContour& c : fp.contours)
      for (const FloatPathSegment& s : c.segments) {
        if (s.kind == path::SegmentKind::kQuadratic && !ps.quadratics)
          return at + name + " draws no quadratic curves";
        if (s.kind == path::SegmentKind::kCubic && !ps.cubics)
          return at + name + " draws no cubic curves";
      }
  }
  if (ps.grid_raw > 1) {
    auto prepared = prepare(scene);
    if (const auto* ok = std::get_if<PreparedScene>(&prepared))
      for (std::size_t i = 0; i < ok->primitives.size(); ++i)
        if (ok->primitives[i].path)
          if (auto q = off_grid(*ok->primitives[i].path, ps.grid_raw))
            return "primitives[" + std::to_string(i) + "]: control point " + *q + " is not on " +
                   name + "'s " + ps.grid + " grid";
  }
  return {};
}

// rule: DRIVER.PATH.LIBRARY
std::string PathLibraryDriver::unsupported(const Scene& scene) const {
  if (scene.width > info_.max_target_side || scene.height > info_.max_target_side)
    return "target larger than " + std::to_string(info_.max_target_side) + " px";
  return path_unsupported(info_.paths, info_.name, scene, /*paths_only=*/true);
}

// rule: DRIVER.PATH.LIBRARY
DrawResult PathLibraryDriver::draw(const Scene& scene) {
  auto prepared = prepare(scene);
  if (const auto* e = std::get_if<SceneError>(&prepared))
    return DriverError{"invalid scene: " + e->what()};
  const PreparedScene& ps = std::get<PreparedScene>(prepared);
  std::vector<Fragment> out;
  std::vector<std::uint8_t> alpha;
  const auto w = static_cast<std::size_t>(ps.width);
  for (std::size_t i = 0; i < ps.primitives.size(); ++i) {
    const PreparedPrimitive& prim = ps.primitives[i];
    if (!prim.path)
      return DriverError{info_.name + " draws paths only"};
    PathJob job{prim.path.get(), ps.width, ps.height, prim.coverage == path::Coverage::kArea};
    alpha.assign(w * static_cast<std::size_t>(ps.height), 0);
    if (auto err = raster(job, alpha))
      return DriverError{info_.name + ": " + *err};
    for (std::int32_t y = 0; y < ps.height; ++y)
      for (std::int32_t x = 0; x < ps.width; ++x) {
        const std::uint8_t a = alpha[static_cast<std::size_t>(y) * w + static_cast<std::size_t>(x)];
        if (a == 0)
          continue;
        Fragment f(static_cast<std::uint32_t>(i), x, y, 1);
        if (job.antialiased)
          f.area = alpha_area(a);
        out.push_back(std::move(f));
      }
  }
  return out;
}

} // namespace rastrules::driver::detail

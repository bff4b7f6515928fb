// SPDX-License-Identifier: MIT
// What the GPU adapters share: see gpu_common.hpp.

#include "gpu_common.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

namespace rastrules::driver::detail {

bool is_line(PrimitiveType t) {
  return t == PrimitiveType::kLine || t == PrimitiveType::kLineStrip;
}

std::uint32_t slot_count(const Primitive& p) {
  if (p.type == PrimitiveType::kLineStrip) {
    return p.v.size() < 2 ? 0U : static_cast<std::uint32_t>(p.v.size() - 1);
  }
  return 1U;
}

// rule: DRIVER.LAVAPIPE.POSITION, DRIVER.OPENGL.POSITION
double position_scale(const Scene& scene) {
  double extent =
      std::max({1.0, static_cast<double>(scene.width), static_cast<double>(scene.height)});
  for (const Primitive& p : scene.primitives) {
    for (const FloatPoint& v : p.v) {
      for (float c : v) {
        if (!std::isfinite(c))
          return 0.0;
        extent = std::max(extent, std::fabs(static_cast<double>(c)));
      }
    }
  }
  // A margin of 2 px keeps the parts of points and lines that lie up to 1 px beyond their
  // vertices (point squares, line rectangles) inside the viewport (what lies outside it is
  // dropped).
  extent += 2.0;
  double k = 1.0;
  while (k < extent)
    k *= 2.0;
  return k;
}

// rule: DRIVER.LAVAPIPE.POSITION, DRIVER.OPENGL.POSITION
double max_position_scale(double max_dim, double bound) {
  double k = 1.0;
  while (2.0 * (2.0 * k) <= max_dim && 2.0 * k <= bound)
    k *= 2.0;
  return k;
}

// rule: DRIVER.LAVAPIPE.SUPPORT, DRIVER.OPENGL.SUPPORT
std::string unsupported_scene(const Scene& scene, const DriverInfo& info, double max_k,
                              const SupportChecks& checks) {
  // rule: DRIVER.VALUES
  // The adapters draw window-space coverage: a scene with pipeline state (which `check` reads
  // since drivers may report values) is refused, not drawn from its empty vertex lists.
  if (const auto field = first_pipeline_field(scene))
    return "pipeline state (" + *field + ", SCENE.PIPELINE) not supported by the adapter";
  const MultisampleState& ms = scene.msaa;
  if (ms.pattern.kind != PatternKind::kStandard) {
    return "sample pattern '" + std::string(to_string(ms.pattern.kind)) + "' not supported (" +
           std::string(checks.pattern_note) + ")";
  }
  const std::uint32_t samples = ms.count();
  if (std::find(info.sample_counts.begin(), info.sample_counts.end(), samples) ==
      info.sample_counts.end()) {
    return std::to_string(samples) + " samples not supported by " + checks.count_by;
  }
  if (checks.msaa) {
    if (std::string why = checks.msaa(ms); !why.empty())
      return why;
  }
  if (ms.shading == ShadingRate::kSample) {
    return "sample-frequency shading not supported (the adapter observes coverage per pixel)";
  }
  if (scene.width > info.max_target_side || scene.height > info.max_target_side) {
    return "target " + std::to_string(scene.width) + "x" + std::to_string(scene.height) +
           " larger than " + std::to_string(info.max_target_side);
  }
  std::uint64_t slots = 0;
  for (const Primitive& p : scene.primitives) {
    // rule: SCENE.PRIM.PATH
    if (p.type == PrimitiveType::kPath)
      return "paths not supported (a GPU adapter draws triangles, points and lines)";
    if (is_line(p.type)) {
      if (std::string why = checks.line(scene, p); !why.empty())
        return why;
    }
    slots += slot_count(p);
  }
  const double k = position_scale(scene);
  if (k > max_k) {
    return "coordinates need a viewport of side " + std::to_string(2.0 * k) + " (" +
           std::string(checks.k_limit) + ": K <= " + std::to_string(max_k) + ")";
  }
  const std::uint64_t bytes = slots * static_cast<std::uint64_t>(std::max(scene.width, 0)) *
                              static_cast<std::uint64_t>(std::max(scene.height, 0)) * 4U;
  if (bytes > kMaxCoverageBytes) {
    return "coverage buffer of " + std::to_string(bytes) + " bytes exceeds " +
           std::to_string(kMaxCoverageBytes);
  }
  return {};
}

DrawResult GpuDriver::draw(const Scene& scene) {
  if (std::string why = unsupported(scene); !why.empty())
    return DriverError{"unsupported: " + why};
  auto prepared = prepare(scene);
  if (const auto* e = std::get_if<SceneError>(&prepared)) {
    return DriverError{"invalid scene: " + e->what()};
  }
  const auto w = static_cast<std::uint32_t>(scene.width);
  const auto h = static_cast<std::uint32_t>(scene.height);
  if (w == 0 || h == 0 || scene.primitives.empty())
    return std::vector<Fragment>{};
  // Slots and vertices: one draw per scene primitive, vertices as float32 exactly as read.
  return draw_packed(scene, pack_scene(scene), w, h);
}

PackedScene pack_scene(const Scene& scene) {
  PackedScene out;
  for (const Primitive& p : scene.primitives) {
    out.first_slot.push_back(out.slots);
    out.slots += slot_count(p);
    for (const FloatPoint& v : p.v) {
      out.vertices.push_back(v[0]);
      out.vertices.push_back(v[1]);
    }
  }
  return out;
}

// rule: DRIVER.LAVAPIPE.COVERAGE, DRIVER.OPENGL.COVERAGE
std::vector<Fragment> decode_coverage(const Scene& scene, const PackedScene& packed,
                                      const std::uint32_t* coverage, std::uint32_t w,
                                      std::uint32_t h) {
  std::vector<Fragment> out;
  const std::uint32_t all = full_mask(scene.msaa.count());
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const bool strip = scene.primitives[i].type == PrimitiveType::kLineStrip;
    const std::uint32_t n = slot_count(scene.primitives[i]);
    for (std::uint32_t s = 0; s < n; ++s) {
      const std::size_t plane = std::size_t{packed.first_slot[i] + s} * w * h;
      for (std::uint32_t y = 0; y < h; ++y) {
        for (std::uint32_t x = 0; x < w; ++x) {
          const std::uint32_t m = coverage[plane + std::size_t{y} * w + x] & all;
          if (m == 0)
            continue;
          Fragment f(static_cast<std::uint32_t>(i), static_cast<std::int32_t>(x),
                     static_cast<std::int32_t>(y), m);
          if (strip)
            f.seg = s;
          out.push_back(f);
        }
      }
    }
  }
  std::sort(out.begin(), out.end(), fragment_before);
  return out;
}

} // namespace rastrules::driver::detail

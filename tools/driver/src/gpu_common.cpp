// SPDX-License-Identifier: MIT
// What the GPU adapters share: see gpu_common.hpp.

#include "gpu_common.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include "drivers.hpp"

namespace rastrules::driver::detail {

bool is_line(PrimitiveType t) {
  return t == PrimitiveType::kLine || t == PrimitiveType::kLineStrip;
}

std::uint32_t slot_count(const Primitive& p) {
  if (p.type == PrimitiveType::kLineStrip) {
    // Window-space vertices, or clip-space positions (pipeline scenes).
    const std::size_t n = p.pos.empty() ? p.v.size() : p.pos.size();
    return n < 2 ? 0U : static_cast<std::uint32_t>(n - 1);
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
  if (const auto field = first_pipeline_field(scene)) {
    if (!checks.pipeline)
      return "pipeline state (" + *field + ", SCENE.PIPELINE) not supported by the adapter";
    if (std::string why = checks.pipeline(scene); !why.empty())
      return why;
  }
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
  // rule: DRIVER.VALUES
  // Sample-rate shading is drawn only by the values path (the adapter's pipeline check decides).
  if (ms.shading == ShadingRate::kSample && !(checks.pipeline && has_pipeline_state(scene))) {
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
                              static_cast<std::uint64_t>(std::max(scene.height, 0)) * 4U *
                              (1U + scene.attributes.size());
  if (bytes > kMaxCoverageBytes) {
    return "coverage buffer of " + std::to_string(bytes) + " bytes exceeds " +
           std::to_string(kMaxCoverageBytes);
  }
  return {};
}

DrawResult GpuDriver::draw(const Scene& scene) {
  if (has_pipeline_state(scene))
    return detail::coverage_of(draw_values(scene));
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

// rule: DRIVER.VALUES
ValuesResult GpuDriver::draw_values(const Scene& scene) {
  if (!has_pipeline_state(scene))
    return Driver::draw_values(scene);
  if (std::string why = unsupported(scene); !why.empty())
    return DriverError{"unsupported: " + why};
  if (const auto e = pipe::validate(scene))
    return DriverError{"invalid scene: " + e->what()};
  // Positions are checked as the reference checks them while it runs (PIPE.INPUT.POSITION):
  // finite and at most 2^64 in magnitude, given and after the transform.
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const Primitive& p = scene.primitives[i];
    for (std::size_t j = 0; j < p.pos.size(); ++j) {
      for (const pipe::Vec4f& q : {p.pos[j], clip_position(scene, p.pos[j])}) {
        for (const float c : q) {
          if (!std::isfinite(c) || std::fabs(static_cast<double>(c)) > pipe::kMaxPosition) {
            return DriverError{"invalid scene: primitives[" + std::to_string(i) + "].pos[" +
                               std::to_string(j) + "]: not finite or beyond 2^64 (" +
                               "PIPE.INPUT.POSITION)"};
          }
        }
      }
    }
  }
  const auto w = static_cast<std::uint32_t>(scene.width);
  const auto h = static_cast<std::uint32_t>(scene.height);
  if (w == 0 || h == 0 || scene.primitives.empty())
    return Drawing{};
  return draw_pipeline(scene, w, h);
}

ValuesResult GpuDriver::draw_pipeline(const Scene&, std::uint32_t, std::uint32_t) {
  return DriverError{"unsupported: pipeline state not supported by the adapter"};
}

// rule: DRIVER.OPENGL.VALUES, DRIVER.LAVAPIPE.VALUES
std::string values_problem(const Scene& s) {
  const pipe::Viewport vp = viewport_of(s);
  for (const Primitive& p : s.primitives) {
    if (!p.pos.empty())
      continue;
    if (std::any_of(p.w.begin(), p.w.end(), [](float w) { return w != 1.0f; }))
      return "window-space w other than 1 not supported by the adapter's values";
    if (std::any_of(p.z.begin(), p.z.end(),
                    [&](float z) { return !(z >= vp.min_depth && z <= vp.max_depth); })) {
      return "window-space z outside the viewport's depth range not supported by the adapter's "
             "values (the driver would clip what the reference clamps)";
    }
  }
  return {};
}

pipe::Vec4f clip_position(const Scene& scene, pipe::Vec4f p) {
  // rule: PIPE.TRANSFORM.FLOAT32
  // In the reference's order, each product rounded to float32 as the reference rounds it.
  if (scene.model)
    p = pipe::transform(*scene.model, p);
  if (scene.view)
    p = pipe::transform(*scene.view, p);
  if (scene.projection)
    p = pipe::transform(*scene.projection, p);
  return p;
}

pipe::Viewport viewport_of(const Scene& scene) {
  return scene.viewport.value_or(pipe::Viewport{0.0f, 0.0f, static_cast<float>(scene.width),
                                                static_cast<float>(scene.height), 0.0f, 1.0f});
}

// rule: DRIVER.VALUES, PIPE.CLIP.LINE
PackedPipeline pack_pipeline(const Scene& scene) {
  PackedPipeline out;
  const std::size_t n = scene.attributes.size();
  out.stride = static_cast<std::uint32_t>(4 + n);
  const pipe::Viewport vp = viewport_of(scene);
  const bool depth_clip = !scene.depth || scene.depth->clip;
  for (const Primitive& p : scene.primitives) {
    out.first_slot.push_back(out.slots);
    const bool window = p.pos.empty();
    out.window_space.push_back(window);
    const std::size_t nv = window ? p.v.size() : p.pos.size();
    out.slots += slot_count(p);
    std::vector<pipe::Vec4f> clip;
    for (std::size_t j = 0; j < nv; ++j) {
      if (window) {
        out.vertices.insert(out.vertices.end(),
                            {p.v[j][0], p.v[j][1], p.z.empty() ? 0.0f : p.z[j], 1.0f});
      } else {
        clip.push_back(clip_position(scene, p.pos[j]));
        out.vertices.insert(out.vertices.end(), clip.back().begin(), clip.back().end());
      }
      for (std::size_t k = 0; k < n; ++k)
        out.vertices.push_back(p.attr.empty() ? 0.0f : p.attr[j][k]);
    }
    bool clipped = false;
    if (!window && p.type == PrimitiveType::kLineStrip) {
      const pipe::ClipVolume vol = pipe::clip_volume(clip, vp, depth_clip);
      clipped = std::any_of(clip.begin(), clip.end(),
                            [&](const pipe::Vec4f& c) { return !pipe::inside(vol, c); });
    }
    out.clipped_strip.push_back(clipped);
  }
  return out;
}

// rule: DRIVER.VALUES
Drawing decode_values(const Scene& scene, const PackedPipeline& packed,
                      const std::uint32_t* coverage, const float* values,
                      const std::vector<std::vector<std::optional<pipe::DepthValue>>>* depth,
                      std::uint32_t w, std::uint32_t h, std::uint32_t per_sample,
                      std::uint32_t depth_samples) {
  Drawing out;
  const std::uint32_t all = full_mask(scene.msaa.count());
  const std::size_t n = scene.attributes.size();
  const std::size_t plane = std::size_t{w} * h;
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const Primitive& p = scene.primitives[i];
    const bool strip = p.type == PrimitiveType::kLineStrip;
    const std::uint32_t slots = slot_count(p);
    for (std::uint32_t s = 0; s < slots; ++s) {
      const std::size_t slot = packed.first_slot[i] + s;
      for (std::size_t k = 0; k < plane; ++k) {
        const std::uint32_t m = coverage[slot * plane + k] & all;
        if (m == 0)
          continue;
        Fragment f(static_cast<std::uint32_t>(i), static_cast<std::int32_t>(k % w),
                   static_cast<std::int32_t>(k / w), m);
        FragmentValues v;
        if (strip && packed.clipped_strip[i])
          v.part = s;
        else if (strip)
          f.seg = s;
        const auto store = [&](Fragment frag, std::size_t entry) {
          FragmentValues fv = v;
          const float* a = values + entry * n;
          fv.attr.assign(a, a + n);
          // One stored depth per covered sample, ascending; none unless each was read.
          if (depth != nullptr && !(*depth)[slot].empty()) {
            for (std::uint32_t bit = 0; bit < 32; ++bit) {
              if ((frag.mask >> bit & 1U) == 0)
                continue;
              const std::size_t at = k * depth_samples + bit;
              if (bit >= depth_samples || !(*depth)[slot][at]) {
                fv.depth.clear();
                break;
              }
              fv.depth.push_back(*(*depth)[slot][at]);
            }
          }
          out.fragments.push_back(frag);
          out.values.push_back(std::move(fv));
        };
        if (per_sample == 0) {
          store(f, slot * plane + k);
          continue;
        }
        // rule: MSAA.SHADING.SAMPLE
        // One fragment per covered sample, its values at the sample's entry.
        for (std::uint32_t bit = 0; bit < 32; ++bit) {
          if ((m >> bit & 1U) == 0)
            continue;
          Fragment fs = f;
          fs.mask = 1U << bit;
          fs.sample = bit;
          store(fs, (slot * plane + k) * per_sample + bit);
        }
      }
    }
  }
  sort_drawing(out);
  return out;
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

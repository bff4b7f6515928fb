// SPDX-License-Identifier: MIT
// Private to the driver library: what the GPU adapters (lavapipe.cpp, opengl.cpp) share. Both
// observe coverage the same way (DRIVER.LAVAPIPE.* / DRIVER.OPENGL.*): one draw per scene
// primitive with its float32 vertices as read, a viewport [-K, K] with K a power of two, and a
// storage buffer of one 32-bit sample mask per pixel and coverage slot (one slot per primitive,
// one per segment of a line strip) that the fragment shader ORs gl_SampleMaskIn into. This
// header holds the API-independent parts of that scheme; what differs (the API calls, the
// support rules of each API) stays in each adapter. Pipeline scenes (DRIVER.VALUES) add a
// position of four floats and the attributes to each vertex, and a plane of values per slot.
// Implements: DRIVER.LAVAPIPE.COVERAGE, DRIVER.LAVAPIPE.POSITION, DRIVER.LAVAPIPE.SUPPORT,
//             DRIVER.OPENGL.COVERAGE, DRIVER.OPENGL.POSITION, DRIVER.OPENGL.SUPPORT,
//             DRIVER.VALUES

#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rastrules/driver/driver.hpp"
#include "rastrules/pipeline.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::driver::detail {

// The largest coverage buffer one draw may use (slots * width * height * 4 bytes).
inline constexpr std::uint64_t kMaxCoverageBytes = std::uint64_t{256} << 20;

[[nodiscard]] bool is_line(PrimitiveType t);

// The number of coverage slots of a primitive: one, or one per segment of a strip (of its
// window-space vertices or, in a pipeline scene, its positions).
[[nodiscard]] std::uint32_t slot_count(const Primitive& p);

// Returns K, the smallest power of two >= every extent the scene needs, or 0 when a
// coordinate is not finite (prepare() reports it).
[[nodiscard]] double position_scale(const Scene& scene);

// Returns the largest power of two K with a viewport [-K, K] that a device allows: 2K <=
// max_dim (the maximum viewport dimension) and [-K, K] inside [-bound, bound] (the viewport
// bounds range).
[[nodiscard]] double max_position_scale(double max_dim, double bound);

// The adapter-specific parts of unsupported() (DRIVER.*.SUPPORT).
struct SupportChecks {
  // Why only the standard sample pattern is supported, e.g. "Vulkan standard sample locations
  // only".
  std::string_view pattern_note;
  // What follows "N samples not supported by " when the sample count is not in info.sample_counts.
  std::string count_by;
  // Names the limit on K in the message, e.g. "device limit".
  std::string_view k_limit;
  // Optional: a check of the multisample state, after the sample count.
  std::function<std::string(const MultisampleState&)> msaa;
  // Checks each line or line strip primitive (required).
  std::function<std::string(const Scene&, const Primitive&)> line;
  // Optional: the adapter draws scenes with pipeline state (DRIVER.VALUES); returns why it
  // cannot draw this one, or "". Without it such scenes are refused.
  std::function<std::string(const Scene&)> pipeline;
};

// Returns why an adapter with this info and largest K cannot draw the scene, or "": the
// pipeline state, the sample pattern, the sample count, the shading rate, the target size, each
// line, K and the coverage buffer's size (with one float per attribute beside each mask), in
// that order.
[[nodiscard]] std::string unsupported_scene(const Scene& scene, const DriverInfo& info,
                                            double max_k, const SupportChecks& checks);

// A scene's vertices, packed for one draw per primitive, and the coverage slot of each
// primitive's first segment.
struct PackedScene {
  std::vector<std::uint32_t> first_slot; // per scene primitive
  std::vector<float> vertices;           // x, y of every vertex, float32 exactly as read
  std::uint32_t slots = 0;               // coverage slots in all
};
[[nodiscard]] PackedScene pack_scene(const Scene& scene);

// Decodes a coverage buffer of packed.slots planes of w * h sample masks into the sorted
// fragments: the masks are cut to the scene's samples, a strip's fragments get their segment.
[[nodiscard]] std::vector<Fragment> decode_coverage(const Scene& scene, const PackedScene& packed,
                                                    const std::uint32_t* coverage, std::uint32_t w,
                                                    std::uint32_t h);

// A pipeline scene's vertices (DRIVER.VALUES), packed for one draw per primitive: per vertex
// the position (clip space after the scene's transform, PIPE.TRANSFORM.FLOAT32, computed as the
// reference computes it; or window x, y, z and w = 1) and one float per declared attribute.
struct PackedPipeline {
  std::vector<std::uint32_t> first_slot; // per scene primitive
  std::vector<bool> window_space;        // per scene primitive: v given, not pos
  // Per scene primitive: a line strip with a vertex outside the clip volume, whose segments
  // are clipped parts (PIPE.CLIP.LINE: part = segment index, no seg).
  std::vector<bool> clipped_strip;
  std::vector<float> vertices;
  std::uint32_t stride = 4; // floats per vertex: 4 + attributes
  std::uint32_t slots = 0;
};
[[nodiscard]] PackedPipeline pack_pipeline(const Scene& scene);

// Returns why a GPU adapter cannot report the values of a pipeline scene, or "": window-space w
// other than 1 (w cannot reach the driver without a product that rounds) and window-space z
// outside the viewport's depth range (the driver would clip what the reference clamps). The
// adapters add their own checks.
// rule: DRIVER.OPENGL.VALUES, DRIVER.LAVAPIPE.VALUES
[[nodiscard]] std::string values_problem(const Scene& scene);

// Returns the clip-space position of p under the scene's transform (PIPE.TRANSFORM.FLOAT32:
// model, then view, then projection, as the reference applies them).
[[nodiscard]] pipe::Vec4f clip_position(const Scene& scene, pipe::Vec4f p);

// Returns the scene's viewport, or the default one (the whole target, depth [0, 1]).
[[nodiscard]] pipe::Viewport viewport_of(const Scene& scene);

// Decodes a pipeline draw: per slot plane of w * h sample masks (coverage) and of w * h *
// attributes floats (values), the fragments with their attributes and, when depth holds a
// plane per slot (w * h * depth_samples entries, sample q of pixel p at p * depth_samples + q),
// the stored depth of each covered sample (none for a fragment with a sample the plane lacks).
// per_sample 0: one values entry per pixel; else (sample-rate shading, MSAA.SHADING.SAMPLE)
// per_sample entries per pixel, and one fragment per covered sample (`sample` k, mask 1 << k) with
// entry k. Sorted with sort_drawing().
// rule: DRIVER.VALUES
[[nodiscard]] Drawing decode_values(
    const Scene& scene, const PackedPipeline& packed, const std::uint32_t* coverage,
    const float* values, const std::vector<std::vector<std::optional<pipe::DepthValue>>>* depth,
    std::uint32_t w, std::uint32_t h, std::uint32_t per_sample, std::uint32_t depth_samples);

// The base of the GPU adapters: not copyable, its info and largest K filled in by the adapter
// when it opens, unsupported() from unsupported_scene() with the adapter's own checks, and
// draw(), which rejects unsupported and invalid scenes, answers empty targets and scenes
// without drawing, and hands the rest, packed, to the adapter's draw_packed().
class GpuDriver : public Driver {
public:
  GpuDriver() = default;
  GpuDriver(const GpuDriver&) = delete;
  GpuDriver& operator=(const GpuDriver&) = delete;

  [[nodiscard]] const DriverInfo& info() const override { return info_; }

  [[nodiscard]] std::string unsupported(const Scene& scene) const override {
    return unsupported_scene(scene, info_, max_k_, support_checks());
  }

  // A scene with pipeline state is drawn by draw_values() and reported without its values.
  [[nodiscard]] DrawResult draw(const Scene& scene) final;

  // rule: DRIVER.VALUES
  // A scene without pipeline state: draw()'s fragments. Otherwise (only when the adapter's
  // support_checks() has a pipeline check) rejects unsupported and invalid scenes (pipe::
  // validate), answers empty targets and scenes, and hands the rest to draw_pipeline().
  [[nodiscard]] ValuesResult draw_values(const Scene& scene) final;

protected:
  // Draws a supported, valid pipeline scene with a w x h target and at least one primitive
  // (DRIVER.VALUES). The default refuses: only adapters with a pipeline check draw them.
  [[nodiscard]] virtual ValuesResult draw_pipeline(const Scene& scene, std::uint32_t w,
                                                   std::uint32_t h);

  // The adapter's part of unsupported() (DRIVER.*.SUPPORT).
  [[nodiscard]] virtual SupportChecks support_checks() const = 0;

  // Draws a supported, valid scene with a w x h target (both > 0) and at least one primitive:
  // one draw per primitive of packed, returning decode_coverage() of the coverage buffer.
  [[nodiscard]] virtual DrawResult draw_packed(const Scene& scene, const PackedScene& packed,
                                               std::uint32_t w, std::uint32_t h) = 0;

  DriverInfo info_;
  double max_k_ = 1.0; // the largest K the device allows (max_position_scale)
};

// Opens a GPU adapter that takes no argument: T() then T::init() (returns "" or the reason).
template <class T>
std::unique_ptr<Driver> open_gpu_driver(std::string_view name, std::string_view arg,
                                        std::string* error) {
  if (!arg.empty()) {
    *error = "driver '" + std::string(name) + "' takes no argument";
    return nullptr;
  }
  auto d = std::make_unique<T>();
  if (std::string why = d->init(); !why.empty()) {
    *error = why;
    return nullptr;
  }
  return d;
}

} // namespace rastrules::driver::detail

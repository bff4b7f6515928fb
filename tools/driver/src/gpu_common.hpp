// SPDX-License-Identifier: MIT
// Private to the driver library: what the GPU adapters (lavapipe.cpp, opengl.cpp) share. Both
// observe coverage the same way (DRIVER.LAVAPIPE.* / DRIVER.OPENGL.*): one draw per scene
// primitive with its float32 vertices as read, a viewport [-K, K] with K a power of two, and a
// storage buffer of one 32-bit sample mask per pixel and coverage slot (one slot per primitive,
// one per segment of a line strip) that the fragment shader ORs gl_SampleMaskIn into. This
// header holds the API-independent parts of that scheme; what differs (the API calls, the
// support rules of each API) stays in each adapter.
// Implements: DRIVER.LAVAPIPE.COVERAGE, DRIVER.LAVAPIPE.POSITION, DRIVER.LAVAPIPE.SUPPORT,
//             DRIVER.OPENGL.COVERAGE, DRIVER.OPENGL.POSITION, DRIVER.OPENGL.SUPPORT

#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "rastrules/driver/driver.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::driver::detail {

// The largest coverage buffer one draw may use (slots * width * height * 4 bytes).
inline constexpr std::uint64_t kMaxCoverageBytes = std::uint64_t{256} << 20;

[[nodiscard]] bool is_line(PrimitiveType t);

// The number of coverage slots of a primitive: one, or one per segment of a strip.
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
};

// Returns why an adapter with this info and largest K cannot draw the scene, or "": the
// sample pattern, the sample count, the shading rate, the target size, each line, K and the
// coverage buffer's size, in that order.
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

  [[nodiscard]] DrawResult draw(const Scene& scene) final;

protected:
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

// SPDX-License-Identifier: MIT
// How long lavapipe takes to draw a coverage-only scene (BENCH.LAVAPIPE): the scene's triangles
// in one draw into a single-sample target without attachments, a fragment shader that writes
// nothing, a precise occlusion query counting the covered samples. The vertices go through the
// adapter's exact position transform (DRIVER.LAVAPIPE.POSITION: float32 positions as read, a
// viewport [-K, K] with K a power of two, coverage.vert), so lavapipe sees the positions the
// reference sees. Everything is created and the vertices uploaded before the clock starts; the
// command buffer is recorded once and submitted for one warm-up and `repeats` timed draws, each
// timed from vkQueueSubmit to the fence with std::chrono::steady_clock.
// Implements: BENCH.LAVAPIPE

#include <vulkan/vulkan.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <exception>
#include <string>
#include <variant>
#include <vector>

#include "gpu_common.hpp"
#include "rastrules/driver/timing.hpp"
#include "rastrules/driver/timing_frag.spv.h"
#include "vulkan_common.hpp"

namespace rastrules::driver {
namespace {

using detail::vk_failed;

// The push constants of coverage.vert (only inv_k is read by this mode).
using Push = detail::CoveragePush;

// Why the scene cannot be timed as BENCH.LAVAPIPE defines it, or "".
std::string untimeable(const Scene& scene, int repeats) {
  if (repeats < 1)
    return "repeats must be at least 1, got " + std::to_string(repeats);
  const auto prepared = prepare(scene);
  if (const auto* e = std::get_if<SceneError>(&prepared))
    return "invalid scene: " + e->what();
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    if (scene.primitives[i].type != PrimitiveType::kTriangle) {
      return "primitives[" + std::to_string(i) + "] is a " +
             std::string(to_string(scene.primitives[i].type)) +
             ": the coverage timing draws triangles only";
    }
  }
  const MultisampleState& ms = scene.msaa;
  if (ms.count() != 1 || !(ms.pattern.positions[0] == SampleOffset{}) ||
      ms.effective_mask() != 1U) {
    return std::to_string(ms.count()) +
           " sample(s) off the pixel centre or masked: the coverage timing is single-sample only";
  }
  if (scene.conventions.fill != FillConvention::kTopLeft) {
    return "fill convention " + std::string(to_string(scene.conventions.fill)) +
           ": lavapipe draws with the top-left rule only";
  }
  return {};
}

// Every Vulkan object of one timing, destroyed in reverse order.
class Timer {
public:
  Timer() = default;
  Timer(const Timer&) = delete;
  Timer& operator=(const Timer&) = delete;
  ~Timer() {
    if (const VkDevice device = vk_.device; device != VK_NULL_HANDLE) {
      vkDeviceWaitIdle(device);
      if (pipeline_ != VK_NULL_HANDLE)
        vkDestroyPipeline(device, pipeline_, nullptr);
      program_.destroy(device);
      if (queries_ != VK_NULL_HANDLE)
        vkDestroyQueryPool(device, queries_, nullptr);
      detail::free_host_buffer(device, &vertices_);
    }
    vk_.destroy();
  }

  // rule: BENCH.LAVAPIPE, DRIVER.LAVAPIPE.DEVICE
  CoverageTiming run(const Scene& scene, int repeats) {
    CoverageTiming t;
    t.repeats = repeats;
    if (std::string why = vk_.open(); !why.empty())
      return unavailable(t, why);
    t.device = detail::device_description(vk_.physical, vk_.props);
    if (std::string why = check_limits(scene); !why.empty())
      return unavailable(t, why);
    if (std::string why = create_device(); !why.empty())
      return unavailable(t, why);
    if (std::string why = create_pipeline(scene); !why.empty())
      return unavailable(t, why);
    if (std::string why = upload(scene); !why.empty())
      return unavailable(t, why);
    if (std::string why = record(); !why.empty())
      return unavailable(t, why);

    std::vector<double> seconds;
    std::uint64_t first_count = 0;
    for (int i = 0; i <= repeats; ++i) { // draw 0 is the warm-up
      double s = 0.0;
      std::uint64_t count = 0;
      if (std::string why = draw(&s, &count); !why.empty())
        return unavailable(t, why);
      if (i == 0) {
        first_count = count;
        continue;
      }
      if (count != first_count) {
        return unavailable(t, "lavapipe: the occlusion query counted " + std::to_string(count) +
                                  " samples in draw " + std::to_string(i) + " and " +
                                  std::to_string(first_count) + " in the warm-up draw");
      }
      seconds.push_back(s);
    }
    std::sort(seconds.begin(), seconds.end());
    const std::size_t n = seconds.size();
    t.seconds_min = seconds.front();
    t.seconds_median = n % 2 == 1 ? seconds[n / 2] : (seconds[n / 2 - 1] + seconds[n / 2]) / 2.0;
    t.samples_passed = first_count;
    t.available = true;
    t.includes = "queue submit to fence of one draw of " + std::to_string(scene.primitives.size()) +
                 " triangles: lavapipe's whole pipeline (vertex shading, clipping, setup, binning, "
                 "rasterization, an empty fragment shader, the occlusion query); not instance, "
                 "device, pipeline or buffer creation, the vertex upload or command recording";
    return t;
  }

private:
  static CoverageTiming unavailable(CoverageTiming t, const std::string& why) {
    t.available = false;
    t.why_not = why;
    t.seconds_median = t.seconds_min = 0.0;
    t.samples_passed = 0;
    return t;
  }

  // rule: DRIVER.LAVAPIPE.POSITION
  std::string check_limits(const Scene& scene) {
    const VkPhysicalDeviceLimits& lim = vk_.props.limits;
    k_ = detail::position_scale(scene);
    const double max_k = detail::max_position_scale(lim);
    if (k_ > max_k) {
      return "coordinates need a viewport of side " + std::to_string(2.0 * k_) +
             " (device limit: K <= " + std::to_string(max_k) + ")";
    }
    if (static_cast<std::uint32_t>(scene.width) > lim.maxFramebufferWidth ||
        static_cast<std::uint32_t>(scene.height) > lim.maxFramebufferHeight) {
      return "target " + std::to_string(scene.width) + "x" + std::to_string(scene.height) +
             " larger than the device's framebuffer limit";
    }
    return {};
  }

  std::string create_device() {
    VkPhysicalDeviceFeatures have{};
    vkGetPhysicalDeviceFeatures(vk_.physical, &have);
    if (have.occlusionQueryPrecise != VK_TRUE) {
      return "lavapipe: device lacks occlusionQueryPrecise (needed to count covered samples)";
    }
    VkPhysicalDeviceFeatures2 features{};
    features.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
    features.features.occlusionQueryPrecise = VK_TRUE;
    if (std::string why = vk_.create_device(features, 0, nullptr, 0); !why.empty())
      return why;
    VkQueryPoolCreateInfo qpi{};
    qpi.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
    qpi.queryType = VK_QUERY_TYPE_OCCLUSION;
    qpi.queryCount = 1;
    if (VkResult r = vkCreateQueryPool(vk_.device, &qpi, nullptr, &queries_); r != VK_SUCCESS) {
      return vk_failed("vkCreateQueryPool", r);
    }
    return {};
  }

  // A render pass and framebuffer without attachments (the sample count is the pipeline's),
  // coverage.vert and the empty timing.frag, triangles with the scene's culling, one sample.
  std::string create_pipeline(const Scene& scene) {
    if (std::string why = program_.create(vk_.device, kTiming_frag, sizeof(kTiming_frag),
                                          VK_SHADER_STAGE_VERTEX_BIT, VK_NULL_HANDLE);
        !why.empty()) {
      return why;
    }
    if (std::string why =
            program_.ensure_framebuffer(vk_.device, static_cast<std::uint32_t>(scene.width),
                                        static_cast<std::uint32_t>(scene.height));
        !why.empty()) {
      return why;
    }
    // The scene's culling, as the adapter maps it (both y-down: the winding maps directly).
    detail::CoveragePipelineState state;
    state.cull = detail::vk_cull_mode(scene.cull);
    state.front = detail::vk_front_face(scene.conventions.front_face);
    return program_.create_pipeline(vk_.device, state, &pipeline_);
  }

  // The float32 positions exactly as read, uploaded once (the adapter's packing).
  std::string upload(const Scene& scene) {
    const detail::PackedScene packed = detail::pack_scene(scene);
    vertex_count_ = static_cast<std::uint32_t>(packed.vertices.size() / 2);
    return vk_.upload_vertices(packed.vertices, &vertices_);
  }

  // rule: DRIVER.LAVAPIPE.POSITION, BENCH.LAVAPIPE
  std::string record() {
    const VkCommandBuffer cmd = vk_.cmd;
    if (std::string why = detail::begin_commands(cmd, 0); !why.empty())
      return why;
    vkCmdResetQueryPool(cmd, queries_, 0, 1);
    program_.begin_pass(cmd, vertices_.buffer, k_);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
    program_.push(cmd, Push{static_cast<float>(1.0 / k_), 0, program_.width, program_.height, 1});
    vkCmdBeginQuery(cmd, queries_, 0, VK_QUERY_CONTROL_PRECISE_BIT);
    if (vertex_count_ > 0)
      vkCmdDraw(cmd, vertex_count_, 1, 0, 0);
    vkCmdEndQuery(cmd, queries_, 0);
    vkCmdEndRenderPass(cmd);
    if (VkResult r = vkEndCommandBuffer(cmd); r != VK_SUCCESS) {
      return vk_failed("vkEndCommandBuffer", r);
    }
    return {};
  }

  // Submits the recorded draw, waits for its fence and reads the query.
  // rule: BENCH.LAVAPIPE
  std::string draw(double* seconds, std::uint64_t* count) {
    const auto start = std::chrono::steady_clock::now();
    const std::string why = vk_.submit_and_wait();
    const auto stop = std::chrono::steady_clock::now();
    if (!why.empty())
      return why;
    *seconds = std::chrono::duration<double>(stop - start).count();
    std::uint64_t result = 0;
    if (VkResult r = vkGetQueryPoolResults(vk_.device, queries_, 0, 1, sizeof(result), &result,
                                           sizeof(result),
                                           VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT);
        r != VK_SUCCESS) {
      return vk_failed("vkGetQueryPoolResults", r);
    }
    *count = result;
    return {};
  }

  detail::LavapipeContext vk_;
  VkQueryPool queries_ = VK_NULL_HANDLE;
  detail::CoverageProgram program_;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  detail::HostBuffer vertices_;
  std::uint32_t vertex_count_ = 0;
  double k_ = 1.0;
};

} // namespace

// rule: BENCH.LAVAPIPE
CoverageTiming time_lavapipe_coverage(const Scene& scene, int repeats) {
  CoverageTiming t;
  t.repeats = repeats;
  try {
    if (std::string why = untimeable(scene, repeats); !why.empty()) {
      t.why_not = why;
      return t;
    }
    Timer timer;
    return timer.run(scene, repeats);
  } catch (const std::exception& e) {
    t.why_not = std::string("lavapipe coverage timing failed: ") + e.what();
  } catch (...) {
    t.why_not = "lavapipe coverage timing failed (unknown exception)";
  }
  t.available = false;
  return t;
}

} // namespace rastrules::driver

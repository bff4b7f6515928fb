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
#include <cstring>
#include <exception>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include "gpu_common.hpp"
#include "rastrules/driver/coverage_vert.spv.h"
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
  if (repeats < 1) return "repeats must be at least 1, got " + std::to_string(repeats);
  const auto prepared = prepare(scene);
  if (const auto* e = std::get_if<SceneError>(&prepared)) return "invalid scene: " + e->what();
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    if (scene.primitives[i].type != PrimitiveType::kTriangle) {
      return "primitives[" + std::to_string(i) + "] is a " +
             std::string(to_string(scene.primitives[i].type)) +
             ": the coverage timing draws triangles only";
    }
  }
  const MultisampleState& ms = scene.msaa;
  if (ms.count() != 1 || !(ms.pattern.positions[0] == SampleOffset{}) || ms.effective_mask() != 1U) {
    return std::to_string(ms.count()) +
           " sample(s) off the pixel centre or masked: the coverage timing is single-sample only";
  }
  if (scene.state.fill != FillConvention::kTopLeft) {
    return "fill convention " + std::string(to_string(scene.state.fill)) +
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
    if (device_ != VK_NULL_HANDLE) {
      vkDeviceWaitIdle(device_);
      if (pipeline_ != VK_NULL_HANDLE) vkDestroyPipeline(device_, pipeline_, nullptr);
      if (framebuffer_ != VK_NULL_HANDLE) vkDestroyFramebuffer(device_, framebuffer_, nullptr);
      if (render_pass_ != VK_NULL_HANDLE) vkDestroyRenderPass(device_, render_pass_, nullptr);
      if (vert_ != VK_NULL_HANDLE) vkDestroyShaderModule(device_, vert_, nullptr);
      if (frag_ != VK_NULL_HANDLE) vkDestroyShaderModule(device_, frag_, nullptr);
      if (layout_ != VK_NULL_HANDLE) vkDestroyPipelineLayout(device_, layout_, nullptr);
      if (queries_ != VK_NULL_HANDLE) vkDestroyQueryPool(device_, queries_, nullptr);
      if (fence_ != VK_NULL_HANDLE) vkDestroyFence(device_, fence_, nullptr);
      if (pool_ != VK_NULL_HANDLE) vkDestroyCommandPool(device_, pool_, nullptr);
      detail::free_host_buffer(device_, &vertices_);
      vkDestroyDevice(device_, nullptr);
    }
    if (instance_ != VK_NULL_HANDLE) vkDestroyInstance(instance_, nullptr);
  }

  // rule: BENCH.LAVAPIPE, DRIVER.LAVAPIPE.DEVICE
  CoverageTiming run(const Scene& scene, int repeats) {
    CoverageTiming t;
    t.repeats = repeats;
    if (std::string why = detail::open_lavapipe_instance(&instance_, &physical_, &props_); !why.empty()) {
      return unavailable(t, why);
    }
    t.device = detail::device_description(physical_, props_);
    if (std::string why = check_limits(scene); !why.empty()) return unavailable(t, why);
    if (std::string why = create_device(); !why.empty()) return unavailable(t, why);
    if (std::string why = create_pipeline(scene); !why.empty()) return unavailable(t, why);
    if (std::string why = upload(scene); !why.empty()) return unavailable(t, why);
    if (std::string why = record(scene); !why.empty()) return unavailable(t, why);

    std::vector<double> seconds;
    std::uint64_t first_count = 0;
    for (int i = 0; i <= repeats; ++i) {  // draw 0 is the warm-up
      double s = 0.0;
      std::uint64_t count = 0;
      if (std::string why = draw(&s, &count); !why.empty()) return unavailable(t, why);
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
    const VkPhysicalDeviceLimits& lim = props_.limits;
    const double max_dim = std::min(lim.maxViewportDimensions[0], lim.maxViewportDimensions[1]);
    const double bound = std::min(-static_cast<double>(lim.viewportBoundsRange[0]),
                                  static_cast<double>(lim.viewportBoundsRange[1]));
    k_ = detail::position_scale(scene);
    const double max_k = detail::max_position_scale(max_dim, bound);
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
    vkGetPhysicalDeviceFeatures(physical_, &have);
    if (have.occlusionQueryPrecise != VK_TRUE) {
      return "lavapipe: device lacks occlusionQueryPrecise (needed to count covered samples)";
    }
    if (std::string why = detail::graphics_queue_family(physical_, &family_); !why.empty()) return why;
    VkPhysicalDeviceFeatures2 features{};
    features.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
    features.features.occlusionQueryPrecise = VK_TRUE;
    if (std::string why = detail::create_device(physical_, family_, features, 0, nullptr, &device_, &queue_);
        !why.empty()) {
      return why;
    }
    if (std::string why = detail::create_submit_objects(device_, family_, 0, &pool_, &cmd_, &fence_);
        !why.empty()) {
      return why;
    }
    VkQueryPoolCreateInfo qpi{};
    qpi.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
    qpi.queryType = VK_QUERY_TYPE_OCCLUSION;
    qpi.queryCount = 1;
    if (VkResult r = vkCreateQueryPool(device_, &qpi, nullptr, &queries_); r != VK_SUCCESS) {
      return vk_failed("vkCreateQueryPool", r);
    }
    return {};
  }

  // A render pass and framebuffer without attachments (the sample count is the pipeline's),
  // coverage.vert and the empty timing.frag, triangles with the scene's culling, one sample.
  std::string create_pipeline(const Scene& scene) {
    for (auto [code, bytes, module] : {std::tuple{kCoverage_vert, sizeof(kCoverage_vert), &vert_},
                                       std::tuple{kTiming_frag, sizeof(kTiming_frag), &frag_}}) {
      if (std::string why = detail::create_shader_module(device_, code, bytes, module); !why.empty()) {
        return why;
      }
    }
    VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(Push)};
    VkPipelineLayoutCreateInfo lci{};
    lci.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    lci.pushConstantRangeCount = 1;
    lci.pPushConstantRanges = &range;
    if (VkResult r = vkCreatePipelineLayout(device_, &lci, nullptr, &layout_); r != VK_SUCCESS) {
      return vk_failed("vkCreatePipelineLayout", r);
    }
    if (std::string why = detail::create_attachmentless_render_pass(device_, &render_pass_);
        !why.empty()) {
      return why;
    }
    VkFramebufferCreateInfo fci{};
    fci.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
    fci.renderPass = render_pass_;
    fci.width = static_cast<std::uint32_t>(scene.width);
    fci.height = static_cast<std::uint32_t>(scene.height);
    fci.layers = 1;
    if (VkResult r = vkCreateFramebuffer(device_, &fci, nullptr, &framebuffer_); r != VK_SUCCESS) {
      return vk_failed("vkCreateFramebuffer", r);
    }
    // The scene's culling, as the adapter maps it (both y-down: the winding maps directly).
    detail::CoveragePipelineState state;
    state.cull = detail::vk_cull_mode(scene.state.cull);
    state.front = detail::vk_front_face(scene.state.front_face);
    if (std::string why = detail::create_coverage_pipeline(device_, vert_, frag_, layout_, render_pass_,
                                                           state, &pipeline_);
        !why.empty()) {
      return why;
    }
    return {};
  }

  // The float32 positions exactly as read, uploaded once (the adapter's packing).
  std::string upload(const Scene& scene) {
    const detail::PackedScene packed = detail::pack_scene(scene);
    vertex_count_ = static_cast<std::uint32_t>(packed.vertices.size() / 2);
    const VkDeviceSize bytes = std::max<VkDeviceSize>(packed.vertices.size() * sizeof(float), 8);
    if (std::string why = detail::create_host_buffer(device_, memory(), bytes,
                                                     VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, &vertices_);
        !why.empty()) {
      return why;
    }
    if (!packed.vertices.empty()) {
      std::memcpy(vertices_.mapped, packed.vertices.data(), packed.vertices.size() * sizeof(float));
    }
    return {};
  }

  VkPhysicalDeviceMemoryProperties memory() const {
    VkPhysicalDeviceMemoryProperties m{};
    vkGetPhysicalDeviceMemoryProperties(physical_, &m);
    return m;
  }

  // rule: DRIVER.LAVAPIPE.POSITION, BENCH.LAVAPIPE
  std::string record(const Scene& scene) {
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    if (VkResult r = vkBeginCommandBuffer(cmd_, &begin); r != VK_SUCCESS) {
      return vk_failed("vkBeginCommandBuffer", r);
    }
    const auto w = static_cast<std::uint32_t>(scene.width);
    const auto h = static_cast<std::uint32_t>(scene.height);
    vkCmdResetQueryPool(cmd_, queries_, 0, 1);
    detail::begin_target_pass(cmd_, render_pass_, framebuffer_, w, h, k_);
    vkCmdBindPipeline(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
    const VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd_, 0, 1, &vertices_.buffer, &zero);
    const Push push{static_cast<float>(1.0 / k_), 0, w, h, 1};
    vkCmdPushConstants(cmd_, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(Push), &push);
    vkCmdBeginQuery(cmd_, queries_, 0, VK_QUERY_CONTROL_PRECISE_BIT);
    if (vertex_count_ > 0) vkCmdDraw(cmd_, vertex_count_, 1, 0, 0);
    vkCmdEndQuery(cmd_, queries_, 0);
    vkCmdEndRenderPass(cmd_);
    if (VkResult r = vkEndCommandBuffer(cmd_); r != VK_SUCCESS) return vk_failed("vkEndCommandBuffer", r);
    return {};
  }

  // Submits the recorded draw, waits for its fence and reads the query.
  // rule: BENCH.LAVAPIPE
  std::string draw(double* seconds, std::uint64_t* count) {
    const auto start = std::chrono::steady_clock::now();
    const std::string why = detail::submit_and_wait(device_, queue_, cmd_, fence_);
    const auto stop = std::chrono::steady_clock::now();
    if (!why.empty()) return why;
    *seconds = std::chrono::duration<double>(stop - start).count();
    std::uint64_t result = 0;
    if (VkResult r = vkGetQueryPoolResults(device_, queries_, 0, 1, sizeof(result), &result, sizeof(result),
                                           VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT);
        r != VK_SUCCESS) {
      return vk_failed("vkGetQueryPoolResults", r);
    }
    *count = result;
    return {};
  }

  VkInstance instance_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties props_{};
  std::uint32_t family_ = 0;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  VkQueryPool queries_ = VK_NULL_HANDLE;
  VkShaderModule vert_ = VK_NULL_HANDLE;
  VkShaderModule frag_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkRenderPass render_pass_ = VK_NULL_HANDLE;
  VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  detail::HostBuffer vertices_;
  std::uint32_t vertex_count_ = 0;
  double k_ = 1.0;
};

}  // namespace

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

}  // namespace rastrules::driver

// SPDX-License-Identifier: MIT
// The lavapipe adapter: draws a scene with Mesa's Vulkan CPU driver (llvmpipe), headless, and
// reads back per-primitive, per-sample coverage from a storage buffer that the fragment
// shader ORs gl_SampleMaskIn into (integer multisampled attachments are not needed).
// Implements: DRIVER.LAVAPIPE.DEVICE, DRIVER.LAVAPIPE.COVERAGE, DRIVER.LAVAPIPE.POSITION,
//             DRIVER.LAVAPIPE.SUPPORT

#include <vulkan/vulkan.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <variant>
#include <vector>

#include "drivers.hpp"
#include "gpu_common.hpp"
#include "rastrules/driver/coverage_frag.spv.h"
#include "rastrules/driver/depth_copy_comp.spv.h"
#include "rastrules/driver/timing_frag.spv.h"
#include "rastrules/driver/values_frag.spv.h"
#include "rastrules/driver/values_sample_frag.spv.h"
#include "rastrules/driver/values_vert.spv.h"
#include "rastrules/scene.hpp"
#include "vulkan_common.hpp"

namespace rastrules::driver {
namespace {

using detail::free_host_buffer;
using detail::HostBuffer;
using detail::vk_failed;

using Push = detail::CoveragePush;

// The push constants of shaders/values.{vert,frag} (DRIVER.LAVAPIPE.VALUES).
struct ValuesPush {
  float inv_k = 1.0F;
  std::uint32_t slot = 0;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint32_t slots = 0;
  std::uint32_t window_space = 0;
  std::uint32_t count = 0;
  std::array<std::uint32_t, 2> kinds{}; // 4 bits per attribute, values.frag's numbering
  std::uint32_t per_sample = 1;         // values entries per pixel (sample-rate shading: count)
};

// values.frag's input for an attribute declaration.
std::uint32_t kind_of(const pipe::AttributeDecl& a) {
  const bool centroid = a.location == pipe::Location::kCentroid;
  const bool sample = a.location == pipe::Location::kSample;
  switch (a.interpolation) {
  case pipe::Interpolation::kPerspective:
    return sample ? 5U : (centroid ? 3U : 0U);
  case pipe::Interpolation::kLinear:
    return sample ? 6U : (centroid ? 4U : 1U);
  case pipe::Interpolation::kFlat:
    break;
  }
  return 2U;
}

// The depth attachment format of a depth format, and the bytes of one texel in a copy.
VkFormat vk_depth_format(pipe::DepthFormat f, bool x8_d24) {
  switch (f) {
  case pipe::DepthFormat::kD16:
    return VK_FORMAT_D16_UNORM;
  case pipe::DepthFormat::kD24:
    return x8_d24 ? VK_FORMAT_X8_D24_UNORM_PACK32 : VK_FORMAT_D24_UNORM_S8_UINT;
  case pipe::DepthFormat::kD32F:
    break;
  }
  return VK_FORMAT_D32_SFLOAT;
}

// Everything that selects a pipeline (DRIVER.LAVAPIPE.SUPPORT).
using PipelineKey = detail::CoveragePipelineState;

class LavapipeDriver final : public detail::GpuDriver {
public:
  ~LavapipeDriver() override { destroy(); }

  // Creates the instance, selects the CPU device and creates everything draws share.
  // Returns an empty string on success, else the reason.
  // rule: DRIVER.LAVAPIPE.DEVICE
  std::string init() {
    if (std::string why = vk_.open(); !why.empty())
      return why;
    if (std::string why = check_features(); !why.empty())
      return why;
    if (std::string why = create_device(); !why.empty())
      return why;
    return create_shared();
  }

  // rule: DRIVER.LAVAPIPE.SUPPORT
  [[nodiscard]] detail::SupportChecks support_checks() const override {
    detail::SupportChecks checks;
    checks.pattern_note = "Vulkan standard sample locations only";
    checks.count_by = vk_.props.deviceName;
    checks.k_limit = "device limit";
    checks.line = [this](const Scene& s, const Primitive& p) -> std::string {
      if (p.aa)
        return "antialiased lines not supported";
      switch (s.conventions.line_mode) {
      case LineMode::kD3DDiamond:
        return "line mode 'd3d' (diamond exit) has no Vulkan equivalent";
      case LineMode::kQuadWide:
        return "line mode 'quad-wide' (1.4 px) not supported (Vulkan rectangular lines are 1.0 px "
               "wide here)";
      case LineMode::kVulkanBresenham:
        if (!info_.lines_bresenham)
          return "Bresenham lines not supported by the device";
        break;
      case LineMode::kQuadNarrow:
        if (!info_.lines_rectangular)
          return "rectangular lines not supported by the device";
        break;
      }
      return {};
    };
    // rule: DRIVER.LAVAPIPE.VALUES
    checks.pipeline = [this](const Scene& s) -> std::string {
      if (std::string why = detail::values_problem(s); !why.empty())
        return why;
      if (s.conventions.provoking == pipe::Provoking::kLast && !provoking_last_)
        return "provoking vertex 'last' not supported by the device (VK_EXT_provoking_vertex)";
      if (s.depth && !s.depth->clip && !depth_clamp_)
        return "depth clipping off not supported by the device (depthClamp)";
      if (s.msaa.shading == ShadingRate::kSample && !sample_rate_shading_)
        return "sample-rate shading not supported by the device (sampleRateShading)";
      if (s.depth && s.depth->bias.clamp != 0.0f && !depth_bias_clamp_)
        return "a depth bias clamp not supported by the device (depthBiasClamp)";
      return {};
    };
    return checks;
  }

  // rule: DRIVER.LAVAPIPE.COVERAGE, DRIVER.LAVAPIPE.POSITION
  [[nodiscard]] DrawResult draw_packed(const Scene& scene, const detail::PackedScene& packed,
                                       std::uint32_t w, std::uint32_t h) override {
    const std::vector<float>& vertices = packed.vertices;
    const std::uint32_t slots = packed.slots;
    const VkDeviceSize cov_bytes = std::max<VkDeviceSize>(VkDeviceSize{slots} * w * h * 4U, 4U);
    if (std::string why = detail::ensure_host_buffer(
            vk_.device, vk_.memory, cov_bytes,
            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, &coverage_);
        !why.empty()) {
      return DriverError{why};
    }
    // ensure_host_buffer reallocates exactly when the size grows: rebind then, whatever the
    // handle.
    if (coverage_.size != bound_size_) {
      bind_coverage();
      bound_size_ = coverage_.size;
    }
    if (std::string why = vk_.upload_vertices(vertices, &vertex_); !why.empty()) {
      return DriverError{why};
    }
    if (std::string why = program_.ensure_framebuffer(vk_.device, w, h); !why.empty()) {
      return DriverError{why};
    }

    const double k = detail::position_scale(scene);
    const auto samples = static_cast<VkSampleCountFlagBits>(scene.msaa.count());
    const std::uint32_t mask = scene.msaa.effective_mask();

    // The command buffer is in the initial state: it is reset as soon as its submission
    // completes, before any buffer it used is replaced.
    const VkCommandBuffer cmd = vk_.cmd;
    if (std::string why = detail::begin_commands(cmd, VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT);
        !why.empty()) {
      return DriverError{why};
    }
    vkCmdFillBuffer(cmd, coverage_.buffer, 0, cov_bytes, 0);
    barrier(VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
            VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
            VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);

    // rule: DRIVER.LAVAPIPE.POSITION
    program_.begin_pass(cmd, vertex_.buffer, k);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, program_.layout, 0, 1, &set_, 0,
                            nullptr);

    VkPipeline bound = VK_NULL_HANDLE;
    std::uint32_t first_vertex = 0;
    for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
      const Primitive& p = scene.primitives[i];
      PipelineKey key = primitive_key(scene, p);
      key.samples = samples;
      key.sample_mask = mask;
      auto pipeline = get_pipeline(key);
      if (const auto* e = std::get_if<std::string>(&pipeline)) {
        vkCmdEndRenderPass(cmd);
        vkEndCommandBuffer(cmd);
        vkResetCommandBuffer(cmd, 0);
        return DriverError{*e};
      }
      const VkPipeline pl = std::get<VkPipeline>(pipeline);
      if (pl != bound) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pl);
        bound = pl;
      }
      program_.push(cmd, Push{static_cast<float>(1.0 / k), packed.first_slot[i], w, h, slots});
      const auto count = static_cast<std::uint32_t>(p.v.size());
      vkCmdDraw(cmd, count, 1, first_vertex, 0);
      first_vertex += count;
    }
    vkCmdEndRenderPass(cmd);
    barrier(VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
            VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
    if (std::string why = end_and_submit(); !why.empty())
      return DriverError{why};

    // rule: DRIVER.LAVAPIPE.COVERAGE
    return detail::decode_coverage(scene, packed,
                                   static_cast<const std::uint32_t*>(coverage_.mapped), w, h);
  }

  // rule: DRIVER.LAVAPIPE.VALUES
  [[nodiscard]] ValuesResult draw_pipeline(const Scene& scene, std::uint32_t w,
                                           std::uint32_t h) override {
    const detail::PackedPipeline packed = detail::pack_pipeline(scene);
    const std::size_t n = scene.attributes.size();
    const std::uint32_t slots = packed.slots;
    const VkDeviceSize plane = VkDeviceSize{w} * h;
    const VkDeviceSize cov_bytes = std::max<VkDeviceSize>(VkDeviceSize{slots} * plane * 4U, 4U);
    const std::uint32_t samples = scene.msaa.count();
    // rule: MSAA.SHADING.SAMPLE
    const bool per_sample = scene.msaa.shading == ShadingRate::kSample;
    const VkDeviceSize val_bytes =
        std::max<VkDeviceSize>(cov_bytes * n * (per_sample ? samples : 1U), 4U);
    // Several samples: D16 and D32F through the compute copy (exact), not D24.
    const bool depth = scene.depth.has_value() &&
                       (samples == 1 || scene.conventions.depth != pipe::DepthFormat::kD24);
    const VkDeviceSize depth_bytes =
        std::max<VkDeviceSize>(VkDeviceSize{slots} * 2U * plane * samples * 4U, 4U);
    for (const auto& [bytes, buffer] :
         {std::pair{cov_bytes, &coverage_}, std::pair{val_bytes, &values_}}) {
      if (std::string why = detail::ensure_host_buffer(
              vk_.device, vk_.memory, bytes,
              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, buffer);
          !why.empty()) {
        return DriverError{why};
      }
    }
    if (depth) {
      if (std::string why = detail::ensure_host_buffer(vk_.device, vk_.memory, depth_bytes,
                                                       VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                                       &depth_readback_);
          !why.empty()) {
        return DriverError{why};
      }
      if (std::string why = ensure_depth_target(w, h, scene.conventions.depth, samples);
          !why.empty()) {
        return DriverError{why};
      }
      if (samples > 1) {
        if (std::string why = ensure_depth_copy(); !why.empty())
          return DriverError{why};
      }
    }
    bind_values();
    bound_size_ = 0; // the coverage path rebinds its set before its next draw
    // The vertices with kValuesStride floats each: the position, then the attributes.
    std::vector<float> vertices;
    for (std::size_t v = 0; v * packed.stride < packed.vertices.size(); ++v) {
      const float* src = packed.vertices.data() + v * packed.stride;
      vertices.insert(vertices.end(), src, src + packed.stride);
      vertices.resize(vertices.size() + (detail::kValuesStride - packed.stride), 0.0F);
    }
    if (std::string why = vk_.upload_vertices(vertices, &values_vertex_); !why.empty())
      return DriverError{why};
    if (std::string why = program_.ensure_framebuffer(vk_.device, w, h); !why.empty())
      return DriverError{why};

    const double k = detail::position_scale(scene);
    const pipe::Viewport vp = detail::viewport_of(scene);
    const pipe::ScissorRect sc = pipe::viewport_scissor(vp);
    const std::int64_t x0 = std::clamp<std::int64_t>(sc.x0, 0, w);
    const std::int64_t y0 = std::clamp<std::int64_t>(sc.y0, 0, h);
    const VkRect2D scissor{
        {static_cast<std::int32_t>(x0), static_cast<std::int32_t>(y0)},
        {static_cast<std::uint32_t>(std::clamp<std::int64_t>(sc.x1, x0, w) - x0),
         static_cast<std::uint32_t>(std::clamp<std::int64_t>(sc.y1, y0, h) - y0)}};
    const DrawView view{k, vp, scissor};
    ValuesPush push;
    push.inv_k = static_cast<float>(1.0 / k);
    push.width = w;
    push.height = h;
    push.slots = slots;
    push.count = static_cast<std::uint32_t>(n);
    push.per_sample = per_sample ? samples : 1U;
    for (std::size_t j = 0; j < n; ++j)
      push.kinds[j / 8] |= kind_of(scene.attributes[j]) << (4U * (j % 8));

    const VkCommandBuffer cmd = vk_.cmd;
    if (std::string why = detail::begin_commands(cmd, VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT);
        !why.empty()) {
      return DriverError{why};
    }
    const auto fail = [&](std::string why) {
      vkEndCommandBuffer(cmd);
      vkResetCommandBuffer(cmd, 0);
      return DriverError{std::move(why)};
    };
    vkCmdFillBuffer(cmd, coverage_.buffer, 0, cov_bytes, 0);
    vkCmdFillBuffer(cmd, values_.buffer, 0, val_bytes, 0);
    barrier(VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
            VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
            VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    const VkDeviceSize zero = 0;

    // The values pass: every primitive once, coverage and attributes into the buffers.
    detail::begin_target_pass(cmd, program_.render_pass, program_.framebuffer, w, h, k);
    vkCmdBindVertexBuffers(cmd, 0, 1, &values_vertex_.buffer, &zero);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, values_layout_, 0, 1,
                            &values_set_, 0, nullptr);
    std::string failed;
    for_each_primitive(
        scene, packed,
        [&](std::size_t i, PipelineKey key, std::uint32_t first, std::uint32_t count) {
          key.samples = static_cast<VkSampleCountFlagBits>(samples);
          key.sample_mask = scene.msaa.effective_mask();
          key.sample_shading = per_sample;
          auto pipeline = get_values_pipeline(key, per_sample ? values_sample_frag_ : values_frag_,
                                              program_.render_pass);
          if (const auto* e = std::get_if<std::string>(&pipeline)) {
            failed = *e;
            return false;
          }
          record_draw(cmd, std::get<VkPipeline>(pipeline), packed.window_space[i], view,
                      packed.first_slot[i], first, count, push);
          return true;
        });
    vkCmdEndRenderPass(cmd);
    if (!failed.empty())
      return fail(failed);

    // rule: DRIVER.LAVAPIPE.VALUES, PIPE.DEPTH.FORMAT
    // The depth passes: each slot alone into the depth attachment of the scene's format,
    // cleared to 0 and then to 1, each result copied out: a pixel the slot covers holds the
    // same value both times.
    if (depth) {
      for_each_primitive(
          scene, packed,
          [&](std::size_t i, PipelineKey key, std::uint32_t first, std::uint32_t count) {
            key.samples = static_cast<VkSampleCountFlagBits>(samples);
            key.sample_mask = scene.msaa.effective_mask();
            key.depth_write = true;
            // rule: PIPE.DEPTH.BIAS
            // Triangles only, as in the reference (Vulkan biases polygons only).
            const pipe::DepthBias& bias = scene.depth->bias;
            key.depth_bias = key.topology == VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST && bias.enabled();
            const bool strip = key.topology == VK_PRIMITIVE_TOPOLOGY_LINE_STRIP;
            if (strip)
              key.topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST;
            auto pipeline = get_values_pipeline(key, empty_frag_, depth_pass_);
            if (const auto* e = std::get_if<std::string>(&pipeline)) {
              failed = *e;
              return false;
            }
            const std::uint32_t parts = strip ? count - 1 : 1;
            for (std::uint32_t s = 0; s < parts; ++s) {
              for (std::uint32_t pass = 0; pass < 2; ++pass) {
                VkClearValue clear{};
                clear.depthStencil = {static_cast<float>(pass), 0};
                VkRenderPassBeginInfo rpb{};
                rpb.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
                rpb.renderPass = depth_pass_;
                rpb.framebuffer = depth_framebuffer_;
                rpb.renderArea = {{0, 0}, {w, h}};
                rpb.clearValueCount = 1;
                rpb.pClearValues = &clear;
                vkCmdBeginRenderPass(cmd, &rpb, VK_SUBPASS_CONTENTS_INLINE);
                vkCmdBindVertexBuffers(cmd, 0, 1, &values_vertex_.buffer, &zero);
                vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, values_layout_, 0, 1,
                                        &values_set_, 0, nullptr);
                if (key.depth_bias)
                  vkCmdSetDepthBias(cmd, static_cast<float>(bias.bias), bias.clamp,
                                    bias.slope_scaled);
                record_draw(cmd, std::get<VkPipeline>(pipeline), packed.window_space[i], view,
                            packed.first_slot[i] + s, strip ? first + s : first, strip ? 2U : count,
                            push);
                vkCmdEndRenderPass(cmd);
                copy_depth_out(cmd, w, h, samples,
                               (VkDeviceSize{push.slot} * 2U + pass) * plane * samples);
              }
            }
            return true;
          });
      if (!failed.empty())
        return fail(failed);
    }
    barrier(VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT |
                VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
            VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
            VK_ACCESS_HOST_READ_BIT);
    if (std::string why = end_and_submit(); !why.empty())
      return DriverError{why};

    std::vector<std::vector<std::optional<pipe::DepthValue>>> depths;
    if (depth) {
      const auto* raw = static_cast<const std::uint8_t*>(depth_readback_.mapped);
      const pipe::DepthFormat f = scene.conventions.depth;
      // Entry k (pixel k / samples, sample k % samples) of a slot after pass 0 or 1, in the
      // format's unit: on several samples the compute copy's float (D16: k / 65535, recovered
      // by rounding; D32F: the stored float), else the copied texel.
      const VkDeviceSize entries = plane * samples;
      const auto texel = [&](std::uint32_t slot, std::uint32_t pass, VkDeviceSize k_) {
        const std::uint8_t* p = raw + ((VkDeviceSize{slot} * 2U + pass) * entries) * 4U;
        if (samples > 1) {
          float x = 0.0F;
          std::memcpy(&x, p + k_ * 4U, 4);
          return f == pipe::DepthFormat::kD16
                     ? static_cast<std::uint32_t>(std::lround(static_cast<double>(x) * 65535.0))
                     : std::bit_cast<std::uint32_t>(x);
        }
        if (f == pipe::DepthFormat::kD16) {
          std::uint16_t v = 0;
          std::memcpy(&v, p + k_ * 2U, 2);
          return std::uint32_t{v};
        }
        std::uint32_t v = 0;
        std::memcpy(&v, p + k_ * 4U, 4);
        return f == pipe::DepthFormat::kD24 ? v & 0xFFFFFFU : v;
      };
      depths.resize(slots);
      for (std::uint32_t slot = 0; slot < slots; ++slot) {
        depths[slot].resize(entries);
        for (VkDeviceSize k_ = 0; k_ < entries; ++k_) {
          const std::uint32_t a = texel(slot, 0, k_);
          if (a != texel(slot, 1, k_))
            continue;
          pipe::DepthValue v;
          if (f == pipe::DepthFormat::kD32F)
            v.f = std::bit_cast<float>(a);
          else
            v.unorm = a;
          depths[slot][k_] = v;
        }
      }
    }
    return detail::decode_values(scene, packed, static_cast<const std::uint32_t*>(coverage_.mapped),
                                 static_cast<const float*>(values_.mapped),
                                 depth ? &depths : nullptr, w, h, per_sample ? samples : 0U,
                                 samples);
  }

private:
  // Ends the command buffer, submits it and waits; the buffer is reset in every case.
  std::string end_and_submit() {
    const VkCommandBuffer cmd = vk_.cmd;
    if (VkResult r = vkEndCommandBuffer(cmd); r != VK_SUCCESS) {
      vkResetCommandBuffer(cmd, 0);
      return vk_failed("vkEndCommandBuffer", r);
    }
    std::string submitted = vk_.submit_and_wait();
    vkResetCommandBuffer(cmd, 0);
    return submitted;
  }

  // The pipeline state of a primitive: topology, line mode, and for triangles the culling and
  // front face (both y-down: on-screen winding maps directly, DRIVER.LAVAPIPE.SUPPORT).
  // rule: DRIVER.LAVAPIPE.SUPPORT
  static PipelineKey primitive_key(const Scene& scene, const Primitive& p) {
    PipelineKey key;
    switch (p.type) {
    case PrimitiveType::kTriangle:
      key.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
      key.cull = detail::vk_cull_mode(scene.cull);
      key.front = detail::vk_front_face(scene.conventions.front_face);
      break;
    case PrimitiveType::kPoint:
      key.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
      break;
    case PrimitiveType::kLine:
    case PrimitiveType::kLineStrip:
      key.topology = p.type == PrimitiveType::kLine ? VK_PRIMITIVE_TOPOLOGY_LINE_LIST
                                                    : VK_PRIMITIVE_TOPOLOGY_LINE_STRIP;
      key.line_mode = scene.conventions.line_mode == LineMode::kVulkanBresenham
                          ? VK_LINE_RASTERIZATION_MODE_BRESENHAM_EXT
                          : VK_LINE_RASTERIZATION_MODE_RECTANGULAR_EXT;
      break;
    case PrimitiveType::kPath:
      break; // never here: unsupported() refuses paths
    }
    return key;
  }

  // Calls draw(i, key, first vertex, vertex count) for each primitive with the pipeline state
  // of the values program (topology, line mode, culling, provoking vertex, depth clamp) filled
  // in; stops when draw returns false.
  // rule: DRIVER.LAVAPIPE.VALUES
  template <class Draw>
  void for_each_primitive(const Scene& scene, const detail::PackedPipeline& packed, Draw&& draw) {
    std::uint32_t first = 0;
    for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
      const Primitive& p = scene.primitives[i];
      const auto count =
          static_cast<std::uint32_t>(packed.window_space[i] ? p.v.size() : p.pos.size());
      PipelineKey key = primitive_key(scene, p);
      key.values_layout = true;
      key.provoking_last = scene.conventions.provoking == pipe::Provoking::kLast;
      key.depth_clamp = !packed.window_space[i] && scene.depth && !scene.depth->clip;
      if (!draw(i, key, first, count))
        return;
      first += count;
    }
  }

  // What every draw of a pipeline scene shares: K, the scene's viewport and its scissor.
  struct DrawView {
    double k = 1.0;
    pipe::Viewport vp;
    VkRect2D scissor{};
  };

  // Records one draw of a slot: the pipeline, the viewport of the primitive (window space
  // through [-K, K] with depth [0, 1], exact, DRIVER.LAVAPIPE.POSITION; clip space through the
  // scene's viewport and depth range), the push constants naming the slot, and the vertices
  // [first, first + count).
  void record_draw(VkCommandBuffer cmd, VkPipeline pipeline, bool window_space,
                   const DrawView& view, std::uint32_t slot, std::uint32_t first,
                   std::uint32_t count, ValuesPush& push) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    const auto kf = static_cast<float>(view.k);
    const pipe::Viewport& vp = view.vp;
    const VkViewport viewport =
        window_space ? VkViewport{-kf, -kf, 2.0F * kf, 2.0F * kf, 0.0F, 1.0F}
                     : VkViewport{vp.x, vp.y, vp.width, vp.height, vp.min_depth, vp.max_depth};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &view.scissor);
    push.slot = slot;
    push.window_space = window_space ? 1U : 0U;
    vkCmdPushConstants(cmd, values_layout_,
                       VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                       sizeof(ValuesPush), &push);
    vkCmdDraw(cmd, count, 1, first, 0);
  }

  // Copies the depth target after a depth pass to the readback buffer from entry `at` (w x h x
  // samples entries of 4 bytes): a copy of the single-sample image, or the compute copy of every
  // sample (depth_copy.comp); then lets the next pass overwrite what was read.
  // rule: DRIVER.LAVAPIPE.VALUES
  void copy_depth_out(VkCommandBuffer cmd, std::uint32_t w, std::uint32_t h, std::uint32_t samples,
                      VkDeviceSize at) {
    if (samples > 1) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, copy_pipeline_);
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, copy_layout_, 0, 1, &copy_set_,
                              0, nullptr);
      const std::array<std::uint32_t, 4> copy_push{w, h, samples, static_cast<std::uint32_t>(at)};
      vkCmdPushConstants(cmd, copy_layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(copy_push),
                         copy_push.data());
      vkCmdDispatch(cmd, (w + 7) / 8, (h + 7) / 8, 1);
      barrier(VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT,
              VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT,
              VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
      return;
    }
    VkBufferImageCopy region{};
    region.bufferOffset = at * 4U;
    region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
    region.imageExtent = {w, h, 1};
    vkCmdCopyImageToBuffer(cmd, depth_image_, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           depth_readback_.buffer, 1, &region);
    barrier(VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT,
            VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT,
            VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
  }

  // Points the values descriptor set at the coverage and values buffers.
  void bind_values() {
    const std::array<VkDescriptorBufferInfo, 2> bi{
        VkDescriptorBufferInfo{coverage_.buffer, 0, VK_WHOLE_SIZE},
        VkDescriptorBufferInfo{values_.buffer, 0, VK_WHOLE_SIZE}};
    std::array<VkWriteDescriptorSet, 2> writes{};
    for (std::uint32_t b = 0; b < 2; ++b) {
      writes[b].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
      writes[b].dstSet = values_set_;
      writes[b].dstBinding = b;
      writes[b].descriptorCount = 1;
      writes[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      writes[b].pBufferInfo = &bi[b];
    }
    vkUpdateDescriptorSets(vk_.device, 2, writes.data(), 0, nullptr);
  }

  // The depth image of w x h in the format (and its view, render pass and framebuffer): kept
  // when it has that size and format, else (after the device is idle) replaced.
  std::string ensure_depth_target(std::uint32_t w, std::uint32_t h, pipe::DepthFormat f,
                                  std::uint32_t samples) {
    const VkFormat format = vk_depth_format(f, x8_d24_);
    if (depth_framebuffer_ != VK_NULL_HANDLE && depth_w_ == w && depth_h_ == h &&
        depth_format_ == format && depth_samples_ == samples) {
      return {};
    }
    // Several samples: the attachment is sampled by the compute copy (depth_copy.comp)
    // instead of copied to the buffer (multisampled images cannot be).
    const bool ms = samples > 1;
    vkDeviceWaitIdle(vk_.device);
    destroy_depth_target();
    const VkDevice device = vk_.device;
    VkImageCreateInfo ici{};
    ici.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
    ici.imageType = VK_IMAGE_TYPE_2D;
    ici.format = format;
    ici.extent = {w, h, 1};
    ici.mipLevels = 1;
    ici.arrayLayers = 1;
    ici.samples = static_cast<VkSampleCountFlagBits>(samples);
    ici.tiling = VK_IMAGE_TILING_OPTIMAL;
    ici.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                (ms ? VK_IMAGE_USAGE_SAMPLED_BIT : VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    if (VkResult r = vkCreateImage(device, &ici, nullptr, &depth_image_); r != VK_SUCCESS) {
      depth_image_ = VK_NULL_HANDLE;
      return vk_failed("vkCreateImage", r);
    }
    VkMemoryRequirements req{};
    vkGetImageMemoryRequirements(device, depth_image_, &req);
    std::uint32_t type = 0;
    while (type < vk_.memory.memoryTypeCount && (req.memoryTypeBits & (1U << type)) == 0U)
      ++type;
    VkMemoryAllocateInfo mai{};
    mai.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    mai.allocationSize = req.size;
    mai.memoryTypeIndex = type;
    if (VkResult r = vkAllocateMemory(device, &mai, nullptr, &depth_memory_); r != VK_SUCCESS) {
      depth_memory_ = VK_NULL_HANDLE;
      return vk_failed("vkAllocateMemory", r);
    }
    vkBindImageMemory(device, depth_image_, depth_memory_, 0);
    const bool stencil = format == VK_FORMAT_D24_UNORM_S8_UINT;
    VkImageViewCreateInfo vci{};
    vci.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
    vci.image = depth_image_;
    vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vci.format = format;
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    if (stencil)
      aspect |= VK_IMAGE_ASPECT_STENCIL_BIT;
    vci.subresourceRange = {aspect, 0, 1, 0, 1};
    if (VkResult r = vkCreateImageView(device, &vci, nullptr, &depth_view_); r != VK_SUCCESS) {
      depth_view_ = VK_NULL_HANDLE;
      return vk_failed("vkCreateImageView", r);
    }
    VkAttachmentDescription att{};
    att.format = format;
    att.samples = static_cast<VkSampleCountFlagBits>(samples);
    att.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    att.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    att.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    att.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    att.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    att.finalLayout =
        ms ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.pDepthStencilAttachment = &ref;
    // The copy after the pass reads what the depth test wrote; the next pass overwrites what
    // the copy before it read.
    std::array<VkSubpassDependency, 2> deps{};
    deps[0] = {VK_SUBPASS_EXTERNAL,
               0,
               VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
               VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                   VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
               VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_SHADER_READ_BIT,
               VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
               0};
    deps[1] = {0,
               VK_SUBPASS_EXTERNAL,
               VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
               VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
               VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_SHADER_READ_BIT,
               0};
    VkRenderPassCreateInfo rci{};
    rci.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
    rci.attachmentCount = 1;
    rci.pAttachments = &att;
    rci.subpassCount = 1;
    rci.pSubpasses = &subpass;
    rci.dependencyCount = static_cast<std::uint32_t>(deps.size());
    rci.pDependencies = deps.data();
    if (VkResult r = vkCreateRenderPass(device, &rci, nullptr, &depth_pass_); r != VK_SUCCESS) {
      depth_pass_ = VK_NULL_HANDLE;
      return vk_failed("vkCreateRenderPass", r);
    }
    VkFramebufferCreateInfo fci{};
    fci.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
    fci.renderPass = depth_pass_;
    fci.attachmentCount = 1;
    fci.pAttachments = &depth_view_;
    fci.width = w;
    fci.height = h;
    fci.layers = 1;
    if (VkResult r = vkCreateFramebuffer(device, &fci, nullptr, &depth_framebuffer_);
        r != VK_SUCCESS) {
      depth_framebuffer_ = VK_NULL_HANDLE;
      return vk_failed("vkCreateFramebuffer", r);
    }
    depth_w_ = w;
    depth_h_ = h;
    depth_format_ = format;
    depth_samples_ = samples;
    return {};
  }

  // The compute copy of multisampled depth (depth_copy.comp): its sampler, set (the depth
  // view, the readback buffer), layout and pipeline, created on first use.
  // rule: DRIVER.LAVAPIPE.VALUES
  std::string ensure_depth_copy() {
    const VkDevice device = vk_.device;
    if (copy_pipeline_ == VK_NULL_HANDLE) {
      VkSamplerCreateInfo sci{};
      sci.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
      sci.magFilter = VK_FILTER_NEAREST;
      sci.minFilter = VK_FILTER_NEAREST;
      if (VkResult r = vkCreateSampler(device, &sci, nullptr, &copy_sampler_); r != VK_SUCCESS)
        return vk_failed("vkCreateSampler", r);
      std::array<VkDescriptorSetLayoutBinding, 2> b{};
      b[0] = {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT,
              nullptr};
      b[1] = {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
      VkDescriptorSetLayoutCreateInfo dli{};
      dli.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
      dli.bindingCount = 2;
      dli.pBindings = b.data();
      if (VkResult r = vkCreateDescriptorSetLayout(device, &dli, nullptr, &copy_set_layout_);
          r != VK_SUCCESS) {
        return vk_failed("vkCreateDescriptorSetLayout", r);
      }
      std::array<VkDescriptorPoolSize, 2> sizes{
          VkDescriptorPoolSize{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1},
          VkDescriptorPoolSize{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}};
      VkDescriptorPoolCreateInfo dpi{};
      dpi.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
      dpi.maxSets = 1;
      dpi.poolSizeCount = 2;
      dpi.pPoolSizes = sizes.data();
      if (VkResult r = vkCreateDescriptorPool(device, &dpi, nullptr, &copy_pool_); r != VK_SUCCESS)
        return vk_failed("vkCreateDescriptorPool", r);
      VkDescriptorSetAllocateInfo dai{};
      dai.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
      dai.descriptorPool = copy_pool_;
      dai.descriptorSetCount = 1;
      dai.pSetLayouts = &copy_set_layout_;
      if (VkResult r = vkAllocateDescriptorSets(device, &dai, &copy_set_); r != VK_SUCCESS)
        return vk_failed("vkAllocateDescriptorSets", r);
      if (std::string why = create_layout(device, copy_set_layout_, VK_SHADER_STAGE_COMPUTE_BIT,
                                          4 * sizeof(std::uint32_t), &copy_layout_);
          !why.empty()) {
        return why;
      }
      VkShaderModule module = VK_NULL_HANDLE;
      if (std::string why = detail::create_shader_module(device, kDepth_copy_comp,
                                                         sizeof(kDepth_copy_comp), &module);
          !why.empty()) {
        return why;
      }
      VkComputePipelineCreateInfo cci{};
      cci.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
      cci.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
      cci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
      cci.stage.module = module;
      cci.stage.pName = "main";
      cci.layout = copy_layout_;
      const VkResult r =
          vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &cci, nullptr, &copy_pipeline_);
      vkDestroyShaderModule(device, module, nullptr);
      if (r != VK_SUCCESS) {
        copy_pipeline_ = VK_NULL_HANDLE;
        return vk_failed("vkCreateComputePipelines", r);
      }
    }
    // The set names the current depth view and readback buffer (both may have been replaced).
    VkDescriptorImageInfo ii{copy_sampler_, depth_view_,
                             VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL};
    VkDescriptorBufferInfo bi{depth_readback_.buffer, 0, VK_WHOLE_SIZE};
    std::array<VkWriteDescriptorSet, 2> writes{};
    for (std::uint32_t b = 0; b < 2; ++b) {
      writes[b].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
      writes[b].dstSet = copy_set_;
      writes[b].dstBinding = b;
      writes[b].descriptorCount = 1;
    }
    writes[0].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    writes[0].pImageInfo = &ii;
    writes[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[1].pBufferInfo = &bi;
    vkUpdateDescriptorSets(device, 2, writes.data(), 0, nullptr);
    return {};
  }

  // Destroys the depth target and the pipelines made for its render pass.
  void destroy_depth_target() {
    const VkDevice device = vk_.device;
    for (auto it = values_pipelines_.begin(); it != values_pipelines_.end();) {
      if (it->first.second == depth_pass_) {
        vkDestroyPipeline(device, it->second, nullptr);
        it = values_pipelines_.erase(it);
      } else {
        ++it;
      }
    }
    if (depth_framebuffer_ != VK_NULL_HANDLE)
      vkDestroyFramebuffer(device, depth_framebuffer_, nullptr);
    if (depth_pass_ != VK_NULL_HANDLE)
      vkDestroyRenderPass(device, depth_pass_, nullptr);
    if (depth_view_ != VK_NULL_HANDLE)
      vkDestroyImageView(device, depth_view_, nullptr);
    if (depth_image_ != VK_NULL_HANDLE)
      vkDestroyImage(device, depth_image_, nullptr);
    if (depth_memory_ != VK_NULL_HANDLE)
      vkFreeMemory(device, depth_memory_, nullptr);
    depth_framebuffer_ = VK_NULL_HANDLE;
    depth_pass_ = VK_NULL_HANDLE;
    depth_view_ = VK_NULL_HANDLE;
    depth_image_ = VK_NULL_HANDLE;
    depth_memory_ = VK_NULL_HANDLE;
    depth_w_ = 0;
  }

  // Returns the cached values pipeline for key with the fragment shader in the render pass.
  std::variant<VkPipeline, std::string>
  get_values_pipeline(const PipelineKey& key, VkShaderModule frag, VkRenderPass pass) {
    auto id = std::make_pair(key, pass);
    if (auto it = values_pipelines_.find(id); it != values_pipelines_.end())
      return it->second;
    VkPipeline pipeline = VK_NULL_HANDLE;
    if (std::string why = detail::create_coverage_pipeline(vk_.device, values_vert_, frag,
                                                           values_layout_, pass, key, &pipeline);
        !why.empty()) {
      return why;
    }
    values_pipelines_.emplace(id, pipeline);
    return pipeline;
  }

  std::string check_features() {
    VkPhysicalDeviceLineRasterizationFeaturesEXT line{};
    line.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_LINE_RASTERIZATION_FEATURES_EXT;
    VkPhysicalDeviceFeatures2 f2{};
    f2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
    f2.pNext = &line;
    vkGetPhysicalDeviceFeatures2(vk_.physical, &f2);
    if (f2.features.fragmentStoresAndAtomics != VK_TRUE) {
      return "lavapipe: device lacks fragmentStoresAndAtomics (needed to observe coverage)";
    }
    if (f2.features.geometryShader != VK_TRUE) {
      return "lavapipe: device lacks geometryShader (needed for gl_PrimitiveID in fragment "
             "shaders)";
    }
    std::uint32_t n = 0;
    vkEnumerateDeviceExtensionProperties(vk_.physical, nullptr, &n, nullptr);
    std::vector<VkExtensionProperties> exts(n);
    vkEnumerateDeviceExtensionProperties(vk_.physical, nullptr, &n, exts.data());
    has_line_ext_ = std::any_of(exts.begin(), exts.end(), [](const VkExtensionProperties& e) {
      return std::strcmp(e.extensionName, VK_EXT_LINE_RASTERIZATION_EXTENSION_NAME) == 0;
    });
    has_provoking_ext_ = std::any_of(exts.begin(), exts.end(), [](const VkExtensionProperties& e) {
      return std::strcmp(e.extensionName, VK_EXT_PROVOKING_VERTEX_EXTENSION_NAME) == 0;
    });
    if (has_provoking_ext_) {
      VkPhysicalDeviceProvokingVertexFeaturesEXT pv{};
      pv.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROVOKING_VERTEX_FEATURES_EXT;
      VkPhysicalDeviceFeatures2 pf{};
      pf.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
      pf.pNext = &pv;
      vkGetPhysicalDeviceFeatures2(vk_.physical, &pf);
      provoking_last_ = pv.provokingVertexLast == VK_TRUE;
    }
    depth_clamp_ = f2.features.depthClamp == VK_TRUE;
    depth_bias_clamp_ = f2.features.depthBiasClamp == VK_TRUE;
    sample_rate_shading_ = f2.features.sampleRateShading == VK_TRUE;
    // rule: DRIVER.LAVAPIPE.VALUES
    // D24 as X8_D24 when it is a depth attachment that can be copied from, else D24S8.
    VkFormatProperties fp{};
    vkGetPhysicalDeviceFormatProperties(vk_.physical, VK_FORMAT_X8_D24_UNORM_PACK32, &fp);
    const VkFormatFeatureFlags need =
        VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT;
    x8_d24_ = (fp.optimalTilingFeatures & need) == need;
    bresenham_ = has_line_ext_ && line.bresenhamLines == VK_TRUE;
    rectangular_ = has_line_ext_ && line.rectangularLines == VK_TRUE;
    smooth_ = has_line_ext_ && line.smoothLines == VK_TRUE;

    // Info (DRIVER.LAVAPIPE.DEVICE).
    const VkPhysicalDeviceLimits& lim = vk_.props.limits;
    info_.name = "lavapipe";
    info_.description = detail::device_description(vk_.physical, vk_.props) +
                        ", lines: " + (bresenham_ ? "bresenham " : "") +
                        (rectangular_ ? "rectangular " : "") + (smooth_ ? "smooth" : "");
    info_.subpixel_bits = static_cast<int>(lim.subPixelPrecisionBits);
    const VkSampleCountFlags counts = lim.framebufferNoAttachmentsSampleCounts;
    for (std::uint32_t c : {1U, 2U, 4U, 8U, 16U}) {
      if ((counts & c) != 0U && (lim.standardSampleLocations == VK_TRUE || c == 1U)) {
        info_.sample_counts.push_back(c);
      }
    }
    info_.points = true;
    info_.lines_bresenham = bresenham_;
    info_.lines_rectangular = rectangular_;
    info_.lines_d3d = false;
    info_.sample_mask = true;
    info_.sample_shading = false;
    info_.values = true; // DRIVER.LAVAPIPE.VALUES
    // rule: DRIVER.LAVAPIPE.POSITION
    max_k_ = detail::max_position_scale(lim);
    const double fb = std::min(lim.maxFramebufferWidth, lim.maxFramebufferHeight);
    info_.max_target_side = static_cast<std::int32_t>(std::min(fb, max_k_));
    return {};
  }

  std::string create_device() {
    VkPhysicalDeviceLineRasterizationFeaturesEXT line{};
    line.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_LINE_RASTERIZATION_FEATURES_EXT;
    line.bresenhamLines = bresenham_ ? VK_TRUE : VK_FALSE;
    line.rectangularLines = rectangular_ ? VK_TRUE : VK_FALSE;
    VkPhysicalDeviceProvokingVertexFeaturesEXT pv{};
    pv.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROVOKING_VERTEX_FEATURES_EXT;
    pv.provokingVertexLast = provoking_last_ ? VK_TRUE : VK_FALSE;
    VkPhysicalDeviceFeatures2 f2{};
    f2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
    std::vector<const char*> exts;
    void* chain = nullptr;
    if (has_line_ext_) {
      line.pNext = chain;
      chain = &line;
      exts.push_back(VK_EXT_LINE_RASTERIZATION_EXTENSION_NAME);
    }
    if (provoking_last_) {
      pv.pNext = chain;
      chain = &pv;
      exts.push_back(VK_EXT_PROVOKING_VERTEX_EXTENSION_NAME);
    }
    f2.pNext = chain;
    f2.features.fragmentStoresAndAtomics = VK_TRUE;
    f2.features.geometryShader = VK_TRUE;
    f2.features.depthClamp = depth_clamp_ ? VK_TRUE : VK_FALSE;
    f2.features.depthBiasClamp = depth_bias_clamp_ ? VK_TRUE : VK_FALSE;
    f2.features.sampleRateShading = sample_rate_shading_ ? VK_TRUE : VK_FALSE;
    return vk_.create_device(f2, static_cast<std::uint32_t>(exts.size()), exts.data(),
                             VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT);
  }

  std::string create_shared() {
    const VkDevice device = vk_.device;
    if (std::string why = create_storage_set(device, 1, &set_layout_, &descriptor_pool_, &set_);
        !why.empty()) {
      return why;
    }
    // Coverage goes to the storage buffer only (the render pass has no attachments).
    if (std::string why =
            program_.create(device, kCoverage_frag, sizeof(kCoverage_frag),
                            VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, set_layout_);
        !why.empty()) {
      return why;
    }
    return create_values_program();
  }

  // A pipeline layout of one descriptor set layout and one push-constant range of `bytes` for
  // `stages`; *layout is VK_NULL_HANDLE on failure.
  static std::string create_layout(VkDevice device, VkDescriptorSetLayout set_layout,
                                   VkShaderStageFlags stages, std::uint32_t bytes,
                                   VkPipelineLayout* layout) {
    const VkPushConstantRange range{stages, 0, bytes};
    VkPipelineLayoutCreateInfo lci{};
    lci.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    lci.setLayoutCount = 1;
    lci.pSetLayouts = &set_layout;
    lci.pushConstantRangeCount = 1;
    lci.pPushConstantRanges = &range;
    if (VkResult r = vkCreatePipelineLayout(device, &lci, nullptr, layout); r != VK_SUCCESS) {
      *layout = VK_NULL_HANDLE;
      return vk_failed("vkCreatePipelineLayout", r);
    }
    return {};
  }

  // A descriptor set of `count` storage buffers (bindings 0, 1, ...) for the fragment stage,
  // with its layout and its own pool.
  static std::string create_storage_set(VkDevice device, std::uint32_t count,
                                        VkDescriptorSetLayout* layout, VkDescriptorPool* pool,
                                        VkDescriptorSet* set) {
    std::vector<VkDescriptorSetLayoutBinding> bindings(count);
    for (std::uint32_t b = 0; b < count; ++b) {
      bindings[b].binding = b;
      bindings[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      bindings[b].descriptorCount = 1;
      bindings[b].stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT;
    }
    VkDescriptorSetLayoutCreateInfo dli{};
    dli.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    dli.bindingCount = count;
    dli.pBindings = bindings.data();
    if (VkResult r = vkCreateDescriptorSetLayout(device, &dli, nullptr, layout); r != VK_SUCCESS)
      return vk_failed("vkCreateDescriptorSetLayout", r);
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, count};
    VkDescriptorPoolCreateInfo dpi{};
    dpi.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    dpi.maxSets = 1;
    dpi.poolSizeCount = 1;
    dpi.pPoolSizes = &size;
    if (VkResult r = vkCreateDescriptorPool(device, &dpi, nullptr, pool); r != VK_SUCCESS)
      return vk_failed("vkCreateDescriptorPool", r);
    VkDescriptorSetAllocateInfo dai{};
    dai.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    dai.descriptorPool = *pool;
    dai.descriptorSetCount = 1;
    dai.pSetLayouts = layout;
    if (VkResult r = vkAllocateDescriptorSets(device, &dai, set); r != VK_SUCCESS)
      return vk_failed("vkAllocateDescriptorSets", r);
    return {};
  }

  // The values program of pipeline scenes: its shaders (and the empty fragment shader of the
  // depth passes), a set of two storage buffers (coverage, values) and its pipeline layout.
  // rule: DRIVER.LAVAPIPE.VALUES
  std::string create_values_program() {
    const VkDevice device = vk_.device;
    for (const auto& [code, bytes, module] :
         {std::tuple{kValues_vert, sizeof(kValues_vert), &values_vert_},
          std::tuple{kValues_frag, sizeof(kValues_frag), &values_frag_},
          std::tuple{kValues_sample_frag, sizeof(kValues_sample_frag), &values_sample_frag_},
          std::tuple{kTiming_frag, sizeof(kTiming_frag), &empty_frag_}}) {
      if (std::string why = detail::create_shader_module(device, code, bytes, module);
          !why.empty()) {
        return why;
      }
    }
    if (std::string why =
            create_storage_set(device, 2, &values_set_layout_, &values_pool_, &values_set_);
        !why.empty()) {
      return why;
    }
    return create_layout(device, values_set_layout_,
                         VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                         sizeof(ValuesPush), &values_layout_);
  }

  // Points the descriptor set at the coverage buffer.
  void bind_coverage() {
    VkDescriptorBufferInfo bi{coverage_.buffer, 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet write{};
    write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    write.dstSet = set_;
    write.dstBinding = 0;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    write.pBufferInfo = &bi;
    vkUpdateDescriptorSets(vk_.device, 1, &write, 0, nullptr);
  }

  void barrier(VkPipelineStageFlags src_stage, VkAccessFlags src, VkPipelineStageFlags dst_stage,
               VkAccessFlags dst) {
    VkMemoryBarrier mb{};
    mb.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    mb.srcAccessMask = src;
    mb.dstAccessMask = dst;
    vkCmdPipelineBarrier(vk_.cmd, src_stage, dst_stage, 0, 1, &mb, 0, nullptr, 0, nullptr);
  }

  // Returns the cached pipeline for key, creating it on first use.
  std::variant<VkPipeline, std::string> get_pipeline(const PipelineKey& key) {
    if (auto it = pipelines_.find(key); it != pipelines_.end())
      return it->second;
    VkPipeline pipeline = VK_NULL_HANDLE;
    if (std::string why = program_.create_pipeline(vk_.device, key, &pipeline); !why.empty()) {
      return why;
    }
    pipelines_.emplace(key, pipeline);
    return pipeline;
  }

  void destroy() {
    if (const VkDevice device = vk_.device; device != VK_NULL_HANDLE) {
      vkDeviceWaitIdle(device);
      for (auto& [key, p] : pipelines_)
        vkDestroyPipeline(device, p, nullptr);
      pipelines_.clear();
      destroy_depth_target();
      if (copy_pipeline_ != VK_NULL_HANDLE)
        vkDestroyPipeline(device, copy_pipeline_, nullptr);
      if (copy_layout_ != VK_NULL_HANDLE)
        vkDestroyPipelineLayout(device, copy_layout_, nullptr);
      if (copy_pool_ != VK_NULL_HANDLE)
        vkDestroyDescriptorPool(device, copy_pool_, nullptr);
      if (copy_set_layout_ != VK_NULL_HANDLE)
        vkDestroyDescriptorSetLayout(device, copy_set_layout_, nullptr);
      if (copy_sampler_ != VK_NULL_HANDLE)
        vkDestroySampler(device, copy_sampler_, nullptr);
      for (auto& [key, p] : values_pipelines_)
        vkDestroyPipeline(device, p, nullptr);
      values_pipelines_.clear();
      for (VkShaderModule m : {values_vert_, values_frag_, values_sample_frag_, empty_frag_}) {
        if (m != VK_NULL_HANDLE)
          vkDestroyShaderModule(device, m, nullptr);
      }
      if (values_layout_ != VK_NULL_HANDLE)
        vkDestroyPipelineLayout(device, values_layout_, nullptr);
      if (values_pool_ != VK_NULL_HANDLE)
        vkDestroyDescriptorPool(device, values_pool_, nullptr);
      if (values_set_layout_ != VK_NULL_HANDLE)
        vkDestroyDescriptorSetLayout(device, values_set_layout_, nullptr);
      free_host_buffer(device, &values_);
      free_host_buffer(device, &values_vertex_);
      free_host_buffer(device, &depth_readback_);
      free_host_buffer(device, &coverage_);
      free_host_buffer(device, &vertex_);
      program_.destroy(device);
      if (descriptor_pool_ != VK_NULL_HANDLE) {
        vkDestroyDescriptorPool(device, descriptor_pool_, nullptr);
      }
      if (set_layout_ != VK_NULL_HANDLE)
        vkDestroyDescriptorSetLayout(device, set_layout_, nullptr);
    }
    vk_.destroy();
  }

  detail::LavapipeContext vk_;
  bool has_line_ext_ = false;
  bool bresenham_ = false;
  bool rectangular_ = false;
  bool smooth_ = false;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkDescriptorPool descriptor_pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  detail::CoverageProgram program_;
  HostBuffer coverage_;
  HostBuffer vertex_;
  VkDeviceSize bound_size_ = 0; // coverage_.size when the descriptor set was last written
  std::map<PipelineKey, VkPipeline> pipelines_;
  // The values path (DRIVER.LAVAPIPE.VALUES).
  bool has_provoking_ext_ = false;
  bool provoking_last_ = false;
  bool depth_clamp_ = false;
  bool depth_bias_clamp_ = false;
  bool sample_rate_shading_ = false;
  bool x8_d24_ = false;
  VkShaderModule values_vert_ = VK_NULL_HANDLE;
  VkShaderModule values_frag_ = VK_NULL_HANDLE;
  VkShaderModule values_sample_frag_ = VK_NULL_HANDLE;
  VkShaderModule empty_frag_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout values_set_layout_ = VK_NULL_HANDLE;
  VkDescriptorPool values_pool_ = VK_NULL_HANDLE;
  VkDescriptorSet values_set_ = VK_NULL_HANDLE;
  VkPipelineLayout values_layout_ = VK_NULL_HANDLE;
  HostBuffer values_;
  HostBuffer values_vertex_;
  HostBuffer depth_readback_;
  VkImage depth_image_ = VK_NULL_HANDLE;
  VkDeviceMemory depth_memory_ = VK_NULL_HANDLE;
  VkImageView depth_view_ = VK_NULL_HANDLE;
  VkRenderPass depth_pass_ = VK_NULL_HANDLE;
  VkFramebuffer depth_framebuffer_ = VK_NULL_HANDLE;
  std::uint32_t depth_w_ = 0;
  std::uint32_t depth_h_ = 0;
  VkFormat depth_format_ = VK_FORMAT_UNDEFINED;
  std::uint32_t depth_samples_ = 0;
  // The compute copy of multisampled depth (ensure_depth_copy).
  VkSampler copy_sampler_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout copy_set_layout_ = VK_NULL_HANDLE;
  VkDescriptorPool copy_pool_ = VK_NULL_HANDLE;
  VkDescriptorSet copy_set_ = VK_NULL_HANDLE;
  VkPipelineLayout copy_layout_ = VK_NULL_HANDLE;
  VkPipeline copy_pipeline_ = VK_NULL_HANDLE;
  std::map<std::pair<PipelineKey, VkRenderPass>, VkPipeline> values_pipelines_;
};

} // namespace

namespace detail {

// rule: DRIVER.LAVAPIPE.DEVICE
std::unique_ptr<Driver> open_lavapipe(std::string_view arg, std::string* error) {
  return open_gpu_driver<LavapipeDriver>("lavapipe", arg, error);
}

} // namespace detail
} // namespace rastrules::driver

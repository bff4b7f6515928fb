// SPDX-License-Identifier: MIT
// The lavapipe adapter: draws a scene with Mesa's Vulkan CPU driver (llvmpipe), headless, and
// reads back per-primitive, per-sample coverage from a storage buffer that the fragment
// shader ORs gl_SampleMaskIn into (integer multisampled attachments are not needed).
// Implements: DRIVER.LAVAPIPE.DEVICE, DRIVER.LAVAPIPE.COVERAGE, DRIVER.LAVAPIPE.POSITION,
//             DRIVER.LAVAPIPE.SUPPORT

#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "drivers.hpp"
#include "gpu_common.hpp"
#include "rastrules/driver/coverage_frag.spv.h"
#include "rastrules/scene.hpp"
#include "vulkan_common.hpp"

namespace rastrules::driver {
namespace {

using detail::free_host_buffer;
using detail::HostBuffer;
using detail::vk_failed;

using Push = detail::CoveragePush;

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
      PipelineKey key;
      key.samples = samples;
      key.sample_mask = mask;
      switch (p.type) {
      case PrimitiveType::kTriangle:
        key.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
        // Both y-down: on-screen winding maps directly (DRIVER.LAVAPIPE.SUPPORT).
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
    if (VkResult r = vkEndCommandBuffer(cmd); r != VK_SUCCESS) {
      vkResetCommandBuffer(cmd, 0);
      return DriverError{vk_failed("vkEndCommandBuffer", r)};
    }
    const std::string submitted = vk_.submit_and_wait();
    vkResetCommandBuffer(cmd, 0);
    if (!submitted.empty())
      return DriverError{submitted};

    // rule: DRIVER.LAVAPIPE.COVERAGE
    return detail::decode_coverage(scene, packed,
                                   static_cast<const std::uint32_t*>(coverage_.mapped), w, h);
  }

private:
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
    VkPhysicalDeviceFeatures2 f2{};
    f2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
    f2.pNext = has_line_ext_ ? &line : nullptr;
    f2.features.fragmentStoresAndAtomics = VK_TRUE;
    f2.features.geometryShader = VK_TRUE;
    const char* ext = VK_EXT_LINE_RASTERIZATION_EXTENSION_NAME;
    return vk_.create_device(f2, has_line_ext_ ? 1U : 0U, &ext,
                             VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT);
  }

  std::string create_shared() {
    const VkDevice device = vk_.device;
    VkDescriptorSetLayoutBinding binding{};
    binding.binding = 0;
    binding.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    binding.descriptorCount = 1;
    binding.stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT;
    VkDescriptorSetLayoutCreateInfo dli{};
    dli.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    dli.bindingCount = 1;
    dli.pBindings = &binding;
    if (VkResult r = vkCreateDescriptorSetLayout(device, &dli, nullptr, &set_layout_);
        r != VK_SUCCESS) {
      return vk_failed("vkCreateDescriptorSetLayout", r);
    }
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1};
    VkDescriptorPoolCreateInfo dpi{};
    dpi.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    dpi.maxSets = 1;
    dpi.poolSizeCount = 1;
    dpi.pPoolSizes = &size;
    if (VkResult r = vkCreateDescriptorPool(device, &dpi, nullptr, &descriptor_pool_);
        r != VK_SUCCESS) {
      return vk_failed("vkCreateDescriptorPool", r);
    }
    VkDescriptorSetAllocateInfo dai{};
    dai.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    dai.descriptorPool = descriptor_pool_;
    dai.descriptorSetCount = 1;
    dai.pSetLayouts = &set_layout_;
    if (VkResult r = vkAllocateDescriptorSets(device, &dai, &set_); r != VK_SUCCESS) {
      return vk_failed("vkAllocateDescriptorSets", r);
    }
    // Coverage goes to the storage buffer only (the render pass has no attachments).
    return program_.create(device, kCoverage_frag, sizeof(kCoverage_frag),
                           VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, set_layout_);
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
};

} // namespace

namespace detail {

// rule: DRIVER.LAVAPIPE.DEVICE
std::unique_ptr<Driver> open_lavapipe(std::string_view arg, std::string* error) {
  return open_gpu_driver<LavapipeDriver>("lavapipe", arg, error);
}

} // namespace detail
} // namespace rastrules::driver

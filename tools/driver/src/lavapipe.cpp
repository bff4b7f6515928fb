// SPDX-License-Identifier: MIT
// The lavapipe adapter: draws a scene with Mesa's Vulkan CPU driver (llvmpipe), headless, and
// reads back per-primitive, per-sample coverage from a storage buffer that the fragment
// shader ORs gl_SampleMaskIn into (integer multisampled attachments are not needed).
// Implements: DRIVER.LAVAPIPE.DEVICE, DRIVER.LAVAPIPE.COVERAGE, DRIVER.LAVAPIPE.POSITION,
//             DRIVER.LAVAPIPE.SUPPORT

#include <vulkan/vulkan.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include "drivers.hpp"
#include "gpu_common.hpp"
#include "vulkan_common.hpp"
#include "rastrules/driver/coverage_frag.spv.h"
#include "rastrules/driver/coverage_vert.spv.h"
#include "rastrules/scene.hpp"

namespace rastrules::driver {
namespace {

using detail::free_host_buffer;
using detail::HostBuffer;
using detail::vk_failed;

using Push = detail::CoveragePush;

// Everything that selects a pipeline (DRIVER.LAVAPIPE.SUPPORT).
struct PipelineKey {
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkLineRasterizationModeEXT line_mode = VK_LINE_RASTERIZATION_MODE_DEFAULT_EXT;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  VkCullModeFlags cull = VK_CULL_MODE_NONE;
  VkFrontFace front = VK_FRONT_FACE_CLOCKWISE;
  std::uint32_t sample_mask = 0xFFFFFFFFu;
  [[nodiscard]] auto tie() const {
    return std::make_tuple(static_cast<int>(topology), static_cast<int>(line_mode),
                           static_cast<int>(samples), cull, static_cast<int>(front),
                           sample_mask);
  }
  friend bool operator<(const PipelineKey& a, const PipelineKey& b) { return a.tie() < b.tie(); }
};

class LavapipeDriver final : public detail::GpuDriver {
 public:
  ~LavapipeDriver() override { destroy(); }

  // Creates the instance, selects the CPU device and creates everything draws share.
  // Returns an empty string on success, else the reason.
  // rule: DRIVER.LAVAPIPE.DEVICE
  std::string init() {
    if (std::string why = detail::open_lavapipe_instance(&instance_, &physical_, &props_);
        !why.empty()) {
      return why;
    }
    if (std::string why = check_features(); !why.empty()) return why;
    if (std::string why = create_device(); !why.empty()) return why;
    return create_shared();
  }

  // rule: DRIVER.LAVAPIPE.SUPPORT
  [[nodiscard]] detail::SupportChecks support_checks() const override {
    detail::SupportChecks checks;
    checks.pattern_note = "Vulkan standard sample locations only";
    checks.count_by = props_.deviceName;
    checks.k_limit = "device limit";
    checks.line = [this](const Scene& s, const Primitive& p) -> std::string {
      if (p.aa) return "antialiased lines not supported";
      switch (s.line_mode) {
        case LineMode::kD3DDiamond:
          return "line mode 'd3d' (diamond exit) has no Vulkan equivalent";
        case LineMode::kQuadWide:
          return "line mode 'quad-wide' (1.4 px) not supported (Vulkan rectangular lines are 1.0 px wide here)";
        case LineMode::kVulkanBresenham:
          if (!info_.lines_bresenham) return "Bresenham lines not supported by the device";
          break;
        case LineMode::kQuadNarrow:
          if (!info_.lines_rectangular) return "rectangular lines not supported by the device";
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
    if (std::string why = ensure_buffer(coverage_, cov_bytes,
                                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                            VK_BUFFER_USAGE_TRANSFER_DST_BIT);
        !why.empty()) {
      return DriverError{why};
    }
    // ensure_buffer reallocates exactly when the size grows: rebind then, whatever the handle.
    if (coverage_.size != bound_size_) {
      bind_coverage();
      bound_size_ = coverage_.size;
    }
    if (std::string why = ensure_buffer(vertex_, std::max<VkDeviceSize>(vertices.size() * sizeof(float), 8),
                                        VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        !why.empty()) {
      return DriverError{why};
    }
    std::memcpy(vertex_.mapped, vertices.data(), vertices.size() * sizeof(float));
    if (std::string why = ensure_framebuffer(w, h); !why.empty()) return DriverError{why};

    const double k = detail::position_scale(scene);
    const auto samples = static_cast<VkSampleCountFlagBits>(scene.msaa.count());
    const std::uint32_t mask = scene.msaa.effective_mask();

    // The command buffer is in the initial state: it is reset as soon as its submission
    // completes, before any buffer it used is replaced.
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(cmd_, &begin);
    vkCmdFillBuffer(cmd_, coverage_.buffer, 0, cov_bytes, 0);
    barrier(VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
            VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
            VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);

    // rule: DRIVER.LAVAPIPE.POSITION
    detail::begin_target_pass(cmd_, render_pass_, framebuffer_, w, h, k);
    vkCmdBindDescriptorSets(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_, 0, nullptr);
    const VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd_, 0, 1, &vertex_.buffer, &zero);

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
          key.cull = detail::vk_cull_mode(scene.state.cull);
          key.front = detail::vk_front_face(scene.state.front_face);
          break;
        case PrimitiveType::kPoint:
          key.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
          break;
        case PrimitiveType::kLine:
        case PrimitiveType::kLineStrip:
          key.topology = p.type == PrimitiveType::kLine ? VK_PRIMITIVE_TOPOLOGY_LINE_LIST
                                                        : VK_PRIMITIVE_TOPOLOGY_LINE_STRIP;
          key.line_mode = scene.line_mode == LineMode::kVulkanBresenham
                              ? VK_LINE_RASTERIZATION_MODE_BRESENHAM_EXT
                              : VK_LINE_RASTERIZATION_MODE_RECTANGULAR_EXT;
          break;
      }
      auto pipeline = get_pipeline(key);
      if (const auto* e = std::get_if<std::string>(&pipeline)) {
        vkCmdEndRenderPass(cmd_);
        vkEndCommandBuffer(cmd_);
        vkResetCommandBuffer(cmd_, 0);
        return DriverError{*e};
      }
      const VkPipeline pl = std::get<VkPipeline>(pipeline);
      if (pl != bound) {
        vkCmdBindPipeline(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, pl);
        bound = pl;
      }
      const Push push{static_cast<float>(1.0 / k), packed.first_slot[i], w, h, slots};
      vkCmdPushConstants(cmd_, layout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                         0, sizeof(Push), &push);
      const auto count = static_cast<std::uint32_t>(p.v.size());
      vkCmdDraw(cmd_, count, 1, first_vertex, 0);
      first_vertex += count;
    }
    vkCmdEndRenderPass(cmd_);
    barrier(VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
            VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
    if (VkResult r = vkEndCommandBuffer(cmd_); r != VK_SUCCESS) {
      vkResetCommandBuffer(cmd_, 0);
      return DriverError{vk_failed("vkEndCommandBuffer", r)};
    }
    if (std::string why = detail::submit_and_wait(device_, queue_, cmd_, fence_); !why.empty()) {
      vkResetCommandBuffer(cmd_, 0);
      return DriverError{why};
    }
    vkResetCommandBuffer(cmd_, 0);

    // rule: DRIVER.LAVAPIPE.COVERAGE
    return detail::decode_coverage(scene, packed, static_cast<const std::uint32_t*>(coverage_.mapped),
                                   w, h);
  }

 private:
  std::string check_features() {
    VkPhysicalDeviceLineRasterizationFeaturesEXT line{};
    line.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_LINE_RASTERIZATION_FEATURES_EXT;
    VkPhysicalDeviceFeatures2 f2{};
    f2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
    f2.pNext = &line;
    vkGetPhysicalDeviceFeatures2(physical_, &f2);
    if (f2.features.fragmentStoresAndAtomics != VK_TRUE) {
      return "lavapipe: device lacks fragmentStoresAndAtomics (needed to observe coverage)";
    }
    if (f2.features.geometryShader != VK_TRUE) {
      return "lavapipe: device lacks geometryShader (needed for gl_PrimitiveID in fragment shaders)";
    }
    std::uint32_t n = 0;
    vkEnumerateDeviceExtensionProperties(physical_, nullptr, &n, nullptr);
    std::vector<VkExtensionProperties> exts(n);
    vkEnumerateDeviceExtensionProperties(physical_, nullptr, &n, exts.data());
    has_line_ext_ = std::any_of(exts.begin(), exts.end(), [](const VkExtensionProperties& e) {
      return std::strcmp(e.extensionName, VK_EXT_LINE_RASTERIZATION_EXTENSION_NAME) == 0;
    });
    bresenham_ = has_line_ext_ && line.bresenhamLines == VK_TRUE;
    rectangular_ = has_line_ext_ && line.rectangularLines == VK_TRUE;
    smooth_ = has_line_ext_ && line.smoothLines == VK_TRUE;

    // Info (DRIVER.LAVAPIPE.DEVICE).
    const VkPhysicalDeviceLimits& lim = props_.limits;
    info_.name = "lavapipe";
    info_.description = detail::device_description(physical_, props_) + ", lines: " + (bresenham_ ? "bresenham " : "") +
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
    // K is a power of two with a viewport [-K, K]: 2K <= maxViewportDimensions and
    // [-K, K] inside viewportBoundsRange.
    const double max_dim = std::min(lim.maxViewportDimensions[0], lim.maxViewportDimensions[1]);
    const double bound = std::min(-static_cast<double>(lim.viewportBoundsRange[0]),
                                  static_cast<double>(lim.viewportBoundsRange[1]));
    max_k_ = detail::max_position_scale(max_dim, bound);
    const double fb = std::min(lim.maxFramebufferWidth, lim.maxFramebufferHeight);
    info_.max_target_side = static_cast<std::int32_t>(std::min(fb, max_k_));
    return {};
  }

  std::string create_device() {
    if (std::string why = detail::graphics_queue_family(physical_, &family_); !why.empty()) return why;
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
    if (std::string why = detail::create_device(physical_, family_, f2, has_line_ext_ ? 1U : 0U, &ext,
                                                &device_, &queue_);
        !why.empty()) {
      return why;
    }
    vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
    return {};
  }

  std::string create_shared() {
    if (std::string why = detail::create_submit_objects(
            device_, family_, VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT, &pool_, &cmd_, &fence_);
        !why.empty()) {
      return why;
    }
    VkDescriptorSetLayoutBinding binding{};
    binding.binding = 0;
    binding.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    binding.descriptorCount = 1;
    binding.stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT;
    VkDescriptorSetLayoutCreateInfo dli{};
    dli.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    dli.bindingCount = 1;
    dli.pBindings = &binding;
    if (VkResult r = vkCreateDescriptorSetLayout(device_, &dli, nullptr, &set_layout_); r != VK_SUCCESS) {
      return vk_failed("vkCreateDescriptorSetLayout", r);
    }
    VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(Push)};
    VkPipelineLayoutCreateInfo lci{};
    lci.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    lci.setLayoutCount = 1;
    lci.pSetLayouts = &set_layout_;
    lci.pushConstantRangeCount = 1;
    lci.pPushConstantRanges = &range;
    if (VkResult r = vkCreatePipelineLayout(device_, &lci, nullptr, &layout_); r != VK_SUCCESS) {
      return vk_failed("vkCreatePipelineLayout", r);
    }
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1};
    VkDescriptorPoolCreateInfo dpi{};
    dpi.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    dpi.maxSets = 1;
    dpi.poolSizeCount = 1;
    dpi.pPoolSizes = &size;
    if (VkResult r = vkCreateDescriptorPool(device_, &dpi, nullptr, &descriptor_pool_); r != VK_SUCCESS) {
      return vk_failed("vkCreateDescriptorPool", r);
    }
    VkDescriptorSetAllocateInfo dai{};
    dai.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    dai.descriptorPool = descriptor_pool_;
    dai.descriptorSetCount = 1;
    dai.pSetLayouts = &set_layout_;
    if (VkResult r = vkAllocateDescriptorSets(device_, &dai, &set_); r != VK_SUCCESS) {
      return vk_failed("vkAllocateDescriptorSets", r);
    }
    for (auto [code, bytes, module] :
         {std::tuple{kCoverage_vert, sizeof(kCoverage_vert), &vert_},
          std::tuple{kCoverage_frag, sizeof(kCoverage_frag), &frag_}}) {
      if (std::string why = detail::create_shader_module(device_, code, bytes, module); !why.empty()) {
        return why;
      }
    }
    // A render pass without attachments: coverage goes to the storage buffer only, and the
    // sample count is the pipeline's rasterizationSamples.
    if (std::string why = detail::create_attachmentless_render_pass(device_, &render_pass_);
        !why.empty()) {
      return why;
    }
    return {};
  }

  std::string ensure_buffer(HostBuffer& b, VkDeviceSize bytes, VkBufferUsageFlags usage) {
    if (b.size >= bytes) return {};
    // The previous command buffer has completed (each draw waits for its fence); wait anyway
    // before destroying a buffer a descriptor set may still name. The caller rebinds the
    // descriptor set after any reallocation: the new buffer may reuse the old handle value,
    // so comparing handles would leave the set pointing at freed memory.
    if (b.buffer != VK_NULL_HANDLE) {
      vkDeviceWaitIdle(device_);
      free_host_buffer(device_, &b);
    }
    VkDeviceSize size = 4096;
    while (size < bytes) size *= 2;
    return detail::create_host_buffer(device_, memory_, size, usage, &b);
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
    vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
  }

  std::string ensure_framebuffer(std::uint32_t w, std::uint32_t h) {
    if (framebuffer_ != VK_NULL_HANDLE && fb_w_ == w && fb_h_ == h) return {};
    if (framebuffer_ != VK_NULL_HANDLE) {
      vkDeviceWaitIdle(device_);
      vkDestroyFramebuffer(device_, framebuffer_, nullptr);
      framebuffer_ = VK_NULL_HANDLE;
    }
    VkFramebufferCreateInfo fci{};
    fci.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
    fci.renderPass = render_pass_;
    fci.width = w;
    fci.height = h;
    fci.layers = 1;
    if (VkResult r = vkCreateFramebuffer(device_, &fci, nullptr, &framebuffer_); r != VK_SUCCESS) {
      framebuffer_ = VK_NULL_HANDLE;
      return vk_failed("vkCreateFramebuffer", r);
    }
    fb_w_ = w;
    fb_h_ = h;
    return {};
  }

  void barrier(VkPipelineStageFlags src_stage, VkAccessFlags src, VkPipelineStageFlags dst_stage,
               VkAccessFlags dst) {
    VkMemoryBarrier mb{};
    mb.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    mb.srcAccessMask = src;
    mb.dstAccessMask = dst;
    vkCmdPipelineBarrier(cmd_, src_stage, dst_stage, 0, 1, &mb, 0, nullptr, 0, nullptr);
  }

  // Returns the cached pipeline for key, creating it on first use.
  std::variant<VkPipeline, std::string> get_pipeline(const PipelineKey& key) {
    if (auto it = pipelines_.find(key); it != pipelines_.end()) return it->second;
    const VkSampleMask mask = key.sample_mask;
    detail::CoveragePipelineState state;
    state.topology = key.topology;
    state.cull = key.cull;
    state.front = key.front;
    state.samples = key.samples;
    state.sample_mask = &mask;
    state.line_mode = key.line_mode;
    VkPipeline pipeline = VK_NULL_HANDLE;
    if (std::string why = detail::create_coverage_pipeline(device_, vert_, frag_, layout_, render_pass_,
                                                           state, &pipeline);
        !why.empty()) {
      return why;
    }
    pipelines_.emplace(key, pipeline);
    return pipeline;
  }

  void destroy() {
    if (device_ != VK_NULL_HANDLE) {
      vkDeviceWaitIdle(device_);
      for (auto& [key, p] : pipelines_) vkDestroyPipeline(device_, p, nullptr);
      pipelines_.clear();
      free_host_buffer(device_, &coverage_);
      free_host_buffer(device_, &vertex_);
      if (framebuffer_ != VK_NULL_HANDLE) vkDestroyFramebuffer(device_, framebuffer_, nullptr);
      if (render_pass_ != VK_NULL_HANDLE) vkDestroyRenderPass(device_, render_pass_, nullptr);
      if (vert_ != VK_NULL_HANDLE) vkDestroyShaderModule(device_, vert_, nullptr);
      if (frag_ != VK_NULL_HANDLE) vkDestroyShaderModule(device_, frag_, nullptr);
      if (descriptor_pool_ != VK_NULL_HANDLE) vkDestroyDescriptorPool(device_, descriptor_pool_, nullptr);
      if (layout_ != VK_NULL_HANDLE) vkDestroyPipelineLayout(device_, layout_, nullptr);
      if (set_layout_ != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(device_, set_layout_, nullptr);
      if (fence_ != VK_NULL_HANDLE) vkDestroyFence(device_, fence_, nullptr);
      if (pool_ != VK_NULL_HANDLE) vkDestroyCommandPool(device_, pool_, nullptr);
      vkDestroyDevice(device_, nullptr);
      device_ = VK_NULL_HANDLE;
    }
    if (instance_ != VK_NULL_HANDLE) {
      vkDestroyInstance(instance_, nullptr);
      instance_ = VK_NULL_HANDLE;
    }
  }

  VkInstance instance_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties props_{};
  VkPhysicalDeviceMemoryProperties memory_{};
  bool has_line_ext_ = false;
  bool bresenham_ = false;
  bool rectangular_ = false;
  bool smooth_ = false;
  std::uint32_t family_ = 0;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkDescriptorPool descriptor_pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  VkShaderModule vert_ = VK_NULL_HANDLE;
  VkShaderModule frag_ = VK_NULL_HANDLE;
  VkRenderPass render_pass_ = VK_NULL_HANDLE;
  VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
  std::uint32_t fb_w_ = 0;
  std::uint32_t fb_h_ = 0;
  HostBuffer coverage_;
  HostBuffer vertex_;
  VkDeviceSize bound_size_ = 0;  // coverage_.size when the descriptor set was last written
  std::map<PipelineKey, VkPipeline> pipelines_;
};

}  // namespace

namespace detail {

// rule: DRIVER.LAVAPIPE.DEVICE
std::unique_ptr<Driver> open_lavapipe(std::string_view arg, std::string* error) {
  return open_gpu_driver<LavapipeDriver>("lavapipe", arg, error);
}

}  // namespace detail
}  // namespace rastrules::driver

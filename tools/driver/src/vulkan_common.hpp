// SPDX-License-Identifier: MIT
// Private to the driver library: the Vulkan plumbing that the lavapipe adapter (lavapipe.cpp)
// and the lavapipe coverage timing (timing_lavapipe.cpp) share, written once: opening lavapipe
// (an instance and the CPU device named llvmpipe) with its device, queue, command buffer and
// fence (LavapipeContext); host-visible buffers and the vertex upload; the coverage.vert program
// with its pipeline layout, attachmentless render pass, framebuffer and pipelines
// (CoverageProgram); command recording with the exact viewport transform; submit-and-wait; the
// device's limit on K; the device description. Every function returning a string returns "" on
// success or the reason it failed.
// Implements: DRIVER.LAVAPIPE.DEVICE, DRIVER.LAVAPIPE.POSITION

#pragma once

#include <vulkan/vulkan.h>

#include "rastrules/triangle.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace rastrules::driver::detail {

// The push constants of shaders/coverage.vert and coverage.frag (layout order): positions are
// divided by K in the vertex shader (DRIVER.LAVAPIPE.POSITION); slot, width, height and slots
// address the coverage buffer (DRIVER.LAVAPIPE.COVERAGE).
struct CoveragePush {
  float inv_k = 1.0F;
  std::uint32_t slot = 0;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint32_t slots = 0;
};

// "lavapipe: WHAT failed (VkResult N)".
[[nodiscard]] std::string vk_failed(const char* what, VkResult r);

// Creates a Vulkan 1.2 instance and selects the CPU device named llvmpipe (lavapipe). On
// failure *instance is VK_NULL_HANDLE or an instance the caller destroys.
// rule: DRIVER.LAVAPIPE.DEVICE
[[nodiscard]] std::string open_lavapipe_instance(VkInstance* instance, VkPhysicalDevice* physical,
                                                 VkPhysicalDeviceProperties* props);

// The first queue family with graphics.
[[nodiscard]] std::string graphics_queue_family(VkPhysicalDevice physical, std::uint32_t* family);

// "NAME, DRIVER DRIVER-INFO, Vulkan X.Y.Z" of the device.
[[nodiscard]] std::string device_description(VkPhysicalDevice physical,
                                             const VkPhysicalDeviceProperties& props);

// A buffer in host-visible, coherent memory, mapped for its whole life.
struct HostBuffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize size = 0;
  void* mapped = nullptr;
};

// Creates *b (which must be empty) with `size` bytes and the usage; on failure *b is empty.
[[nodiscard]] std::string create_host_buffer(VkDevice device,
                                             const VkPhysicalDeviceMemoryProperties& memory,
                                             VkDeviceSize size, VkBufferUsageFlags usage,
                                             HostBuffer* b);

// Unmaps and frees *b (nothing when it is empty) and leaves it empty.
void free_host_buffer(VkDevice device, HostBuffer* b);

// Creates a logical device with one queue of `family`, the features in *features (pNext chain
// included) and the extensions, and gets its queue. On failure *device is VK_NULL_HANDLE.
[[nodiscard]] std::string create_device(VkPhysicalDevice physical, std::uint32_t family,
                                        const VkPhysicalDeviceFeatures2& features,
                                        std::uint32_t extension_count,
                                        const char* const* extensions, VkDevice* device,
                                        VkQueue* queue);

// A command pool of `family` (with `flags`), one primary command buffer and one fence: what
// every draw submits and waits on.
[[nodiscard]] std::string create_submit_objects(VkDevice device, std::uint32_t family,
                                                VkCommandPoolCreateFlags flags, VkCommandPool* pool,
                                                VkCommandBuffer* cmd, VkFence* fence);

// A shader module from SPIR-V words (bytes is the size in bytes).
[[nodiscard]] std::string create_shader_module(VkDevice device, const std::uint32_t* code,
                                               std::size_t bytes, VkShaderModule* module);

// A render pass of one graphics subpass without attachments: the sample count is the
// pipeline's rasterizationSamples, and results leave through buffers or queries.
[[nodiscard]] std::string create_attachmentless_render_pass(VkDevice device, VkRenderPass* pass);

// Floats per vertex of the values program: the position and 16 attributes (pipe::kMaxAttributes).
inline constexpr std::uint32_t kValuesStride = 20;

// What differs between the adapter's pipelines and the timing's one. The vertex input is one
// binding of float32 (x, y) pairs, or the values program's vertices; viewport and scissor are
// dynamic.
struct CoveragePipelineState {
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkCullModeFlags cull = VK_CULL_MODE_NONE;
  VkFrontFace front = VK_FRONT_FACE_CLOCKWISE;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  std::optional<VkSampleMask> sample_mask; // none: pSampleMask is null (every sample)
  VkLineRasterizationModeEXT line_mode = VK_LINE_RASTERIZATION_MODE_DEFAULT_EXT;
  // The values program of pipeline scenes (DRIVER.LAVAPIPE.VALUES): vertices of kValuesStride
  // floats (a position of four, then 16 attributes as four vec4), the last vertex provoking
  // (VK_EXT_provoking_vertex), depth clamping instead of depth clipping, and a depth test that
  // always passes and writes (the depth passes, which have a depth attachment).
  bool values_layout = false;
  bool provoking_last = false;
  bool depth_clamp = false;
  bool depth_write = false;
  // Depth bias enabled, its three terms dynamic state (vkCmdSetDepthBias; PIPE.DEPTH.BIAS).
  bool depth_bias = false;
  // Sample-rate shading (sampleShadingEnable, minSampleShading 1; MSAA.SHADING.SAMPLE).
  bool sample_shading = false;

  // An order, so that the state can key a cache of pipelines.
  [[nodiscard]] auto tie() const {
    return std::make_tuple(static_cast<int>(topology), static_cast<int>(line_mode),
                           static_cast<int>(samples), cull, static_cast<int>(front), sample_mask,
                           values_layout, provoking_last, depth_clamp, depth_write, depth_bias,
                           sample_shading);
  }
  friend bool operator<(const CoveragePipelineState& a, const CoveragePipelineState& b) {
    return a.tie() < b.tie();
  }
};

// Begins `pass` on `framebuffer` over the w x h target and sets the dynamic state: the scissor
// to the target and the viewport of side 2K centred on the origin that brings the shader's
// positions (x / K, y / K) back to window coordinates exactly (DRIVER.LAVAPIPE.POSITION).
// rule: DRIVER.LAVAPIPE.POSITION
void begin_target_pass(VkCommandBuffer cmd, VkRenderPass pass, VkFramebuffer framebuffer,
                       std::uint32_t w, std::uint32_t h, double k);

// Submits cmd to queue with fence, waits for the fence and resets it.
[[nodiscard]] std::string submit_and_wait(VkDevice device, VkQueue queue, VkCommandBuffer cmd,
                                          VkFence fence);

// The scene's culling as Vulkan state: both are y-down, so the on-screen winding maps directly.
[[nodiscard]] VkCullModeFlags vk_cull_mode(CullMode cull);
[[nodiscard]] VkFrontFace vk_front_face(FrontFace front);

// A graphics pipeline of the two shaders for the state, in `layout` and `pass`.
[[nodiscard]] std::string create_coverage_pipeline(VkDevice device, VkShaderModule vert,
                                                   VkShaderModule frag, VkPipelineLayout layout,
                                                   VkRenderPass pass,
                                                   const CoveragePipelineState& state,
                                                   VkPipeline* pipeline);

// Grows *b (with `usage`) to at least `bytes`: nothing when it is large enough, else (after the
// device is idle, as a descriptor set or command buffer may still name it) frees it and creates
// one of the next power of two >= max(bytes, 4096). A caller that points a descriptor set at the
// buffer rebinds it whenever b->size changes: the new buffer may reuse the old handle value.
[[nodiscard]] std::string ensure_host_buffer(VkDevice device,
                                             const VkPhysicalDeviceMemoryProperties& memory,
                                             VkDeviceSize bytes, VkBufferUsageFlags usage,
                                             HostBuffer* b);

// The largest K of a viewport [-K, K] that the device's limits allow (max_position_scale of
// maxViewportDimensions and viewportBoundsRange).
// rule: DRIVER.LAVAPIPE.POSITION
[[nodiscard]] double max_position_scale(const VkPhysicalDeviceLimits& lim);

// Begins cmd (in the initial state) with `flags`.
[[nodiscard]] std::string begin_commands(VkCommandBuffer cmd, VkCommandBufferUsageFlags flags);

// Opened lavapipe: the instance, the CPU device, its logical device and graphics queue, and the
// one command buffer and fence that every draw records, submits and waits on. destroy()
// destroys what was created, the device's children first; the owner destroys what it created
// on the device (after vkDeviceWaitIdle) before that.
struct LavapipeContext {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties props{};
  VkPhysicalDeviceMemoryProperties memory{};
  std::uint32_t family = 0;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;

  // open_lavapipe_instance().
  // rule: DRIVER.LAVAPIPE.DEVICE
  [[nodiscard]] std::string open();
  // The graphics queue family, the logical device with the features and extensions
  // (create_device()), its memory properties, and the command pool (with `pool_flags`), command
  // buffer and fence.
  [[nodiscard]] std::string create_device(const VkPhysicalDeviceFeatures2& features,
                                          std::uint32_t extension_count,
                                          const char* const* extensions,
                                          VkCommandPoolCreateFlags pool_flags);
  // submit_and_wait() of cmd.
  [[nodiscard]] std::string submit_and_wait() const;
  // The vertex buffer *b holds the float32 (x, y) pairs: grown by ensure_host_buffer(), then
  // written.
  [[nodiscard]] std::string upload_vertices(const std::vector<float>& vertices,
                                            HostBuffer* b) const;
  void destroy();
};

// What draws through coverage.vert share: its shader module and a fragment shader's, the
// pipeline layout (the CoveragePush range for push_stages, and an optional descriptor set
// layout), the attachmentless render pass, a framebuffer of the target's size, and the
// pipelines of that program.
struct CoverageProgram {
  VkShaderModule vert = VK_NULL_HANDLE;
  VkShaderModule frag = VK_NULL_HANDLE;
  VkShaderStageFlags push_stages = 0;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  std::uint32_t width = 0;
  std::uint32_t height = 0;

  // Creates the modules (coverage.vert and the fragment shader's SPIR-V, `frag_bytes` bytes),
  // the layout and the render pass. set_layout may be VK_NULL_HANDLE (no descriptor set).
  [[nodiscard]] std::string create(VkDevice device, const std::uint32_t* frag_code,
                                   std::size_t frag_bytes, VkShaderStageFlags stages,
                                   VkDescriptorSetLayout set_layout);
  // A framebuffer of w x h: kept when it has that size, else (after the device is idle)
  // replaced.
  [[nodiscard]] std::string ensure_framebuffer(VkDevice device, std::uint32_t w, std::uint32_t h);
  // create_coverage_pipeline() of this program's shaders, layout and render pass.
  [[nodiscard]] std::string create_pipeline(VkDevice device, const CoveragePipelineState& state,
                                            VkPipeline* pipeline) const;
  // Begins the render pass over the framebuffer with the exact viewport transform
  // (begin_target_pass) and binds `vertices` as the vertex buffer.
  // rule: DRIVER.LAVAPIPE.POSITION
  void begin_pass(VkCommandBuffer cmd, VkBuffer vertices, double k) const;
  // Pushes the constants to push_stages.
  void push(VkCommandBuffer cmd, const CoveragePush& constants) const;
  void destroy(VkDevice device);
};

} // namespace rastrules::driver::detail

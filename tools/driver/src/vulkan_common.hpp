// SPDX-License-Identifier: MIT
// Private to the driver library: the Vulkan pieces that the lavapipe adapter (lavapipe.cpp)
// and the lavapipe coverage timing (timing_lavapipe.cpp) share: opening lavapipe (an instance
// and the CPU device named llvmpipe), the graphics queue family, host-visible buffers and the
// device description. Every function returns "" on success or the reason it failed.
// Implements: DRIVER.LAVAPIPE.DEVICE

#pragma once

#include <vulkan/vulkan.h>

#include "rastrules/triangle.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

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
                                        std::uint32_t extension_count, const char* const* extensions,
                                        VkDevice* device, VkQueue* queue);

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

// What differs between the adapter's pipelines and the timing's one. The vertex input is always
// one binding of float32 (x, y) pairs; viewport and scissor are dynamic.
struct CoveragePipelineState {
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkCullModeFlags cull = VK_CULL_MODE_NONE;
  VkFrontFace front = VK_FRONT_FACE_CLOCKWISE;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  const VkSampleMask* sample_mask = nullptr;  // nullptr: every sample
  VkLineRasterizationModeEXT line_mode = VK_LINE_RASTERIZATION_MODE_DEFAULT_EXT;
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

}  // namespace rastrules::driver::detail

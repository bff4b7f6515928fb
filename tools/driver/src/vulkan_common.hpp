// SPDX-License-Identifier: MIT
// Private to the driver library: the Vulkan pieces that the lavapipe adapter (lavapipe.cpp)
// and the lavapipe coverage timing (timing_lavapipe.cpp) share: opening lavapipe (an instance
// and the CPU device named llvmpipe), the graphics queue family, host-visible buffers and the
// device description. Every function returns "" on success or the reason it failed.
// Implements: DRIVER.LAVAPIPE.DEVICE

#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

namespace rastrules::driver::detail {

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

}  // namespace rastrules::driver::detail

// SPDX-License-Identifier: MIT
// What the Vulkan users of the driver library share: see vulkan_common.hpp.

#include "vulkan_common.hpp"

#include <dlfcn.h>

#include <string_view>
#include <vector>

namespace rastrules::driver::detail {

std::string vk_failed(const char* what, VkResult r) {
  return std::string("lavapipe: ") + what + " failed (VkResult " +
         std::to_string(static_cast<int>(r)) + ")";
}

// rule: DRIVER.LAVAPIPE.DEVICE
std::string open_lavapipe_instance(VkInstance* instance, VkPhysicalDevice* physical,
                                   VkPhysicalDeviceProperties* props) {
  VkApplicationInfo app{};
  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.pApplicationName = "rastrules";
  app.apiVersion = VK_API_VERSION_1_2;
  VkInstanceCreateInfo ici{};
  ici.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  ici.pApplicationInfo = &app;
  if (VkResult r = vkCreateInstance(&ici, nullptr, instance); r != VK_SUCCESS) {
    *instance = VK_NULL_HANDLE;
    return vk_failed("vkCreateInstance (is a Vulkan loader installed?)", r);
  }
  std::uint32_t n = 0;
  vkEnumeratePhysicalDevices(*instance, &n, nullptr);
  std::vector<VkPhysicalDevice> devices(n);
  vkEnumeratePhysicalDevices(*instance, &n, devices.data());
  std::string seen;
  *physical = VK_NULL_HANDLE;
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties p{};
    vkGetPhysicalDeviceProperties(d, &p);
    seen += std::string(seen.empty() ? "" : ", ") + p.deviceName;
    if (p.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU &&
        std::string_view(p.deviceName).find("llvmpipe") != std::string_view::npos) {
      *physical = d;
      *props = p;
      break;
    }
  }
  if (*physical == VK_NULL_HANDLE) {
    return "lavapipe: no CPU Vulkan device named llvmpipe (install mesa-vulkan-drivers); devices: " +
           (seen.empty() ? std::string("none") : seen);
  }
  // Keep Mesa's ICD loaded for the life of the process: the loader unloads it with the last
  // instance, and its process-wide state (LLVM, caches) is not meant to be torn down and
  // rebuilt by every driver that is opened and closed (it shows as leaks under
  // LeakSanitizer). Only marks the already loaded library; does nothing if it is not.
  static void* const pinned = dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
  (void)pinned;
  return {};
}

std::string graphics_queue_family(VkPhysicalDevice physical, std::uint32_t* family) {
  std::uint32_t n = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &n, nullptr);
  std::vector<VkQueueFamilyProperties> families(n);
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &n, families.data());
  for (std::uint32_t i = 0; i < n; ++i) {
    if ((families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) != 0U) {
      *family = i;
      return {};
    }
  }
  return "lavapipe: no graphics queue";
}

std::string device_description(VkPhysicalDevice physical, const VkPhysicalDeviceProperties& props) {
  VkPhysicalDeviceDriverProperties drv{};
  drv.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES;
  VkPhysicalDeviceProperties2 p2{};
  p2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
  p2.pNext = &drv;
  vkGetPhysicalDeviceProperties2(physical, &p2);
  return std::string(props.deviceName) + ", " + drv.driverName + " " + drv.driverInfo +
         ", Vulkan " + std::to_string(VK_API_VERSION_MAJOR(props.apiVersion)) + "." +
         std::to_string(VK_API_VERSION_MINOR(props.apiVersion)) + "." +
         std::to_string(VK_API_VERSION_PATCH(props.apiVersion));
}

std::string create_host_buffer(VkDevice device, const VkPhysicalDeviceMemoryProperties& memory,
                               VkDeviceSize size, VkBufferUsageFlags usage, HostBuffer* b) {
  VkBufferCreateInfo bci{};
  bci.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  bci.size = size;
  bci.usage = usage;
  bci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  if (VkResult r = vkCreateBuffer(device, &bci, nullptr, &b->buffer); r != VK_SUCCESS) {
    b->buffer = VK_NULL_HANDLE;
    return vk_failed("vkCreateBuffer", r);
  }
  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(device, b->buffer, &req);
  const VkMemoryPropertyFlags want =
      VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  std::uint32_t type = memory.memoryTypeCount;
  for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
    if ((req.memoryTypeBits & (1U << i)) != 0U && (memory.memoryTypes[i].propertyFlags & want) == want) {
      type = i;
      break;
    }
  }
  if (type == memory.memoryTypeCount) {
    free_host_buffer(device, b);
    return "lavapipe: no host-visible coherent memory";
  }
  VkMemoryAllocateInfo mai{};
  mai.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  mai.allocationSize = req.size;
  mai.memoryTypeIndex = type;
  if (VkResult r = vkAllocateMemory(device, &mai, nullptr, &b->memory); r != VK_SUCCESS) {
    b->memory = VK_NULL_HANDLE;
    free_host_buffer(device, b);
    return vk_failed("vkAllocateMemory", r);
  }
  vkBindBufferMemory(device, b->buffer, b->memory, 0);
  if (VkResult r = vkMapMemory(device, b->memory, 0, VK_WHOLE_SIZE, 0, &b->mapped); r != VK_SUCCESS) {
    b->mapped = nullptr;
    free_host_buffer(device, b);
    return vk_failed("vkMapMemory", r);
  }
  b->size = size;
  return {};
}

void free_host_buffer(VkDevice device, HostBuffer* b) {
  if (b->mapped != nullptr) vkUnmapMemory(device, b->memory);
  if (b->buffer != VK_NULL_HANDLE) vkDestroyBuffer(device, b->buffer, nullptr);
  if (b->memory != VK_NULL_HANDLE) vkFreeMemory(device, b->memory, nullptr);
  *b = HostBuffer{};
}

}  // namespace rastrules::driver::detail

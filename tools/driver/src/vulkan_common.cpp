// SPDX-License-Identifier: MIT
// What the Vulkan users of the driver library share: see vulkan_common.hpp.

#include "vulkan_common.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cstring>
#include <string_view>
#include <vector>

#include "gpu_common.hpp"
#include "rastrules/driver/coverage_vert.spv.h"

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
    return "lavapipe: no CPU Vulkan device named llvmpipe (install mesa-vulkan-drivers); "
           "devices: " +
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
    if ((req.memoryTypeBits & (1U << i)) != 0U &&
        (memory.memoryTypes[i].propertyFlags & want) == want) {
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
  if (VkResult r = vkMapMemory(device, b->memory, 0, VK_WHOLE_SIZE, 0, &b->mapped);
      r != VK_SUCCESS) {
    b->mapped = nullptr;
    free_host_buffer(device, b);
    return vk_failed("vkMapMemory", r);
  }
  b->size = size;
  return {};
}

void free_host_buffer(VkDevice device, HostBuffer* b) {
  if (b->mapped != nullptr)
    vkUnmapMemory(device, b->memory);
  if (b->buffer != VK_NULL_HANDLE)
    vkDestroyBuffer(device, b->buffer, nullptr);
  if (b->memory != VK_NULL_HANDLE)
    vkFreeMemory(device, b->memory, nullptr);
  *b = HostBuffer{};
}

std::string create_device(VkPhysicalDevice physical, std::uint32_t family,
                          const VkPhysicalDeviceFeatures2& features, std::uint32_t extension_count,
                          const char* const* extensions, VkDevice* device, VkQueue* queue) {
  const float priority = 1.0F;
  VkDeviceQueueCreateInfo qci{};
  qci.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  qci.queueFamilyIndex = family;
  qci.queueCount = 1;
  qci.pQueuePriorities = &priority;
  VkDeviceCreateInfo dci{};
  dci.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  dci.pNext = &features;
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  dci.enabledExtensionCount = extension_count;
  dci.ppEnabledExtensionNames = extension_count > 0 ? extensions : nullptr;
  if (VkResult r = vkCreateDevice(physical, &dci, nullptr, device); r != VK_SUCCESS) {
    *device = VK_NULL_HANDLE;
    return vk_failed("vkCreateDevice", r);
  }
  vkGetDeviceQueue(*device, family, 0, queue);
  return {};
}

std::string create_submit_objects(VkDevice device, std::uint32_t family,
                                  VkCommandPoolCreateFlags flags, VkCommandPool* pool,
                                  VkCommandBuffer* cmd, VkFence* fence) {
  VkCommandPoolCreateInfo pci{};
  pci.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
  pci.flags = flags;
  pci.queueFamilyIndex = family;
  if (VkResult r = vkCreateCommandPool(device, &pci, nullptr, pool); r != VK_SUCCESS) {
    return vk_failed("vkCreateCommandPool", r);
  }
  VkCommandBufferAllocateInfo cai{};
  cai.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  cai.commandPool = *pool;
  cai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  cai.commandBufferCount = 1;
  if (VkResult r = vkAllocateCommandBuffers(device, &cai, cmd); r != VK_SUCCESS) {
    return vk_failed("vkAllocateCommandBuffers", r);
  }
  VkFenceCreateInfo fci{};
  fci.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
  if (VkResult r = vkCreateFence(device, &fci, nullptr, fence); r != VK_SUCCESS) {
    return vk_failed("vkCreateFence", r);
  }
  return {};
}

std::string create_shader_module(VkDevice device, const std::uint32_t* code, std::size_t bytes,
                                 VkShaderModule* module) {
  VkShaderModuleCreateInfo sci{};
  sci.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  sci.codeSize = bytes;
  sci.pCode = code;
  if (VkResult r = vkCreateShaderModule(device, &sci, nullptr, module); r != VK_SUCCESS) {
    *module = VK_NULL_HANDLE;
    return vk_failed("vkCreateShaderModule", r);
  }
  return {};
}

std::string create_attachmentless_render_pass(VkDevice device, VkRenderPass* pass) {
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  VkRenderPassCreateInfo rci{};
  rci.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
  rci.subpassCount = 1;
  rci.pSubpasses = &subpass;
  if (VkResult r = vkCreateRenderPass(device, &rci, nullptr, pass); r != VK_SUCCESS) {
    return vk_failed("vkCreateRenderPass", r);
  }
  return {};
}

std::string create_coverage_pipeline(VkDevice device, VkShaderModule vert, VkShaderModule frag,
                                     VkPipelineLayout layout, VkRenderPass pass,
                                     const CoveragePipelineState& state, VkPipeline* pipeline) {
  VkPipelineShaderStageCreateInfo stages[2]{};
  stages[0].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vert;
  stages[0].pName = "main";
  stages[1] = stages[0];
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = frag;
  VkVertexInputBindingDescription vb{0, 2 * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX};
  std::vector<VkVertexInputAttributeDescription> va{{0, 0, VK_FORMAT_R32G32_SFLOAT, 0}};
  if (state.values_layout) {
    // rule: DRIVER.LAVAPIPE.VALUES
    vb.stride = kValuesStride * sizeof(float);
    va.clear();
    for (std::uint32_t i = 0; i < kValuesStride / 4; ++i)
      va.push_back({i, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 16U * i});
  }
  VkPipelineVertexInputStateCreateInfo vi{};
  vi.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
  vi.vertexBindingDescriptionCount = 1;
  vi.pVertexBindingDescriptions = &vb;
  vi.vertexAttributeDescriptionCount = static_cast<std::uint32_t>(va.size());
  vi.pVertexAttributeDescriptions = va.data();
  VkPipelineInputAssemblyStateCreateInfo ia{};
  ia.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
  ia.topology = state.topology;
  VkPipelineViewportStateCreateInfo vp{};
  vp.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
  vp.viewportCount = 1;
  vp.scissorCount = 1;
  VkPipelineRasterizationLineStateCreateInfoEXT line{};
  line.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_LINE_STATE_CREATE_INFO_EXT;
  line.lineRasterizationMode = state.line_mode;
  VkPipelineRasterizationProvokingVertexStateCreateInfoEXT provoking{};
  provoking.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_PROVOKING_VERTEX_STATE_CREATE_INFO_EXT;
  provoking.provokingVertexMode = VK_PROVOKING_VERTEX_MODE_LAST_VERTEX_EXT;
  VkPipelineRasterizationStateCreateInfo rs{};
  rs.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
  const void* chain = nullptr;
  if (state.provoking_last) {
    provoking.pNext = chain;
    chain = &provoking;
  }
  if (state.line_mode != VK_LINE_RASTERIZATION_MODE_DEFAULT_EXT) {
    line.pNext = chain;
    chain = &line;
  }
  rs.pNext = chain;
  rs.depthClampEnable = state.depth_clamp ? VK_TRUE : VK_FALSE;
  rs.depthBiasEnable = state.depth_bias ? VK_TRUE : VK_FALSE;
  rs.polygonMode = VK_POLYGON_MODE_FILL;
  rs.cullMode = state.cull;
  rs.frontFace = state.front;
  rs.lineWidth = 1.0F;
  VkPipelineMultisampleStateCreateInfo ms{};
  ms.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
  ms.rasterizationSamples = state.samples;
  ms.pSampleMask = state.sample_mask.has_value() ? &*state.sample_mask : nullptr;
  ms.sampleShadingEnable = state.sample_shading ? VK_TRUE : VK_FALSE;
  ms.minSampleShading = state.sample_shading ? 1.0F : 0.0F;
  const VkDynamicState dyn[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR,
                                VK_DYNAMIC_STATE_DEPTH_BIAS};
  VkPipelineDynamicStateCreateInfo ds{};
  ds.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO;
  ds.dynamicStateCount = state.depth_bias ? 3U : 2U;
  ds.pDynamicStates = dyn;
  VkGraphicsPipelineCreateInfo gci{};
  gci.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
  gci.stageCount = 2;
  gci.pStages = stages;
  gci.pVertexInputState = &vi;
  gci.pInputAssemblyState = &ia;
  gci.pViewportState = &vp;
  gci.pRasterizationState = &rs;
  gci.pMultisampleState = &ms;
  VkPipelineDepthStencilStateCreateInfo dss{};
  dss.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
  dss.depthTestEnable = VK_TRUE;
  dss.depthWriteEnable = VK_TRUE;
  dss.depthCompareOp = VK_COMPARE_OP_ALWAYS;
  gci.pDepthStencilState = state.depth_write ? &dss : nullptr;
  gci.pDynamicState = &ds;
  gci.layout = layout;
  gci.renderPass = pass;
  if (VkResult r = vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &gci, nullptr, pipeline);
      r != VK_SUCCESS) {
    *pipeline = VK_NULL_HANDLE;
    return vk_failed("vkCreateGraphicsPipelines", r);
  }
  return {};
}

// rule: DRIVER.LAVAPIPE.POSITION
void begin_target_pass(VkCommandBuffer cmd, VkRenderPass pass, VkFramebuffer framebuffer,
                       std::uint32_t w, std::uint32_t h, double k) {
  VkRenderPassBeginInfo rpb{};
  rpb.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
  rpb.renderPass = pass;
  rpb.framebuffer = framebuffer;
  rpb.renderArea = {{0, 0}, {w, h}};
  vkCmdBeginRenderPass(cmd, &rpb, VK_SUBPASS_CONTENTS_INLINE);
  const auto kf = static_cast<float>(k);
  const VkViewport viewport{-kf, -kf, 2.0F * kf, 2.0F * kf, 0.0F, 1.0F};
  const VkRect2D scissor{{0, 0}, {w, h}};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
}

std::string submit_and_wait(VkDevice device, VkQueue queue, VkCommandBuffer cmd, VkFence fence) {
  VkSubmitInfo submit{};
  submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  if (VkResult r = vkQueueSubmit(queue, 1, &submit, fence); r != VK_SUCCESS) {
    return vk_failed("vkQueueSubmit", r);
  }
  const VkResult waited = vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX);
  vkResetFences(device, 1, &fence);
  if (waited != VK_SUCCESS)
    return vk_failed("vkWaitForFences", waited);
  return {};
}

VkCullModeFlags vk_cull_mode(CullMode cull) {
  return cull == CullMode::kBack    ? VK_CULL_MODE_BACK_BIT
         : cull == CullMode::kFront ? VK_CULL_MODE_FRONT_BIT
                                    : VK_CULL_MODE_NONE;
}

VkFrontFace vk_front_face(FrontFace front) {
  return front == FrontFace::kClockwise ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE;
}

std::string ensure_host_buffer(VkDevice device, const VkPhysicalDeviceMemoryProperties& memory,
                               VkDeviceSize bytes, VkBufferUsageFlags usage, HostBuffer* b) {
  if (b->size >= bytes)
    return {};
  if (b->buffer != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(device);
    free_host_buffer(device, b);
  }
  VkDeviceSize size = 4096;
  while (size < bytes)
    size *= 2;
  return create_host_buffer(device, memory, size, usage, b);
}

// rule: DRIVER.LAVAPIPE.POSITION
double max_position_scale(const VkPhysicalDeviceLimits& lim) {
  // K is a power of two with a viewport [-K, K]: 2K <= maxViewportDimensions and [-K, K]
  // inside viewportBoundsRange.
  const double max_dim = std::min(lim.maxViewportDimensions[0], lim.maxViewportDimensions[1]);
  const double bound = std::min(-static_cast<double>(lim.viewportBoundsRange[0]),
                                static_cast<double>(lim.viewportBoundsRange[1]));
  return max_position_scale(max_dim, bound);
}

std::string begin_commands(VkCommandBuffer cmd, VkCommandBufferUsageFlags flags) {
  VkCommandBufferBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  begin.flags = flags;
  if (VkResult r = vkBeginCommandBuffer(cmd, &begin); r != VK_SUCCESS) {
    return vk_failed("vkBeginCommandBuffer", r);
  }
  return {};
}

// rule: DRIVER.LAVAPIPE.DEVICE
std::string LavapipeContext::open() {
  return open_lavapipe_instance(&instance, &physical, &props);
}

std::string LavapipeContext::create_device(const VkPhysicalDeviceFeatures2& features,
                                           std::uint32_t extension_count,
                                           const char* const* extensions,
                                           VkCommandPoolCreateFlags pool_flags) {
  if (std::string why = graphics_queue_family(physical, &family); !why.empty())
    return why;
  if (std::string why = detail::create_device(physical, family, features, extension_count,
                                              extensions, &device, &queue);
      !why.empty()) {
    return why;
  }
  vkGetPhysicalDeviceMemoryProperties(physical, &memory);
  return create_submit_objects(device, family, pool_flags, &pool, &cmd, &fence);
}

std::string LavapipeContext::submit_and_wait() const {
  return detail::submit_and_wait(device, queue, cmd, fence);
}

std::string LavapipeContext::upload_vertices(const std::vector<float>& vertices,
                                             HostBuffer* b) const {
  const VkDeviceSize bytes = vertices.size() * sizeof(float);
  if (std::string why = ensure_host_buffer(device, memory, std::max<VkDeviceSize>(bytes, 8),
                                           VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, b);
      !why.empty()) {
    return why;
  }
  if (!vertices.empty())
    std::memcpy(b->mapped, vertices.data(), bytes);
  return {};
}

void LavapipeContext::destroy() {
  if (device != VK_NULL_HANDLE) {
    if (fence != VK_NULL_HANDLE)
      vkDestroyFence(device, fence, nullptr);
    if (pool != VK_NULL_HANDLE)
      vkDestroyCommandPool(device, pool, nullptr);
    vkDestroyDevice(device, nullptr);
  }
  if (instance != VK_NULL_HANDLE)
    vkDestroyInstance(instance, nullptr);
  *this = LavapipeContext{};
}

std::string CoverageProgram::create(VkDevice device, const std::uint32_t* frag_code,
                                    std::size_t frag_bytes, VkShaderStageFlags stages,
                                    VkDescriptorSetLayout set_layout) {
  if (std::string why = create_shader_module(device, kCoverage_vert, sizeof(kCoverage_vert), &vert);
      !why.empty()) {
    return why;
  }
  if (std::string why = create_shader_module(device, frag_code, frag_bytes, &frag); !why.empty()) {
    return why;
  }
  push_stages = stages;
  const VkPushConstantRange range{push_stages, 0, sizeof(CoveragePush)};
  VkPipelineLayoutCreateInfo lci{};
  lci.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  lci.setLayoutCount = set_layout != VK_NULL_HANDLE ? 1U : 0U;
  lci.pSetLayouts = set_layout != VK_NULL_HANDLE ? &set_layout : nullptr;
  lci.pushConstantRangeCount = 1;
  lci.pPushConstantRanges = &range;
  if (VkResult r = vkCreatePipelineLayout(device, &lci, nullptr, &layout); r != VK_SUCCESS) {
    layout = VK_NULL_HANDLE;
    return vk_failed("vkCreatePipelineLayout", r);
  }
  // Without attachments: results leave through buffers or queries, and the sample count is
  // the pipeline's rasterizationSamples.
  return create_attachmentless_render_pass(device, &render_pass);
}

std::string CoverageProgram::ensure_framebuffer(VkDevice device, std::uint32_t w, std::uint32_t h) {
  if (framebuffer != VK_NULL_HANDLE && width == w && height == h)
    return {};
  if (framebuffer != VK_NULL_HANDLE) {
    vkDeviceWaitIdle(device);
    vkDestroyFramebuffer(device, framebuffer, nullptr);
    framebuffer = VK_NULL_HANDLE;
  }
  VkFramebufferCreateInfo fci{};
  fci.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
  fci.renderPass = render_pass;
  fci.width = w;
  fci.height = h;
  fci.layers = 1;
  if (VkResult r = vkCreateFramebuffer(device, &fci, nullptr, &framebuffer); r != VK_SUCCESS) {
    framebuffer = VK_NULL_HANDLE;
    return vk_failed("vkCreateFramebuffer", r);
  }
  width = w;
  height = h;
  return {};
}

std::string CoverageProgram::create_pipeline(VkDevice device, const CoveragePipelineState& state,
                                             VkPipeline* pipeline) const {
  return create_coverage_pipeline(device, vert, frag, layout, render_pass, state, pipeline);
}

// rule: DRIVER.LAVAPIPE.POSITION
void CoverageProgram::begin_pass(VkCommandBuffer cmd, VkBuffer vertices, double k) const {
  begin_target_pass(cmd, render_pass, framebuffer, width, height, k);
  const VkDeviceSize zero = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &zero);
}

void CoverageProgram::push(VkCommandBuffer cmd, const CoveragePush& constants) const {
  vkCmdPushConstants(cmd, layout, push_stages, 0, sizeof(CoveragePush), &constants);
}

void CoverageProgram::destroy(VkDevice device) {
  if (framebuffer != VK_NULL_HANDLE)
    vkDestroyFramebuffer(device, framebuffer, nullptr);
  if (render_pass != VK_NULL_HANDLE)
    vkDestroyRenderPass(device, render_pass, nullptr);
  if (vert != VK_NULL_HANDLE)
    vkDestroyShaderModule(device, vert, nullptr);
  if (frag != VK_NULL_HANDLE)
    vkDestroyShaderModule(device, frag, nullptr);
  if (layout != VK_NULL_HANDLE)
    vkDestroyPipelineLayout(device, layout, nullptr);
  *this = CoverageProgram{};
}

} // namespace rastrules::driver::detail

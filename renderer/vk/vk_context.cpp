#include "renderer/vk/vk_context.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <type_traits>

#include "renderer/vk/compute_pipeline.h"
#include "renderer/vk/vk_check.h"

namespace raylab {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

int deviceRank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
    default: return 4;
  }
}

std::vector<VkPhysicalDevice> enumerateDevices(VkInstance instance) {
  uint32_t count = 0;
  VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
  return devices;
}

}  // namespace

VulkanContext::VulkanContext(const ContextOptions& options) {
  createInstance(options);
  pickPhysicalDevice(options);
  createDevice(options);
  if (!options.quiet) {
    const std::string validation = options.validation == ValidationMode::Off
                                       ? ""
                                       : std::string(", validation on (") + validationModeName(options.validation) + ")";
    std::fprintf(stderr, "raylab: device %s (%s), subgroup %u%s\n", info_.name.c_str(), info_.driver.c_str(),
                 info_.subgroupSize, validation.c_str());
  }
}

VulkanContext::~VulkanContext() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    vkDestroyFence(device_, fence_, nullptr);
    vkDestroyCommandPool(device_, commandPool_, nullptr);
    vkDestroyDevice(device_, nullptr);
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
  }
  if (instance_) vkDestroyInstance(instance_, nullptr);
}

void VulkanContext::pickPhysicalDevice(const ContextOptions& options) {
  std::vector<VkPhysicalDevice> devices = enumerateDevices(instance_);
  if (devices.empty()) throw VulkanError("no Vulkan device found (apt-get install mesa-vulkan-drivers for lavapipe)");
  int bestRank = 1 << 30;
  std::string names;
  // Digits only: the device of that number in `raylab devices` (0-based), for GPUs of one name on one host.
  const std::string& wanted = options.deviceName;
  const bool byNumber = !wanted.empty() && wanted.size() <= 9 && wanted.find_first_not_of("0123456789") == std::string::npos;
  for (size_t n = 0; n < devices.size(); ++n) {
    VkPhysicalDevice d = devices[n];
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(d, &p);
    names += std::string(names.empty() ? "" : ", ") + std::to_string(n) + ": " + p.deviceName;
    if (p.apiVersion < VK_API_VERSION_1_2) continue;
    if (byNumber) {
      if (std::stoul(wanted) == n) physical_ = d;
    } else if (!wanted.empty()) {
      if (lower(p.deviceName).find(lower(wanted)) != std::string::npos && !physical_) physical_ = d;
    } else if (deviceRank(p.deviceType) < bestRank) {
      bestRank = deviceRank(p.deviceType);
      physical_ = d;
    }
  }
  if (!physical_) {
    if (!options.deviceName.empty())
      throw UnknownDeviceError("--device '" + options.deviceName + "' is unknown: it matches no Vulkan 1.2 device; devices: " + names);
    throw VulkanError("no Vulkan 1.2 device found; devices: " + names);
  }

  VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceMaintenance3Properties maintenance3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
  subgroup.pNext = &driver;
  driver.pNext = &maintenance3;
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  props.pNext = &subgroup;
  vkGetPhysicalDeviceProperties2(physical_, &props);
  info_.name = props.properties.deviceName;
  info_.driver = std::string(driver.driverName) + " " + driver.driverInfo;
  info_.vendorId = props.properties.vendorID;
  info_.subgroupSize = subgroup.subgroupSize;
  info_.timestampPeriodNs = props.properties.limits.timestampPeriod;
  info_.maxGroupCountX = props.properties.limits.maxComputeWorkGroupCount[0];
  info_.maxGroupCountY = props.properties.limits.maxComputeWorkGroupCount[1];
  setDispatchRowGroups(0);
  info_.maxMemoryAllocationSize = maintenance3.maxMemoryAllocationSize;
  info_.isCpu = props.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  vkGetPhysicalDeviceMemoryProperties(physical_, &memoryProperties_);
}

void VulkanContext::createDevice(const ContextOptions& options) {
  uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &familyCount, families.data());
  // Prefer a family that does graphics too: the window draws its panels on the same queue.
  int chosen = -1;
  for (uint32_t i = 0; i < familyCount && chosen < 0; ++i)
    if ((families[i].queueFlags & (VK_QUEUE_COMPUTE_BIT | VK_QUEUE_GRAPHICS_BIT)) ==
        (VK_QUEUE_COMPUTE_BIT | VK_QUEUE_GRAPHICS_BIT))
      chosen = static_cast<int>(i);
  for (uint32_t i = 0; i < familyCount && chosen < 0; ++i)
    if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) chosen = static_cast<int>(i);
  if (chosen < 0) throw VulkanError(info_.name + " has no compute queue");
  queueFamily_ = static_cast<uint32_t>(chosen);
  info_.timestamps = families[queueFamily_].timestampValidBits > 0;

  VkPhysicalDeviceVulkan12Features have12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceFeatures2 have{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  have.pNext = &have12;
  vkGetPhysicalDeviceFeatures2(physical_, &have);
  if (!have12.bufferDeviceAddress || !have12.scalarBlockLayout || !have.features.shaderInt64)
    throw VulkanError(info_.name + " lacks bufferDeviceAddress, scalarBlockLayout or shaderInt64");

  // Ray tracing (the rt tracer) and SER, enabled where the device has them.
  std::vector<const char*> extensions = options.deviceExtensions;
  uint32_t extensionCount = 0;
  vkEnumerateDeviceExtensionProperties(physical_, nullptr, &extensionCount, nullptr);
  std::vector<VkExtensionProperties> available(extensionCount);
  vkEnumerateDeviceExtensionProperties(physical_, nullptr, &extensionCount, available.data());
  auto has = [&](const char* name) {
    for (const auto& e : available)
      if (std::strcmp(e.extensionName, name) == 0) return true;
    return false;
  };
  VkPhysicalDeviceAccelerationStructureFeaturesKHR haveAs{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  VkPhysicalDeviceRayTracingPipelineFeaturesKHR haveRt{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
  VkPhysicalDeviceRayTracingInvocationReorderFeaturesNV haveSer{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_INVOCATION_REORDER_FEATURES_NV};
  const char* rtExtensions[] = {VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME, VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME,
                                VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME};
  std::string missing;
  for (const char* e : rtExtensions)
    if (!has(e)) missing += (missing.empty() ? "" : ", ") + std::string(e);
  const bool serExtension = has(VK_NV_RAY_TRACING_INVOCATION_REORDER_EXTENSION_NAME);
  if (missing.empty()) {
    haveAs.pNext = &haveRt;
    if (serExtension) haveRt.pNext = &haveSer;
    VkPhysicalDeviceFeatures2 query{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    query.pNext = &haveAs;
    vkGetPhysicalDeviceFeatures2(physical_, &query);
    if (!haveAs.accelerationStructure) missing = "the accelerationStructure feature";
    if (!haveRt.rayTracingPipeline) missing += (missing.empty() ? "" : ", ") + std::string("the rayTracingPipeline feature");
  }
  info_.rayTracing = missing.empty();
  info_.rayTracingMissing = missing;
  VkPhysicalDeviceAccelerationStructureFeaturesKHR wantAs{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  VkPhysicalDeviceRayTracingPipelineFeaturesKHR wantRt{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
  VkPhysicalDeviceRayTracingInvocationReorderFeaturesNV wantSer{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_INVOCATION_REORDER_FEATURES_NV};
  if (info_.rayTracing) {
    for (const char* e : rtExtensions) extensions.push_back(e);
    wantAs.accelerationStructure = VK_TRUE;
    wantRt.rayTracingPipeline = VK_TRUE;
    wantAs.pNext = &wantRt;
    info_.ser = serExtension && haveSer.rayTracingInvocationReorder;
    if (info_.ser) {
      extensions.push_back(VK_NV_RAY_TRACING_INVOCATION_REORDER_EXTENSION_NAME);
      wantSer.rayTracingInvocationReorder = VK_TRUE;
      wantRt.pNext = &wantSer;
    }
    VkPhysicalDeviceRayTracingPipelinePropertiesKHR rtProps{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR};
    VkPhysicalDeviceAccelerationStructurePropertiesKHR asProps{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
    VkPhysicalDeviceRayTracingInvocationReorderPropertiesNV serProps{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_INVOCATION_REORDER_PROPERTIES_NV};
    VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
    rtProps.pNext = &asProps;
    asProps.pNext = &subgroup;
    if (info_.ser) subgroup.pNext = &serProps;
    VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props.pNext = &rtProps;
    vkGetPhysicalDeviceProperties2(physical_, &props);
    info_.shaderGroupHandleSize = rtProps.shaderGroupHandleSize;
    info_.shaderGroupHandleAlignment = rtProps.shaderGroupHandleAlignment;
    info_.shaderGroupBaseAlignment = rtProps.shaderGroupBaseAlignment;
    info_.maxRayDispatchInvocationCount = rtProps.maxRayDispatchInvocationCount;
    info_.minAccelerationStructureScratchOffsetAlignment = asProps.minAccelerationStructureScratchOffsetAlignment;
    info_.subgroupsInRayGen = (subgroup.supportedStages & VK_SHADER_STAGE_RAYGEN_BIT_KHR) &&
                              (subgroup.supportedOperations & VK_SUBGROUP_FEATURE_ARITHMETIC_BIT);
    if (info_.ser)
      info_.serReorderingHint =
          serProps.rayTracingInvocationReorderReorderingHint == VK_RAY_TRACING_INVOCATION_REORDER_MODE_REORDER_NV
              ? "reorder"
              : "none";
  }
  if (!info_.ser)
    info_.serMissing = !info_.rayTracing ? missing + ", " + VK_NV_RAY_TRACING_INVOCATION_REORDER_EXTENSION_NAME
                       : !serExtension   ? std::string(VK_NV_RAY_TRACING_INVOCATION_REORDER_EXTENSION_NAME)
                                         : "the rayTracingInvocationReorder feature";

  VkPhysicalDeviceVulkan12Features want12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  want12.bufferDeviceAddress = VK_TRUE;
  want12.scalarBlockLayout = VK_TRUE;
  want12.hostQueryReset = have12.hostQueryReset;
  want12.shaderSubgroupExtendedTypes = have12.shaderSubgroupExtendedTypes;
  if (info_.rayTracing) want12.pNext = &wantAs;
  VkPhysicalDeviceFeatures2 want{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  want.pNext = &want12;
  want.features.shaderInt64 = VK_TRUE;

  float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = queueFamily_;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;

  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.pNext = &want;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VK_CHECK(vkCreateDevice(physical_, &info, nullptr, &device_));
  vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
  if (info_.rayTracing) {
    auto load = [&](auto& fn, const char* name) {
      fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(vkGetDeviceProcAddr(device_, name));
      if (!fn) throw VulkanError(std::string("the device has no ") + name);
    };
    load(rt_.createAccelerationStructure, "vkCreateAccelerationStructureKHR");
    load(rt_.destroyAccelerationStructure, "vkDestroyAccelerationStructureKHR");
    load(rt_.getAccelerationStructureBuildSizes, "vkGetAccelerationStructureBuildSizesKHR");
    load(rt_.cmdBuildAccelerationStructures, "vkCmdBuildAccelerationStructuresKHR");
    load(rt_.getAccelerationStructureDeviceAddress, "vkGetAccelerationStructureDeviceAddressKHR");
    load(rt_.cmdCopyAccelerationStructure, "vkCmdCopyAccelerationStructureKHR");
    load(rt_.cmdWriteAccelerationStructuresProperties, "vkCmdWriteAccelerationStructuresPropertiesKHR");
    load(rt_.createRayTracingPipelines, "vkCreateRayTracingPipelinesKHR");
    load(rt_.getRayTracingShaderGroupHandles, "vkGetRayTracingShaderGroupHandlesKHR");
    load(rt_.cmdTraceRays, "vkCmdTraceRaysKHR");
    setRayTracingBarriers(true);
  }

  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  poolInfo.queueFamilyIndex = queueFamily_;
  VK_CHECK(vkCreateCommandPool(device_, &poolInfo, nullptr, &commandPool_));
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VK_CHECK(vkCreateFence(device_, &fenceInfo, nullptr, &fence_));
}

void VulkanContext::submitAndWait(const std::function<void(VkCommandBuffer)>& record) const {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = commandPool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd;
  VK_CHECK(vkAllocateCommandBuffers(device_, &alloc, &cmd));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  record(cmd);
  VK_CHECK(vkEndCommandBuffer(cmd));
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  VK_CHECK(vkResetFences(device_, 1, &fence_));
  VK_CHECK(vkQueueSubmit(queue_, 1, &submit, fence_));
  VK_CHECK(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX));
  vkFreeCommandBuffers(device_, commandPool_, 1, &cmd);
}

uint32_t VulkanContext::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags wanted) const {
  for (uint32_t i = 0; i < memoryProperties_.memoryTypeCount; ++i)
    if ((typeBits & (1u << i)) && (memoryProperties_.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
  throw VulkanError("no memory type with the wanted properties");
}

std::vector<std::string> VulkanContext::describeDevices() {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.apiVersion = VK_API_VERSION_1_2;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  VkInstance instance;
  VK_CHECK(vkCreateInstance(&info, nullptr, &instance));
  std::vector<std::string> lines;
  for (VkPhysicalDevice d : enumerateDevices(instance)) {
    const size_t number = lines.size();  // what --device N picks
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(d, &p);
    uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(d, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateDeviceExtensionProperties(d, nullptr, &count, extensions.data());
    auto lacking = [&](std::initializer_list<const char*> names) {
      std::string missing;
      for (const char* n : names) {
        bool found = false;
        for (const auto& e : extensions) found = found || std::strcmp(e.extensionName, n) == 0;
        if (!found) missing += (missing.empty() ? "" : ", ") + std::string(n);
      }
      return missing.empty() ? std::string("yes") : "no (lacks " + missing + ")";
    };
    lines.push_back(std::to_string(number) + ": " + p.deviceName + "\n  rt tracer: " +
                    lacking({VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME, VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME,
                             VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME}) +
                    "\n  SER: " + lacking({VK_NV_RAY_TRACING_INVOCATION_REORDER_EXTENSION_NAME}));
  }
  vkDestroyInstance(instance, nullptr);
  return lines;
}

void VulkanContext::setDispatchRowGroups(uint32_t groups) {
  info_.dispatchRowGroups = groups > 0 ? std::min(groups, info_.maxGroupCountX) : info_.maxGroupCountX;
}

}  // namespace raylab

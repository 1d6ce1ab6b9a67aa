#include "renderer/vk/vk_context.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <optional>

#include "renderer/vk/compute_pipeline.h"
#include "renderer/vk/pipeline_statistics.h"
#include "renderer/vk/ray_tracing_support.h"
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

std::vector<VkQueueFamilyProperties> queueFamilyProperties(VkPhysicalDevice physical) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
  return families;
}

// A family that does graphics too where there is one (the window draws its panels on the same queue), else
// any compute family; none if the device computes nowhere.
std::optional<uint32_t> chooseQueueFamily(const std::vector<VkQueueFamilyProperties>& families) {
  const VkQueueFlags both = VK_QUEUE_COMPUTE_BIT | VK_QUEUE_GRAPHICS_BIT;
  for (uint32_t i = 0; i < families.size(); ++i)
    if ((families[i].queueFlags & both) == both) return i;
  for (uint32_t i = 0; i < families.size(); ++i)
    if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) return i;
  return std::nullopt;
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
    bool pick = false;
    if (byNumber) {
      pick = std::stoul(wanted) == n;
    } else if (!wanted.empty()) {
      pick = lower(p.deviceName).find(lower(wanted)) != std::string::npos && !physical_;
    } else if (deviceRank(p.deviceType) < bestRank) {
      bestRank = deviceRank(p.deviceType);
      pick = true;
    }
    if (pick) physical_ = d, info_.number = uint32_t(n);  // its number: what `raylab devices` lists it as
  }
  if (!physical_) {
    if (!options.deviceName.empty())
      throw UnknownDeviceError("--device '" + options.deviceName + "' is unknown: it matches no Vulkan 1.2 device; devices: " + names);
    throw VulkanError("no Vulkan 1.2 device found; devices: " + names);
  }

  VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceMaintenance3Properties maintenance3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
  VkPhysicalDeviceIDProperties id{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ID_PROPERTIES};
  VkPhysicalDevicePCIBusInfoPropertiesEXT pci{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PCI_BUS_INFO_PROPERTIES_EXT};
  const bool hasPci = missingDeviceExtensions(physical_, {VK_EXT_PCI_BUS_INFO_EXTENSION_NAME}).empty();
  subgroup.pNext = &driver;
  driver.pNext = &maintenance3;
  maintenance3.pNext = &id;
  if (hasPci) id.pNext = &pci;
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
  info_.subgroupPartitioned = (subgroup.supportedOperations & VK_SUBGROUP_FEATURE_PARTITIONED_BIT_NV) &&
                              missingDeviceExtensions(physical_, {VK_NV_SHADER_SUBGROUP_PARTITIONED_EXTENSION_NAME}).empty();
  char hex[2 * VK_UUID_SIZE + 1] = {};
  for (uint32_t i = 0; i < VK_UUID_SIZE; ++i) std::snprintf(hex + 2 * i, 3, "%02x", id.deviceUUID[i]);
  info_.uuid = hex;
  if (hasPci) {
    char bus[32];
    std::snprintf(bus, sizeof(bus), "%04x:%02x:%02x.%x", pci.pciDomain, pci.pciBus, pci.pciDevice, pci.pciFunction);
    info_.pciBus = bus;
  }
  vkGetPhysicalDeviceMemoryProperties(physical_, &memoryProperties_);
}

void VulkanContext::createDevice(const ContextOptions& options) {
  const std::vector<VkQueueFamilyProperties> families = queueFamilyProperties(physical_);
  const std::optional<uint32_t> family = chooseQueueFamily(families);
  if (!family) throw VulkanError(info_.name + " has no compute queue");
  queueFamily_ = *family;
  info_.timestamps = families[queueFamily_].timestampValidBits > 0;

  VkPhysicalDeviceVulkan12Features have12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceFeatures2 have{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
  have.pNext = &have12;
  vkGetPhysicalDeviceFeatures2(physical_, &have);
  if (!have12.bufferDeviceAddress || !have12.scalarBlockLayout || !have.features.shaderInt64)
    throw VulkanError(info_.name + " lacks bufferDeviceAddress, scalarBlockLayout or shaderInt64");

  // Ray tracing (the rt tracer) and SER, enabled where the device has them.
  RayTracingSupport rayTracing(physical_, info_);
  std::vector<const char*> extensions = options.deviceExtensions;
  extensions.insert(extensions.end(), rayTracing.extensions().begin(), rayTracing.extensions().end());
  if (info_.subgroupPartitioned) extensions.push_back(VK_NV_SHADER_SUBGROUP_PARTITIONED_EXTENSION_NAME);

  VkPhysicalDeviceVulkan12Features want12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  want12.bufferDeviceAddress = VK_TRUE;
  want12.scalarBlockLayout = VK_TRUE;
  want12.hostQueryReset = have12.hostQueryReset;
  want12.shaderSubgroupExtendedTypes = have12.shaderSubgroupExtendedTypes;
  ShaderStatisticsFeature statistics;
  want12.pNext = statistics.enable(physical_, extensions, rayTracing.features());
  info_.shaderStatistics = statistics.enabled;
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
    rt_ = loadRayTracingFunctions(device_);
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
    auto lacking = [&](const std::vector<const char*>& names) {
      const std::string missing = missingDeviceExtensions(d, names);
      return missing.empty() ? std::string("yes") : "no (lacks " + missing + ")";
    };
    lines.push_back(std::to_string(number) + ": " + p.deviceName + "\n  rt tracer: " + lacking(kRayTracingExtensions) +
                    "\n  SER: " + lacking(kSerExtensions));
  }
  vkDestroyInstance(instance, nullptr);
  return lines;
}

void VulkanContext::setDispatchRowGroups(uint32_t groups) {
  info_.dispatchRowGroups = groups > 0 ? std::min(groups, info_.maxGroupCountX) : info_.maxGroupCountX;
}

}  // namespace raylab

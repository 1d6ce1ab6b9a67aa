#include "renderer/vk/ray_tracing_support.h"

#include <cstring>
#include <type_traits>

#include "renderer/vk/vk_check.h"

namespace raylab {

const std::vector<const char*> kRayTracingExtensions{VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
                                                     VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME,
                                                     VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME};
const std::vector<const char*> kSerExtensions{VK_NV_RAY_TRACING_INVOCATION_REORDER_EXTENSION_NAME};

namespace {
void appendName(std::string& list, const std::string& name) { list += (list.empty() ? "" : ", ") + name; }
}  // namespace

std::string missingDeviceExtensions(VkPhysicalDevice physical, const std::vector<const char*>& wanted) {
  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> available(count);
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, available.data());
  std::string missing;
  for (const char* name : wanted) {
    bool found = false;
    for (const auto& e : available) found = found || std::strcmp(e.extensionName, name) == 0;
    if (!found) appendName(missing, name);
  }
  return missing;
}

RayTracingSupport::RayTracingSupport(VkPhysicalDevice physical, DeviceInfo& info) {
  std::string missing = missingDeviceExtensions(physical, kRayTracingExtensions);
  const bool serExtension = missingDeviceExtensions(physical, kSerExtensions).empty();
  VkPhysicalDeviceAccelerationStructureFeaturesKHR haveAs{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  VkPhysicalDeviceRayTracingPipelineFeaturesKHR haveRt{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR};
  VkPhysicalDeviceRayTracingInvocationReorderFeaturesNV haveSer{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_INVOCATION_REORDER_FEATURES_NV};
  if (missing.empty()) {
    haveAs.pNext = &haveRt;
    if (serExtension) haveRt.pNext = &haveSer;
    VkPhysicalDeviceFeatures2 query{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    query.pNext = &haveAs;
    vkGetPhysicalDeviceFeatures2(physical, &query);
    if (!haveAs.accelerationStructure) missing = "the accelerationStructure feature";
    if (!haveRt.rayTracingPipeline) appendName(missing, "the rayTracingPipeline feature");
  }
  info.rayTracing = missing.empty();
  info.rayTracingMissing = missing;
  info.ser = info.rayTracing && serExtension && haveSer.rayTracingInvocationReorder;
  if (!info.ser)
    info.serMissing = !info.rayTracing ? missing + ", " + kSerExtensions[0]
                      : !serExtension  ? std::string(kSerExtensions[0])
                                       : "the rayTracingInvocationReorder feature";
  if (!info.rayTracing) return;

  extensions_ = kRayTracingExtensions;
  accelerationStructure_.accelerationStructure = VK_TRUE;
  pipeline_.rayTracingPipeline = VK_TRUE;
  accelerationStructure_.pNext = &pipeline_;
  if (info.ser) {
    extensions_.insert(extensions_.end(), kSerExtensions.begin(), kSerExtensions.end());
    reorder_.rayTracingInvocationReorder = VK_TRUE;
    pipeline_.pNext = &reorder_;
  }
  readProperties(physical, info);
}

void RayTracingSupport::readProperties(VkPhysicalDevice physical, DeviceInfo& info) const {
  VkPhysicalDeviceRayTracingPipelinePropertiesKHR rtProps{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR};
  VkPhysicalDeviceAccelerationStructurePropertiesKHR asProps{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
  VkPhysicalDeviceRayTracingInvocationReorderPropertiesNV serProps{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_INVOCATION_REORDER_PROPERTIES_NV};
  VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
  rtProps.pNext = &asProps;
  asProps.pNext = &subgroup;
  if (info.ser) subgroup.pNext = &serProps;
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  props.pNext = &rtProps;
  vkGetPhysicalDeviceProperties2(physical, &props);
  info.shaderGroupHandleSize = rtProps.shaderGroupHandleSize;
  info.shaderGroupHandleAlignment = rtProps.shaderGroupHandleAlignment;
  info.shaderGroupBaseAlignment = rtProps.shaderGroupBaseAlignment;
  info.maxRayDispatchInvocationCount = rtProps.maxRayDispatchInvocationCount;
  info.minAccelerationStructureScratchOffsetAlignment = asProps.minAccelerationStructureScratchOffsetAlignment;
  info.subgroupsInRayGen = (subgroup.supportedStages & VK_SHADER_STAGE_RAYGEN_BIT_KHR) &&
                           (subgroup.supportedOperations & VK_SUBGROUP_FEATURE_ARITHMETIC_BIT);
  if (info.ser)
    info.serReorderingHint =
        serProps.rayTracingInvocationReorderReorderingHint == VK_RAY_TRACING_INVOCATION_REORDER_MODE_REORDER_NV
            ? "reorder"
            : "none";
}

RayTracingFunctions loadRayTracingFunctions(VkDevice device) {
  RayTracingFunctions rt;
  auto load = [&](auto& fn, const char* name) {
    fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(vkGetDeviceProcAddr(device, name));
    if (!fn) throw VulkanError(std::string("the device has no ") + name);
  };
  load(rt.createAccelerationStructure, "vkCreateAccelerationStructureKHR");
  load(rt.destroyAccelerationStructure, "vkDestroyAccelerationStructureKHR");
  load(rt.getAccelerationStructureBuildSizes, "vkGetAccelerationStructureBuildSizesKHR");
  load(rt.cmdBuildAccelerationStructures, "vkCmdBuildAccelerationStructuresKHR");
  load(rt.getAccelerationStructureDeviceAddress, "vkGetAccelerationStructureDeviceAddressKHR");
  load(rt.cmdCopyAccelerationStructure, "vkCmdCopyAccelerationStructureKHR");
  load(rt.cmdWriteAccelerationStructuresProperties, "vkCmdWriteAccelerationStructuresPropertiesKHR");
  load(rt.createRayTracingPipelines, "vkCreateRayTracingPipelinesKHR");
  load(rt.getRayTracingShaderGroupHandles, "vkGetRayTracingShaderGroupHandlesKHR");
  load(rt.cmdTraceRays, "vkCmdTraceRaysKHR");
  return rt;
}

}  // namespace raylab

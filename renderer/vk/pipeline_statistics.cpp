#include "renderer/vk/pipeline_statistics.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace raylab {

bool shaderStatisticsWanted() {
  static const bool wanted = [] {
    const char* v = std::getenv("RAYLAB_SHADER_STATS");
    return v && std::strcmp(v, "0") != 0 && *v != '\0';
  }();
  return wanted;
}

void* ShaderStatisticsFeature::enable(VkPhysicalDevice physical, std::vector<const char*>& extensions, void* next) {
  if (!shaderStatisticsWanted()) return next;
  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> available(count);
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, available.data());
  for (const VkExtensionProperties& e : available)
    if (std::strcmp(e.extensionName, VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME) == 0) enabled = true;
  if (!enabled) {
    std::fprintf(stderr, "shader-stats: the device lacks %s\n", VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME);
    return next;
  }
  extensions.push_back(VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME);
  feature.pipelineExecutableInfo = VK_TRUE;
  feature.pNext = next;
  return &feature;
}

namespace {
std::string statisticValue(const VkPipelineExecutableStatisticKHR& s) {
  switch (s.format) {
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR: return s.value.b32 ? "true" : "false";
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_INT64_KHR: return std::to_string(s.value.i64);
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_UINT64_KHR: return std::to_string(s.value.u64);
    case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_FLOAT64_KHR: return std::to_string(s.value.f64);
    default: return "?";
  }
}
}  // namespace

void printShaderStatistics(VkDevice device, VkPipeline pipeline, const std::string& name) {
  auto properties = reinterpret_cast<PFN_vkGetPipelineExecutablePropertiesKHR>(
      vkGetDeviceProcAddr(device, "vkGetPipelineExecutablePropertiesKHR"));
  auto statistics = reinterpret_cast<PFN_vkGetPipelineExecutableStatisticsKHR>(
      vkGetDeviceProcAddr(device, "vkGetPipelineExecutableStatisticsKHR"));
  if (!properties || !statistics) return;
  VkPipelineInfoKHR info{VK_STRUCTURE_TYPE_PIPELINE_INFO_KHR};
  info.pipeline = pipeline;
  uint32_t count = 0;
  if (properties(device, &info, &count, nullptr) != VK_SUCCESS) return;
  std::vector<VkPipelineExecutablePropertiesKHR> executables(count, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_PROPERTIES_KHR});
  properties(device, &info, &count, executables.data());
  for (uint32_t i = 0; i < count; ++i) {
    VkPipelineExecutableInfoKHR which{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INFO_KHR};
    which.pipeline = pipeline;
    which.executableIndex = i;
    uint32_t n = 0;
    if (statistics(device, &which, &n, nullptr) != VK_SUCCESS) continue;
    std::vector<VkPipelineExecutableStatisticKHR> stats(n, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR});
    statistics(device, &which, &n, stats.data());
    std::string line = "shader-stats " + name + " " + executables[i].name + ":";
    for (const VkPipelineExecutableStatisticKHR& s : stats) line += std::string(" ") + s.name + "=" + statisticValue(s) + ";";
    std::fprintf(stderr, "%s\n", line.c_str());
  }
}

}  // namespace raylab

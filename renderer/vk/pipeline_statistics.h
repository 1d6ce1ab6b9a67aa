// The compiler's own statistics of each compute pipeline (VK_KHR_pipeline_executable_properties: on NVIDIA
// the register count, local memory and shared memory of the final machine code), printed to stderr as a
// pipeline is created. A diagnostic for traversal work, where occupancy decides speed: turned on by the
// environment variable RAYLAB_SHADER_STATS=1, and only where the device has the extension (a device without
// it says so once and builds pipelines as always). It changes no pipeline and no image.
#pragma once

#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace raylab {

// Whether RAYLAB_SHADER_STATS asks for the statistics (read once per process).
bool shaderStatisticsWanted();

// What createDevice chains in when the statistics are wanted and the device has the extension.
struct ShaderStatisticsFeature {
  VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR feature{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR};
  bool enabled = false;
  // Adds the extension to `extensions` and returns the feature struct to chain in front of `next`, or `next`
  // when the statistics are not wanted or not available.
  void* enable(VkPhysicalDevice physical, std::vector<const char*>& extensions, void* next);
};

// Prints "shader-stats NAME EXECUTABLE: statistic=value, ..." for every executable of `pipeline`.
void printShaderStatistics(VkDevice device, VkPipeline pipeline, const std::string& name);

}  // namespace raylab

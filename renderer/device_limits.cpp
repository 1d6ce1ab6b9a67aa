#include "renderer/device_limits.h"

#include "shaders/shared_types.h"

namespace raylab {

std::string pathsBeyondDevice(const DeviceInfo& device, const Settings& s) {
  const uint64_t paths = uint64_t(s.width) * s.height * s.sppPerFrame;
  const std::string what = std::to_string(s.width) + "x" + std::to_string(s.height) + " at " +
                           std::to_string(s.sppPerFrame) + " spp is " + std::to_string(paths) + " paths per frame; ";
  // Path stages run in groups of RL_PATH_GROUP_SIZE threads, rows of dispatchRowGroups groups, at most
  // maxGroupCountY rows.
  const uint64_t launchable = uint64_t(device.dispatchRowGroups) * device.maxGroupCountY * RL_PATH_GROUP_SIZE;
  if (device.dispatchRowGroups > 0 && device.maxGroupCountY > 0 && paths > launchable)
    return what + device.name + " launches at most " + std::to_string(launchable) + " threads per dispatch";
  if (s.tracer == Tracer::Rt && device.maxRayDispatchInvocationCount > 0 && paths > device.maxRayDispatchInvocationCount)
    return what + device.name + " launches at most " + std::to_string(device.maxRayDispatchInvocationCount) +
           " rays per ray-tracing dispatch (--tracer rt)";
  if (device.maxMemoryAllocationSize > 0 && paths * kLargestBytesPerPath > device.maxMemoryAllocationSize)
    return what + "a buffer of " + std::to_string(kLargestBytesPerPath) + " bytes a path needs " +
           std::to_string(paths * kLargestBytesPerPath) + " bytes and " + device.name + " allocates at most " +
           std::to_string(device.maxMemoryAllocationSize);
  return "";
}

}  // namespace raylab

// Whether a device can hold and launch a frame of the settings' paths, said before anything renders. The
// settings' own limits (renderer/settings/settings_validation.h: at most 8192 a side, 2^26 paths a frame) hold on
// every device; these are the device's own: how many threads its dispatches can cover in rows
// (renderer/vk/dispatch_size.h), how many rays one ray-tracing launch may have (--tracer rt), and the
// largest single allocation, which must hold one 16-byte element of every path's state.
#pragma once

#include <cstdint>
#include <string>

#include "renderer/settings/settings.h"
#include "renderer/vk/vk_context.h"

namespace raylab {

// The bytes a path takes in the largest per-path buffer (one RL_STATE_* element, the results).
inline constexpr uint64_t kLargestBytesPerPath = 16;

// Empty when `device` can run a frame of `settings`; else why not, naming the paths per frame and the limit.
std::string pathsBeyondDevice(const DeviceInfo& device, const Settings& settings);

}  // namespace raylab

// What the installed Khronos validation layer can do, for the GPU-assisted mode (validation_mode.h).
#pragma once

#include <cstdint>
#include <string>

namespace raylab {

// The layer's spec version (VK_MAKE_API_VERSION), 0 when it is not installed.
uint32_t validationLayerVersion();

// Why GPU-assisted validation cannot instrument the renderer's path shaders with this layer, or "" when it
// can. Found by a real run on Debian 12's layer: its instrumentation crashes.
std::string gpuAssistedUnavailable();

}  // namespace raylab

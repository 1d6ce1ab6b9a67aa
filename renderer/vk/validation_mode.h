// Which checks the Khronos validation layer runs. Synchronization validation and GPU-assisted validation
// cannot share one instance on the layers we support (1.3.239 and 1.4.309), so they are two modes:
//   sync    (--validate, RAYLAB_VALIDATE=1)             the core checks plus synchronization validation
//   gpu-av  (--validate=gpu-av, RAYLAB_VALIDATE=gpu-av)  the core checks plus GPU-assisted validation, which
//           instruments shaders to check every buffer-device-address access (all of ours) at run time
#pragma once

#include <optional>
#include <string>

namespace raylab {

enum class ValidationMode { Off, Sync, GpuAssisted };

// "1", "sync" -> Sync; "gpu-av" -> GpuAssisted; "", "0", "off" -> Off; anything else: nullopt.
std::optional<ValidationMode> parseValidationMode(const std::string& text);
const char* validationModeName(ValidationMode mode);  // "off", "sync", "gpu-av"
// RAYLAB_VALIDATE from the environment; an unknown value is an error (std::invalid_argument), not "off".
ValidationMode validationModeFromEnvironment();

}  // namespace raylab

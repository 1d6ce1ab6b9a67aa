#include "renderer/vk/validation_mode.h"

#include <cstdlib>
#include <stdexcept>

namespace raylab {

std::optional<ValidationMode> parseValidationMode(const std::string& text) {
  if (text.empty() || text == "0" || text == "off") return ValidationMode::Off;
  if (text == "1" || text == "sync") return ValidationMode::Sync;
  if (text == "gpu-av") return ValidationMode::GpuAssisted;
  return std::nullopt;
}

const char* validationModeName(ValidationMode mode) {
  switch (mode) {
    case ValidationMode::Sync: return "sync";
    case ValidationMode::GpuAssisted: return "gpu-av";
    default: return "off";
  }
}

ValidationMode validationModeFromEnvironment() {
  const char* env = std::getenv("RAYLAB_VALIDATE");
  if (!env) return ValidationMode::Off;
  if (std::optional<ValidationMode> mode = parseValidationMode(env)) return *mode;
  throw std::invalid_argument(std::string("RAYLAB_VALIDATE='") + env + "' is not 0, 1, sync or gpu-av");
}

}  // namespace raylab

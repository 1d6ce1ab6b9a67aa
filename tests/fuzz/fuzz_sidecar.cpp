// Screenshot sidecars and settings files (`--settings FILE.json`, app/sidecar.h), which read Settings
// through settingsFromJson (renderer/settings/settings_json.h) and the camera. The only acceptable failure is
// UsageError; a file that is accepted must hold settings that pass validateSettings and a usable camera.
#include <cmath>

#include "app/sidecar.h"
#include "renderer/settings/settings_validation.h"
#include "tests/fuzz/fuzz_input.h"

namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string path = raylab::fuzz::writeInput(data, size, ".json");
  try {
    raylab::Sidecar s = raylab::readSidecar(path);
    // Accepted: no silent wrong result, every source of Settings is held to the same checks.
    if (raylab::settingsError(s.settings)) __builtin_trap();
    if (s.camera && (!finite(s.camera->position) || !finite(s.camera->target) || !finite(s.camera->up) ||
                     !(s.camera->yfovRadians > 0.0f && s.camera->yfovRadians < 3.1416f) ||
                     s.camera->position == s.camera->target))
      __builtin_trap();
  } catch (const raylab::UsageError&) {
  }
  return 0;
}

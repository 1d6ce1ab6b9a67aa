#include "app/command_errors.h"

#include <cstdio>

#include "app/cli_options.h"
#include "app/scene_setup.h"
#include "app/ui_script.h"

namespace raylab {

int withCommandErrors(const std::function<void(const std::string&)>& printUsage, const std::function<int()>& body) {
  try {
    return body();
  } catch (const UsageError& e) {
    printUsage(e.what());
    return kExitUsage;
  } catch (const ScriptError& e) {
    std::fprintf(stderr, "raylab: %s\n", e.what());
    return kExitUsage;
  } catch (const SceneLoadError& e) {
    std::fprintf(stderr, "raylab: cannot load scene: %s\n", e.what());
    return kExitBadScene;
  }
}

}  // namespace raylab

#include "app/config_dir.h"

#include <cstdlib>

namespace raylab {

std::string configDir() {
  const char* xdg = std::getenv("XDG_CONFIG_HOME");
  if (xdg && xdg[0] == '/') return std::string(xdg) + "/raylab";
  const char* home = std::getenv("HOME");
  if (home && home[0] != '\0') return std::string(home) + "/.config/raylab";
  return "";
}

}  // namespace raylab

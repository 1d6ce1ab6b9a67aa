#include "app/window/script_keys.h"

#include <stdexcept>

#include <GLFW/glfw3.h>

#include "app/window/lab_input.h"

namespace raylab {

void pressScriptKey(LabInput& input, const std::string& name) {
  const bool shift = name.rfind("shift+", 0) == 0;
  const std::string key = shift ? name.substr(6) : name;
  int code = GLFW_KEY_UNKNOWN;
  if (key.size() == 1 && key[0] >= 'A' && key[0] <= 'Z') code = GLFW_KEY_A + (key[0] - 'A');  // GLFW's letters are ASCII
  else if (key == "Tab") code = GLFW_KEY_TAB;
  else if (key == "Esc") code = GLFW_KEY_ESCAPE;
  else if (key.size() >= 2 && key[0] == 'F') code = GLFW_KEY_F1 + std::stoi(key.substr(1)) - 1;
  // The script was checked before the window opened (scriptKeyName): any other name is a bug here.
  if (code == GLFW_KEY_UNKNOWN) throw std::logic_error("press: no GLFW key for '" + name + "'");
  input.press(code, shift ? GLFW_MOD_SHIFT : 0);
}

}  // namespace raylab

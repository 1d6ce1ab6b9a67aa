// A script's `press KEY` (app/ui_script.h) as a key press on the window: the name scriptKeyName accepted
// turned into GLFW's key and modifiers and delivered through LabInput's own key handler, so a script presses
// a hotkey exactly as the keyboard does.
#pragma once

#include <string>

namespace raylab {

class LabInput;

void pressScriptKey(LabInput& input, const std::string& name);

}  // namespace raylab

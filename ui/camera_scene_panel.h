// The camera and scene panel: built-in scenes or a glTF path (load errors shown here, never a crash), the
// scene's named viewpoints as buttons, fly or orbit mode and speed, the camera as copyable text, and the
// screenshot folder with its buttons.
#pragma once

#include "ui/ui_state.h"

namespace raylab {

UiRequests drawCameraScenePanel(const CameraModel& model);

}  // namespace raylab

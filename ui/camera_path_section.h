// The camera path section of the Scene and camera panel (issue 37): Play/Stop for the path given with
// --camera-path or recorded last, with the frame it is at, and Record/Stop with the keyframes so far and
// where the last recording went. It reads CameraPathModel and asks through UiRequests, like every panel.
#pragma once

#include "ui/ui_state.h"

namespace raylab {

void drawCameraPathSection(const CameraPathModel& m, UiRequests& r);

}  // namespace raylab

// One colour per pipeline stage, shared by the timing plots and the stacked bars so a stage looks the
// same everywhere.
#pragma once

#include <string>

#include <imgui.h>

namespace raylab {

ImU32 stageColor(const std::string& stage);

}  // namespace raylab

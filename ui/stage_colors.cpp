#include "ui/stage_colors.h"

#include <functional>

#include "renderer/stages.h"

namespace raylab {

ImU32 stageColor(const std::string& stage) {
  // The frame loop's stages have fixed colours (renderer/stages.h); the Timing panel's remainder its own; anything
  // else a stable hashed one.
  if (const StageInfo* s = findStage(stage)) return IM_COL32(s->r, s->g, s->b, 255);
  if (stage == "unattributed") return IM_COL32(60, 60, 60, 255);
  size_t h = std::hash<std::string>{}(stage);
  return IM_COL32(80 + h % 160, 80 + (h >> 8) % 160, 80 + (h >> 16) % 160, 255);
}

}  // namespace raylab

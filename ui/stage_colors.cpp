#include "ui/stage_colors.h"

#include <functional>
#include <map>

namespace raylab {

ImU32 stageColor(const std::string& stage) {
  // The frame loop's stages get fixed, distinguishable colours; anything new a stable hashed one.
  static const std::map<std::string, ImU32> known = {
      {"generate", IM_COL32(120, 120, 120, 255)}, {"trace", IM_COL32(230, 85, 60, 255)},
      {"learn", IM_COL32(250, 200, 60, 255)},     {"shade", IM_COL32(80, 160, 230, 255)},
      {"keys", IM_COL32(150, 210, 90, 255)},      {"oracle-trace", IM_COL32(240, 140, 200, 255)},
      {"sort", IM_COL32(170, 110, 230, 255)},     {"reorder", IM_COL32(60, 200, 190, 255)},
      {"accumulate", IM_COL32(200, 200, 200, 255)}, {"tonemap", IM_COL32(90, 90, 200, 255)},
      {"megakernel", IM_COL32(230, 130, 40, 255)}, {"setup", IM_COL32(100, 100, 100, 255)},
      {"counters", IM_COL32(140, 110, 80, 255)},  {"unattributed", IM_COL32(60, 60, 60, 255)},
      {"trace+shade", IM_COL32(155, 120, 145, 255)},
  };
  if (auto it = known.find(stage); it != known.end()) return it->second;
  size_t h = std::hash<std::string>{}(stage);
  return IM_COL32(80 + h % 160, 80 + (h >> 8) % 160, 80 + (h >> 16) % 160, 255);
}

}  // namespace raylab

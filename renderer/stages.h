// Every timed stage of a frame, declared once: its name (what recordStage and ScopedStage are given, the
// bench's `NAME_ms` CSV column, the charts' and the Timing panel's label), its role in the sort policy's and
// the speed-accuracy book's sums, and its colour in the UI. A stage timed under a name missing here is a
// programming error (StageTimer scopes refuse it), so a new stage is one row here and its recordStage call.
#pragma once

#include <cstdint>
#include <string_view>

namespace raylab {

enum class StageRole {
  PathWork,     // the traversal and shading that sorted rays make cheaper (trace, shade, or both fused)
  Reorder,      // what sorting costs at the bounce it sorts after (keys, their oracle trace, sort, reorder)
  LearnBefore,  // sorting's cost paid one bounce later: learning lengths of the rays sorted at bounce - 1
  Frame,        // the rest of the frame's work (camera rays, accumulation, the megakernel, set-up)
  Instrument,   // what only measuring costs (detailed counters, heatmaps)
};

struct StageInfo {
  const char* name;
  StageRole role;
  uint8_t r, g, b;  // colour in the Timing panel and the stage charts
};

// In the order the bench's CSV columns and the charts' stacks list them.
inline constexpr StageInfo kStages[] = {
    {"generate", StageRole::Frame, 120, 120, 120},
    {"trace", StageRole::PathWork, 230, 85, 60},
    {"learn", StageRole::LearnBefore, 250, 200, 60},
    {"shade", StageRole::PathWork, 80, 160, 230},
    {"keys", StageRole::Reorder, 150, 210, 90},
    {"oracle-trace", StageRole::Reorder, 240, 140, 200},
    {"sort", StageRole::Reorder, 170, 110, 230},
    {"reorder", StageRole::Reorder, 60, 200, 190},
    {"accumulate", StageRole::Frame, 200, 200, 200},
    {"tonemap", StageRole::Frame, 90, 90, 200},
    {"megakernel", StageRole::Frame, 230, 130, 40},
    {"setup", StageRole::Frame, 100, 100, 100},
    {"counters", StageRole::Instrument, 140, 110, 80},
    {"trace+shade", StageRole::PathWork, 155, 120, 145},
    {"heatmap", StageRole::Instrument, 210, 170, 120},
};

// The stage called `name`, or nullptr.
constexpr const StageInfo* findStage(std::string_view name) {
  for (const StageInfo& s : kStages)
    if (name == s.name) return &s;
  return nullptr;
}

// Sorting's cost, wherever it is paid (StageRole::Reorder and LearnBefore).
constexpr bool isSortingCost(std::string_view name) {
  const StageInfo* s = findStage(name);
  return s && (s->role == StageRole::Reorder || s->role == StageRole::LearnBefore);
}

}  // namespace raylab

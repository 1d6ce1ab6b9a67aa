// `raylab --frame-log FILE`: one JSON object per line and UI frame, so a benchmark (app/frame_log_report.py)
// can report how live the window stays (p50/p95 of the UI frame time, time to a preview after a change)
// from a real run, and a test can compare the window's frames with headless ones (each line that completes
// a render frame carries that frame's GPU time, stage times and sort plan). Speed claims come from such
// logs, never from timed tests.
#pragma once

#include <cstdint>
#include <string>

#include "app/window/live_render.h"
#include "renderer/checked_write.h"
#include "renderer/settings/settings.h"

namespace raylab {

// What one turn of the window's loop did besides its render work (RenderTurn: render_ms, frame_done,
// preview, steps, frame_steps, preview_width/height).
struct UiFrameRecord {
  double uiMs = 0.0;          // the turn's wall time: events, panels, render work, blit, present
  bool changed = false;       // the settings or the camera changed in it (whether or not that restarted)
  bool restarted = false;     // a change of camera or settings restarted the accumulation in it
  bool panels = false;        // the panels were rebuilt in it (after input, or when what they show changed)
  bool presented = false;     // the window was drawn and presented in it
  uint32_t framePaths = 0;    // paths of a whole render frame
};

class FrameLog {
 public:
  // Opens (truncates) `path`; throws WriteError naming the file and the reason when it cannot.
  explicit FrameLog(const std::string& path);

  // One line, written whole (AppendFile: a log of a run that is killed still ends on a whole line) or
  // WriteError. Not fsynced: one UI frame's line is not worth a disk flush.
  // `settings`: the render's, for a completed frame's "frame" object.
  void write(const UiFrameRecord& r, const RenderTurn& turn, const Settings& settings);
  void close() { file_.close(); }  // throws WriteError
  const std::string& path() const { return file_.path(); }

 private:
  AppendFile file_;
  uint64_t frames_ = 0;
};

}  // namespace raylab

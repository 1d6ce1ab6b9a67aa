// `raylab --frame-log FILE`: one JSON object per line and UI frame, so a benchmark (app/frame_log_report.py)
// can report how live the window stays (p50/p95 of the UI frame time, time to a preview after a change)
// from a real run. Speed claims come from such logs, never from timed tests.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

namespace raylab {

// What one turn of the window's loop did.
struct UiFrameRecord {
  double uiMs = 0.0;          // the turn's wall time: events, panels, render work, blit, present
  double renderMs = 0.0;      // wall time of the render submissions made in it (slices and preview)
  bool frameDone = false;     // a whole render frame completed in it (statistics and screenshots then)
  bool preview = false;       // a coarse preview was rendered and shown in it
  bool restarted = false;     // a change of camera or settings restarted the accumulation in it
  bool panels = false;        // the panels were rebuilt in it (after input, or when what they show changed)
  bool presented = false;     // the window was drawn and presented in it
  uint32_t slicePaths = 0;    // paths of the render slice submitted in it (0: none)
  uint32_t framePaths = 0;    // paths of a whole render frame
  uint32_t previewWidth = 0, previewHeight = 0;  // size of the preview rendered in it
};

class FrameLog {
 public:
  // Opens (truncates) `path`; throws std::runtime_error naming the file and the reason when it cannot.
  explicit FrameLog(const std::string& path);
  ~FrameLog();
  FrameLog(const FrameLog&) = delete;
  FrameLog& operator=(const FrameLog&) = delete;

  void write(const UiFrameRecord& r);

 private:
  std::FILE* file_ = nullptr;
  uint64_t frames_ = 0;
};

}  // namespace raylab

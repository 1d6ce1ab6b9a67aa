#include "app/window/frame_log.h"

#include <cstdio>

namespace raylab {

FrameLog::FrameLog(const std::string& path) : file_(path, AppendFile::Start::Empty) {}

void FrameLog::write(const UiFrameRecord& r, const RenderTurn& turn) {
  char line[512];
  std::snprintf(line, sizeof(line),
                "{\"ui_frame\":%llu,\"ui_ms\":%.3f,\"render_ms\":%.3f,\"frame_done\":%s,\"preview\":%s,"
                "\"restarted\":%s,\"panels\":%s,\"presented\":%s,\"slice_paths\":%u,\"frame_paths\":%u,\"preview_width\":%u,\"preview_height\":%u}\n",
                static_cast<unsigned long long>(frames_++), r.uiMs, turn.renderMs, turn.frameDone ? "true" : "false",
                turn.preview ? "true" : "false", r.restarted ? "true" : "false", r.panels ? "true" : "false",
                r.presented ? "true" : "false", turn.slicePaths, r.framePaths, turn.previewWidth, turn.previewHeight);
  file_.append(line, /*durable=*/false);
}

}  // namespace raylab

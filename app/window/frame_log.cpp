#include "app/window/frame_log.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace raylab {

FrameLog::FrameLog(const std::string& path) : file_(std::fopen(path.c_str(), "w")) {
  if (!file_) throw std::runtime_error("cannot write --frame-log " + path + ": " + std::strerror(errno));
}

FrameLog::~FrameLog() {
  if (file_) std::fclose(file_);
}

void FrameLog::write(const UiFrameRecord& r, const RenderTurn& turn) {
  std::fprintf(file_,
               "{\"ui_frame\":%llu,\"ui_ms\":%.3f,\"render_ms\":%.3f,\"frame_done\":%s,\"preview\":%s,"
               "\"restarted\":%s,\"panels\":%s,\"presented\":%s,\"slice_paths\":%u,\"frame_paths\":%u,\"preview_width\":%u,\"preview_height\":%u}\n",
               static_cast<unsigned long long>(frames_++), r.uiMs, turn.renderMs, turn.frameDone ? "true" : "false",
               turn.preview ? "true" : "false", r.restarted ? "true" : "false", r.panels ? "true" : "false",
               r.presented ? "true" : "false", turn.slicePaths, r.framePaths, turn.previewWidth, turn.previewHeight);
  std::fflush(file_);  // a log of a run that is killed still ends on a whole line
}

}  // namespace raylab

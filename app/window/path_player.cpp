#include "app/window/path_player.h"

namespace raylab {

void PathPlayer::play(PathRender path) {
  path_ = std::move(path);
  frame_ = 0;
  playing_ = path_.frames > 0;
  due_ = playing_;
  moved_ = false;
}

std::optional<Viewpoint> PathPlayer::moveIfDue(PathTracer& tracer) {
  if (!playing_ || !due_) return std::nullopt;
  due_ = false;
  current_ = movePathCamera(tracer, path_, frame_).view;
  moved_ = true;
  return current_;
}

bool PathPlayer::holds(const Viewpoint& v) const {
  return !moved_ || sameCamera(v, current_);
}

bool PathPlayer::frameDone() {
  if (!playing_ || due_) return false;  // a frame finished before the path's camera went in is not the path's
  if (frame_ + 1 >= path_.frames) {
    playing_ = false;
    return true;
  }
  ++frame_;
  due_ = true;
  return false;
}

}  // namespace raylab

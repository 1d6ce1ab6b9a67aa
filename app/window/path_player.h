// Playing a camera path in the window (`raylab --camera-path FILE|builtin:NAME`, P, the Play button): one
// path frame per completed render frame. Each path frame's camera goes into the tracer through
// movePathCamera, the very step `raylab render|bench --camera-path` replays with, so the accumulation
// restarts every frame and the length caches, the sort policy's costs and the key grid behave as under
// SettingsChange::cameraMove exactly as in those commands. The window's fly camera follows the path and
// takes no input while it plays; the render frames' statistics reach the panels as any frame's do.
#pragma once

#include <cstdint>
#include <optional>

#include "app/camera_path/render_camera_path.h"

namespace raylab {

class PathTracer;

class PathPlayer {
 public:
  // Plays `path` from its frame 0.
  void play(PathRender path);
  void stop() { playing_ = false; }
  bool playing() const { return playing_; }
  uint32_t frame() const { return frame_; }
  uint32_t frames() const { return path_.frames; }
  const PathRender& path() const { return path_; }
  // While a path frame is due (at the start, and after each completed render frame), moves `tracer` to its
  // camera and returns that camera for the fly camera to take; otherwise (the frame moved to is still
  // rendering, or nothing plays) nothing.
  std::optional<Viewpoint> moveIfDue(PathTracer& tracer);
  // A render frame completed: it was the current path frame's, so the next one is due. True when that was
  // the path's last frame (playing stops).
  bool frameDone();
  // Whether `view` is the camera the path put in last (true before the first): one that is not was moved
  // some other way (a viewpoint button, a pasted camera, R), which ends the playing.
  bool holds(const Viewpoint& view) const;

 private:
  PathRender path_;
  bool playing_ = false;
  bool due_ = false;  // the current path frame's camera is not in the tracer yet
  uint32_t frame_ = 0;
  Viewpoint current_;  // the camera of the path frame moved in last
  bool moved_ = false;  // current_ is set: a path frame was moved in since play()
};

}  // namespace raylab

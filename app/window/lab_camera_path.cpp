// The lab window's camera paths (issue 37): playing one (path_player.h: the replay step render and bench
// use) and recording the fly camera into one (camera_path_recorder.h), saved beside the screenshots with a
// sidecar (recorded_path_file.h).
#include <cstdio>
#include <filesystem>

#include "app/camera_path/camera_path_builtin.h"
#include "app/cli_options.h"
#include "app/window/lab_window.h"
#include "app/window/recorded_path_file.h"
#include "app/window/screenshot.h"
#include "renderer/path_tracer.h"
#include "renderer/vk/vk_context.h"

namespace raylab {

// Each UI frame, before the tracer takes the settings and camera: a path made for another scene stops; a
// path frame that is due goes into the tracer and the fly camera (the same camera, so syncTracer moves
// nothing again); a recording takes the camera this UI frame renders.
void LabWindow::stepCameraPath() {
  if (pathPlayer_.playing() && settings_.scene != pathScene_) {
    pathPlayer_.stop();
    cameraModel_.path.status = "the path stopped: another scene was loaded";
  } else if (pathPlayer_.playing() && !pathPlayer_.holds(camera_.viewpoint())) {
    pathPlayer_.stop();
    cameraModel_.path.status = "the path stopped: the camera was moved";
  }
  if (std::optional<Viewpoint> v = pathPlayer_.moveIfDue(*tracer_)) camera_.reset(*v, camera_.speed());
  if (!recorder_.recording()) return;
  // A path belongs to the scene it was flown in: a new scene ends the recording (saved as it was).
  if (recorder_.frames() > 0 && recording_.settings.scene != settings_.scene) {
    finishRecording();
    return;
  }
  if (recorder_.frames() == 0) {
    recording_.camera = camera_.viewpoint();
    recording_.camera.name = settings_.view;
  }
  recorder_.add(camera_.viewpoint());
  recording_.settings = settings_;
  recording_.stats = ui_.lastStats();
}

// A render frame completed: during a path, the next path frame is due.
void LabWindow::onPathFrameDone() {
  if (!pathPlayer_.frameDone()) return;
  char text[160];
  std::snprintf(text, sizeof(text), "played %u frames of the path", pathPlayer_.frames());
  cameraModel_.path.status = text;
  panelsDirty_ = true;
}

void LabWindow::togglePathPlayback() {
  if (pathPlayer_.playing()) {
    pathPlayer_.stop();
    char text[160];
    std::snprintf(text, sizeof(text), "stopped at frame %u of %u", pathPlayer_.frame(), pathPlayer_.frames());
    cameraModel_.path.status = text;
  } else if (!cameraModel_.path.spec.empty()) {
    playCameraPath(cameraModel_.path.spec);
  }
  panelsDirty_ = true;
}

// Resolved again for the current scene (a built-in name means that scene's path); a path that cannot be
// played is said in the panel, and the lab goes on.
void LabWindow::playCameraPath(const std::string& spec) {
  try {
    pathPlayer_.play(pathRenderFor(spec, scene_.scene, std::nullopt));
  } catch (const UsageError& e) {
    cameraModel_.path.status = e.what();
    return;
  }
  pathScene_ = settings_.scene;
  cameraModel_.path.status.clear();
}

void LabWindow::togglePathRecording() {
  panelsDirty_ = true;
  if (recorder_.recording()) {
    finishRecording();
    return;
  }
  recorder_.start(sceneUp(scene_.scene));
  recording_ = SidecarContent{};
  recording_.device = ctx_->info();
  cameraModel_.path.status = "recording: one keyframe per UI frame";
}

// Saves the recording, if one runs. A path that could not be written or replayed is a failed write: said
// in the panel and on stderr, and the lab exits 1 at the end.
void LabWindow::finishRecording() {
  if (!recorder_.recording()) return;
  const std::string name = freshScreenshotName(options_.screenshotDir, "path");
  const std::string file = (std::filesystem::path(options_.screenshotDir) / (name + ".path.json")).string();
  std::string& status = cameraModel_.path.status;
  try {
    const std::optional<CameraPath> path = recorder_.stop(file);
    if (!path) {
      status = "nothing recorded";
      return;
    }
    const std::string written = writeRecordedPath(options_.screenshotDir, name, *path, recording_);
    status = "saved " + written + " (" + std::to_string(path->frames) + " frames), sidecar " + name + ".json";
    cameraModel_.path.spec = written;  // Play replays it
    std::fprintf(stderr, "raylab: saved %s (%u frames)\n", written.c_str(), path->frames);
  } catch (const CameraPathError& e) {
    status = std::string("the recorded path cannot be replayed, not saved: ") + e.what();
    reportWriteFailure(status);
  } catch (const std::exception& e) {  // WriteError, a folder that cannot be made
    status = std::string("camera path not saved: ") + e.what();
    reportWriteFailure(status);
  }
}

void LabWindow::fillCameraPathModel() {
  CameraPathModel& m = cameraModel_.path;
  m.playing = pathPlayer_.playing();
  m.frame = pathPlayer_.frame();
  m.frames = pathPlayer_.frames();
  m.recording = recorder_.recording();
  m.recordedFrames = recorder_.frames();
}

}  // namespace raylab

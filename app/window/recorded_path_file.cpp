#include "app/window/recorded_path_file.h"

#include <filesystem>
#include <stdexcept>

#include "app/camera_path/camera_path_file.h"
#include "renderer/checked_write.h"

namespace raylab {

std::string writeRecordedPath(const std::string& dir, const std::string& name, const CameraPath& path,
                              SidecarContent content) {
  namespace fs = std::filesystem;
  std::error_code error;
  fs::create_directories(dir, error);
  if (error) throw std::runtime_error("cannot create the folder '" + dir + "' for the camera path: " + error.message());
  const fs::path pathFile = fs::path(dir) / (name + ".path.json");
  const fs::path sidecarFile = fs::path(dir) / (name + ".json");
  writeFileChecked(pathFile.string(), cameraPathFileText(path));
  content.kind = "camera-path";
  content.settings.frames = path.frames;  // one image per path frame, as the replay renders it
  nlohmann::json sidecar = makeSidecar(content);
  // A path has no image of its own; the render size is in the settings.
  sidecar.erase("image"), sidecar.erase("image_width"), sidecar.erase("image_height");
  sidecar["camera_path"] = pathFile.filename().string();
  sidecar["path_frames"] = path.frames;
  sidecar["replay"] = "raylab render --settings " + sidecarFile.filename().string() + " --camera-path " +
                      pathFile.filename().string();
  try {
    writeFileChecked(sidecarFile.string(), sidecar.dump(2) + "\n");
  } catch (const WriteError&) {
    fs::remove(pathFile, error);
    throw;
  }
  return pathFile.string();
}

}  // namespace raylab

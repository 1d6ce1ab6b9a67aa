#include "app/window/screenshot.h"

#include <ctime>
#include <filesystem>
#include <stdexcept>

#include "app/heatmap_legend_image.h"
#include "renderer/checked_write.h"
#include "renderer/png_writer.h"

namespace raylab {

std::string writeScreenshot(const std::string& dir, const std::string& name, const std::vector<uint32_t>& rgba,
                            SidecarContent content) {
  namespace fs = std::filesystem;
  std::error_code error;
  fs::create_directories(dir, error);
  if (error) throw std::runtime_error("cannot create screenshot folder '" + dir + "': " + error.message());
  const fs::path png = fs::path(dir) / (name + ".png");
  // A heatmap render carries its legend (the window's own legend is in a window screenshot already).
  const HeatmapStats noLegend;
  const LegendImage image = withHeatmapLegend(rgba, content.imageWidth, content.imageHeight,
                                              content.kind == "render" ? content.stats.heatmap : noLegend);
  content.imageHeight = image.height;
  writePng(png.string(), image.width, image.height, image.rgba);
  content.image = png.filename().string();
  const fs::path json = fs::path(dir) / (name + ".json");
  try {
    writeFileChecked(json.string(), makeSidecar(content).dump(2) + "\n");
  } catch (const WriteError&) {
    fs::remove(png, error);  // a shot is its PNG and its sidecar, or nothing: a PNG alone cannot be re-rendered
    throw;
  }
  return png.string();
}

std::string freshScreenshotName(const std::string& dir, const std::string& kind) {
  char stamp[32];
  std::time_t now = std::time(nullptr);
  std::strftime(stamp, sizeof(stamp), "%Y%m%d-%H%M%S", std::localtime(&now));
  std::string base = kind + "-" + stamp, name = base;
  // NAME.json too: a recorded camera path (recorded_path_file.h) has a sidecar and no PNG.
  for (int i = 2; std::filesystem::exists(std::filesystem::path(dir) / (name + ".png")) ||
                  std::filesystem::exists(std::filesystem::path(dir) / (name + ".json"));
       ++i)
    name = base + "-" + std::to_string(i);
  return name;
}

}  // namespace raylab

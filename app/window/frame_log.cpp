#include "app/window/frame_log.h"

#include <cstdio>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

namespace raylab {
namespace {

// A completed render frame as headless `raylab render --stats` measures it: GPU and wall time, each
// stage's total over the bounces, and which bounces were sorted after and why (the sort policy's plan).
nlohmann::json frameJson(const FrameStats& stats, const Settings& settings) {
  std::map<std::string, double> stages;
  for (const StageTime& t : stats.stages) stages[t.stage] += t.ms;
  nlohmann::json sorted = nlohmann::json::array(), reasons = nlohmann::json::array();
  for (const BounceStats& b : stats.bounces) sorted.push_back(b.sortedAfter), reasons.push_back(b.sortReason);
  // The heatmap pixel the readout shows (the pointer over the image), or null: what tests check against
  // real pointer motion (tests/cli/gpu/window_hover.sh).
  const HeatmapProbe& probe = stats.heatmap.probe;
  const nlohmann::json hover =
      probe.valid ? nlohmann::json{{"x", probe.x}, {"y", probe.y}, {"state", probe.state}} : nlohmann::json(nullptr);
  return {{"frame", stats.frameIndex},
          {"gpu_frame_ms", stats.frameMs},
          {"wall_ms", stats.wallMs},
          {"strategy", toString(settings.strategy)},
          {"sort_policy", toString(settings.sortPolicy)},
          {"stages", stages},
          {"sorted_after", sorted},
          {"hover", hover},
          {"sort_reasons", reasons}};
}

}  // namespace

FrameLog::FrameLog(const std::string& path) : file_(path, AppendFile::Start::Empty) {}

void FrameLog::write(const UiFrameRecord& r, const RenderTurn& turn, const Settings& settings) {
  char head[512];
  std::snprintf(head, sizeof(head),
                "{\"ui_frame\":%llu,\"ui_ms\":%.3f,\"render_ms\":%.3f,\"frame_done\":%s,\"preview\":%s,"
                "\"changed\":%s,\"restarted\":%s,\"panels\":%s,\"presented\":%s,\"steps\":%u,\"frame_steps\":%u,"
                "\"frame_paths\":%u,\"preview_width\":%u,\"preview_height\":%u",
                static_cast<unsigned long long>(frames_++), r.uiMs, turn.renderMs, turn.frameDone ? "true" : "false",
                turn.preview ? "true" : "false", r.changed ? "true" : "false", r.restarted ? "true" : "false",
                r.panels ? "true" : "false", r.presented ? "true" : "false", turn.steps, turn.frameSteps, r.framePaths,
                turn.previewWidth, turn.previewHeight);
  std::string line = head;
  if (turn.frameDone) line += ",\"frame\":" + frameJson(*turn.frameDone, settings).dump();
  line += "}\n";
  file_.append(line, /*durable=*/false);
}

}  // namespace raylab

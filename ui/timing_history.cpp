#include "ui/timing_history.h"

#include <algorithm>

namespace raylab {

void TimingHistory::push(const FrameStats& stats) {
  Frame f;
  f.gpuMs = static_cast<float>(stats.frameMs);
  f.wallMs = static_cast<float>(stats.wallMs);
  f.stageMs.assign(stages_.size(), 0.0f);
  for (const StageTime& t : stats.stages) {
    auto it = std::find(stages_.begin(), stages_.end(), t.stage);
    size_t i = static_cast<size_t>(it - stages_.begin());
    if (it == stages_.end()) stages_.push_back(t.stage);
    if (i >= f.stageMs.size()) f.stageMs.resize(i + 1, 0.0f);
    f.stageMs[i] += static_cast<float>(t.ms);
  }
  frames_.push_back(std::move(f));
  if (frames_.size() > capacity_) frames_.pop_front();
}

void TimingHistory::clear() {
  frames_.clear();
  stages_.clear();
}

std::vector<float> TimingHistory::frameMs() const {
  std::vector<float> v;
  for (const Frame& f : frames_) v.push_back(f.gpuMs);
  return v;
}

std::vector<float> TimingHistory::wallMs() const {
  std::vector<float> v;
  for (const Frame& f : frames_) v.push_back(f.wallMs);
  return v;
}

std::vector<float> TimingHistory::stageMs(const std::string& stage) const {
  auto it = std::find(stages_.begin(), stages_.end(), stage);
  size_t i = static_cast<size_t>(it - stages_.begin());
  std::vector<float> v;
  for (const Frame& f : frames_) v.push_back(i < f.stageMs.size() ? f.stageMs[i] : 0.0f);
  return v;
}

}  // namespace raylab

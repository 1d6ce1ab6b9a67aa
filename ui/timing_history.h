// A scrolling record of the last frames' timings, per stage summed over bounces, for the timing plots.
#pragma once

#include <deque>
#include <string>
#include <vector>

#include "renderer/frame_stats.h"

namespace raylab {

class TimingHistory {
 public:
  explicit TimingHistory(size_t capacity = 240) : capacity_(capacity) {}
  void push(const FrameStats& stats);
  void clear();

  // Stage names in the order they first appeared.
  const std::vector<std::string>& stages() const { return stages_; }
  // Milliseconds per frame, oldest first: the whole frame (GPU), host wall time, or one stage.
  std::vector<float> frameMs() const;
  std::vector<float> wallMs() const;
  std::vector<float> stageMs(const std::string& stage) const;
  size_t size() const { return frames_.size(); }

 private:
  struct Frame {
    float gpuMs = 0.0f, wallMs = 0.0f;
    std::vector<float> stageMs;  // indexed like stages_
  };
  size_t capacity_;
  std::vector<std::string> stages_;
  std::deque<Frame> frames_;
};

}  // namespace raylab

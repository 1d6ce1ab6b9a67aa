// Whether the length cache a window screenshot shows learned over the same frames as a headless re-render of
// its sidecar. A re-render starts its cache and its accumulation together and learns over the sidecar's
// frames only; the window's cache outlives camera moves (without a camera-clamped grid) and learns on while
// the strategy or grid changes (a new grid starts a new cache; a new strategy can keep the old one). Keys,
// the cache heatmaps and the prediction statistics read the cache, the image never does (the invariant), so
// only those can differ. Plain C++, fed after each finished frame (tests/cpu/test_learned_history.cpp).
#pragma once

#include <cstdint>
#include <string>

namespace raylab {

struct LearnedState {
  bool reproducible = true;
  std::string note;  // what the sidecar says about it (empty where the strategy learns nothing)
};

class LearnedHistory {
 public:
  // After every finished render frame: which tracer (a new scene makes a new one, with a new cache), its
  // accumulated frames after this frame, and KeyStage::cacheEpoch().
  void onFrame(const void* tracer, uint32_t accumulated, uint64_t cacheEpoch) {
    const bool fresh = tracer != tracer_;
    if (accumulated == 1) {
      // The accumulation starts here: the cache started with it when it is new since the frame before.
      cleanStart_ = fresh || cacheEpoch != lastEpoch_;
      startEpoch_ = cacheEpoch;
    } else if (fresh) {
      cleanStart_ = false;  // a tracer met mid-accumulation: its history is unknown
      startEpoch_ = cacheEpoch;
    }
    tracer_ = tracer;
    lastEpoch_ = cacheEpoch;
  }

  // At a screenshot of `frames` accumulated frames, with a strategy that learns lengths or not.
  LearnedState state(bool learns, uint32_t frames, uint64_t cacheEpoch) const {
    if (!learns) return {};
    const std::string n = std::to_string(frames);
    if (cleanStart_ && cacheEpoch == startEpoch_)
      return {true, "the length cache learned over this image's " + n + " frames only, as a re-render's does"};
    return {false, "the length cache also learned before this image's " + n +
                       " frames (camera moves, or strategy or grid changes, kept it): a re-render learns over the " + n +
                       " frames only, so its keys, cache heatmaps and prediction statistics can differ; the image "
                       "cannot. To reproduce them: press L in the window (restart learning: a fresh cache and "
                       "accumulation), or a script's restart-learning, then take the screenshot again"};
  }

 private:
  const void* tracer_ = nullptr;
  uint64_t lastEpoch_ = 0, startEpoch_ = 0;
  bool cleanStart_ = false;
};

}  // namespace raylab

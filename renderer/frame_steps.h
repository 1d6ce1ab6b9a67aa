// One step of a frame (PathTracer::recordSteps): a stage over the whole frame, recorded by a closure that
// holds what the frame loop decided for it (state set, bounce, fusions) when the frame's steps were built.
// A window submits a few consecutive steps per UI frame; a step never covers part of the frame's paths, so
// it computes exactly what the same stage computes in a whole frame.
#pragma once

#include <functional>
#include <string>

#include <vulkan/vulkan.h>

namespace raylab {

struct FrameStep {
  const char* name = "";  // its kind: the stage it records (setup, generate, trace, shade, keys, sort, ...)
  int bounce = -1;        // the bounce it belongs to (-1: outside the bounce loop)
  std::function<void(VkCommandBuffer)> record;
};

// The GPU time one recorded step took: its kind, bounce and the sum of the stage scopes it recorded.
struct StepTime {
  std::string name;
  int bounce = -1;
  double ms = 0.0;
};

}  // namespace raylab

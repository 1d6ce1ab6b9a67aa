// Measures one benchmark cell on a PathTracer: warm-up frames, timed frames (median/min/max per stage,
// image error against a reference after each frame), then one untimed frame in the counting/detailed
// modes for SIMT efficiency, virtual warp efficiency and prediction accuracy.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/path_tracer.h"

namespace raylab {

struct Spread {
  double median = 0.0, min = 0.0, max = 0.0;
};
Spread spreadOf(std::vector<double> values);

struct CellResult {
  Spread frameMs;                         // GPU time of the whole frame
  Spread wallMs;
  std::map<std::string, Spread> stageMs;  // per stage name, summed over bounces
  Spread traceAfterFirstMs;               // trace stage, bounces >= 1
  std::vector<double> errorCurveMs;       // cumulative GPU ms after each timed frame
  std::vector<double> errorCurveRelMse;   // relative MSE against the reference after each timed frame
  double raysPerSecond = 0.0;
  FrameStats detailed;                    // the counting/detailed frame
};

CellResult measureCell(PathTracer& tracer, const Settings& settings, uint32_t warmup, uint32_t timed,
                       const std::vector<glm::vec3>& reference, bool detailFrame);

nlohmann::json toJson(const CellResult& r);

}  // namespace raylab

// The frames of one `raylab render`, summed (still camera or camera path alike), for its summary line and
// its --stats file.
#pragma once

#include <cstdint>

#include <nlohmann/json.hpp>

#include "app/radiance_digest.h"
#include "renderer/path_tracer.h"
#include "renderer/stats_json.h"

namespace raylab {

// All frames, and those after the first (frame 0 pays for first use: pipeline compilation, page faults, a
// GPU's clocks rising), which the rate is quoted over.
struct RenderTotals {
  nlohmann::json frames = nlohmann::json::array();  // per frame, with --stats only
  double gpuMs = 0.0, wallMs = 0.0;
  uint64_t rays = 0;
  double laterWorkMs = 0.0, laterWallMs = 0.0;  // frames 1 on: GPU work time (instrument passes excluded), wall
  uint64_t laterRays = 0;
  uint32_t frameCount = 0;
  bool budgetSpent = false;  // the time budget ended the render before --frames did
  // Rays a second over frames 1 on (frame 0 alone for a one-frame render): GPU work time, wall time without it.
  double raysPerSecond() const {
    const bool later = frameCount > 1;
    const double ms = later ? (laterWorkMs > 0.0 ? laterWorkMs : laterWallMs) : (gpuMs > 0.0 ? gpuMs : wallMs);
    return ms > 0 ? (later ? laterRays : rays) / (ms * 1e-3) : 0.0;
  }
  // Adds frame `f`'s figures (f: the frame's number in this render).
  template <class Stats>
  void add(uint32_t f, const Stats& st) {
    gpuMs += st.frameMs;
    wallMs += st.wallMs;
    rays += st.raysTraced;
    if (f > 0) laterWorkMs += st.workMs(), laterWallMs += st.wallMs, laterRays += st.raysTraced;
    ++frameCount;
  }
};

// Frame `f` of a render: detailed where --detail-every says (with --stats only), rendered, added to `t`, and
// with --stats its JSON appended to t.frames. Returns that JSON for the caller's own fields (nullptr without
// --stats). `digest` (--frame-digests): the JSON has the frame's "radiance_digest" (radiance_digest.h).
inline nlohmann::json* renderCountedFrame(PathTracer& tracer, uint32_t f, bool stats, uint32_t detailEvery,
                                          RenderTotals& t, bool digest = false) {
  tracer.setDetailedStats(stats && detailEvery > 0 && f % detailEvery == 0);
  const FrameStats& st = tracer.renderFrame();
  t.add(f, st);
  if (!stats) return nullptr;
  nlohmann::json frame = toJson(st);
  frame["detailed"] = tracer.detailedStats();
  if (digest) frame["radiance_digest"] = radianceDigest(tracer.readRadiance());
  t.frames.push_back(std::move(frame));
  return &t.frames.back();
}

}  // namespace raylab

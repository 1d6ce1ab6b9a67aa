// What the heatmap pass reports with each frame (FrameStats::heatmap): the colour range and its unit and
// scale for the legend, how many pixels had a value, a path without a value or no path, why a shown view is
// empty, and the hovered pixel's data when the window asked for it (HeatmapPass::setProbe).
#pragma once

#include <cstdint>
#include <string>

#include <glm/glm.hpp>

namespace raylab {

// The data of one pixel of the heatmap shown (what the hover readout prints).
struct HeatmapProbe {
  bool valid = false;    // a probe was asked for and read back this frame
  uint32_t x = 0, y = 0;
  std::string state;     // "value", or why there is none ("no path at this bounce", "no cache entry", ...)
  double value = 0.0;    // the view's value (the key for sort keys, the rank when ranking)
  bool hasPath = false;
  uint32_t pathId = 0;
  bool hasKey = false;
  uint32_t key = 0;
  bool hasCell = false;
  glm::uvec3 cell{0};    // the key's cell (sort keys; direction keys: octahedral u, v), else the ray origin's
  std::string cellKind;  // "key cell", "direction cell" or "origin cell"
  uint32_t octant = 0;   // the ray direction's octant (bit k: component k negative)
};

struct HeatmapStats {
  std::string view;          // the view drawn this frame; empty: the render
  uint32_t bounce = 0;
  std::string unit;          // the quantity the colours stand for ("traversal steps")
  std::string scale;         // "linear" or "log" (sort keys by cell or hash: "categorical")
  std::string keyColour;     // sort keys: "cell", "rank" or "hash"
  double min = 0.0, max = 0.0;            // the colour range's ends (locked, natural, or the frame's)
  bool rangeLocked = false;               // the range stays put (locked by the user, or the view's natural one)
  double frameMin = 0.0, frameMax = 0.0;  // the values this frame held
  uint32_t pixels = 0;                    // in the image
  uint32_t pixelsWithValue = 0;
  uint32_t pixelsWithoutValue = 0;        // a path, but no value (noValueMeaning)
  uint32_t pixelsWithoutPath = 0;         // no path of the pixel reached the bounce
  std::string noValueMeaning;             // "no cache entry (never learned)", "escaped: no actual cell"
  std::string emptyReason;                // set when the view shows nothing at all this frame, and why
  HeatmapProbe probe;
};

}  // namespace raylab

#include "ui/label_placement.h"

#include <algorithm>
#include <limits>

namespace raylab {
namespace {

constexpr int kRings = 6;

float overlapArea(const Box& a, const Box& b) {
  float w = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), h = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  return w > 0 && h > 0 ? w * h : 0.0f;
}

// Shifted into the area (as far as it fits).
Box clampInto(Box b, const Box& area) {
  float dx = b.x1 > area.x1 ? area.x1 - b.x1 : 0.0f, dy = b.y1 > area.y1 ? area.y1 - b.y1 : 0.0f;
  b.x0 += dx, b.x1 += dx, b.y0 += dy, b.y1 += dy;
  dx = b.x0 < area.x0 ? area.x0 - b.x0 : 0.0f, dy = b.y0 < area.y0 ? area.y0 - b.y0 : 0.0f;
  b.x0 += dx, b.x1 += dx, b.y0 += dy, b.y1 += dy;
  return b;
}

// The eight places around (x, y) at distance d: right, left, above, below, then the corners.
std::vector<Box> around(const LabelRequest& r, float d) {
  const float w = r.width, h = r.height, x = r.x, y = r.y;
  const float tops[] = {y - h / 2, y - h / 2, y - d - h, y + d, y - d - h, y - d - h, y + d, y + d};
  const float lefts[] = {x + d, x - d - w, x - w / 2, x - w / 2, x + d, x - d - w, x + d, x - d - w};
  std::vector<Box> boxes;
  for (int i = 0; i < 8; ++i) boxes.push_back({lefts[i], tops[i], lefts[i] + w, tops[i] + h});
  return boxes;
}

}  // namespace

std::vector<LabelPlacement> placeLabels(const std::vector<LabelRequest>& labels, const Box& area, float markerRadius) {
  std::vector<Box> taken;  // every marker, then each label as it is placed
  for (const LabelRequest& r : labels)
    taken.push_back({r.x - markerRadius, r.y - markerRadius, r.x + markerRadius, r.y + markerRadius});
  std::vector<LabelPlacement> out;
  for (const LabelRequest& r : labels) {
    LabelPlacement best;
    float bestOverlap = std::numeric_limits<float>::max();
    for (int ring = 0; ring < kRings && bestOverlap > 0.0f; ++ring) {
      float d = markerRadius + 2.0f + ring * (r.height + 2.0f);
      for (const Box& candidate : around(r, d)) {
        Box b = clampInto(candidate, area);
        float overlap = 0.0f;
        for (const Box& t : taken) overlap += overlapArea(b, t);
        if (overlap < bestOverlap) {
          bestOverlap = overlap;
          // A label pushed away from its marker (outer ring, or shifted by the edge) points back to it.
          float gapX = std::max({b.x0 - r.x, r.x - b.x1, 0.0f}), gapY = std::max({b.y0 - r.y, r.y - b.y1, 0.0f});
          best = {b, std::max(gapX, gapY) > markerRadius + 4.0f};
        }
        if (overlap == 0.0f) break;
      }
    }
    taken.push_back(best.box);
    out.push_back(best);
  }
  return out;
}

}  // namespace raylab

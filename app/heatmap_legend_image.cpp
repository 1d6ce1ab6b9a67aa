#include "app/heatmap_legend_image.h"

#include <algorithm>
#include <cstdio>

#include <glm/glm.hpp>
#include <stb/stb_easy_font.h>

#include "renderer/heatmap/heatmap_colours.h"

namespace raylab {
namespace {

constexpr uint32_t kBackground = 0xFF141414u;
constexpr uint32_t kText = 0xFFE6E6E6u;

struct Canvas {
  std::vector<uint32_t>& rgba;
  uint32_t width, height;
  void fill(int x0, int y0, int x1, int y1, uint32_t colour) {
    x0 = std::max(x0, 0), y0 = std::max(y0, 0);
    x1 = std::min<int>(x1, int(width)), y1 = std::min<int>(y1, int(height));
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) rgba[size_t(y) * width + size_t(x)] = colour;
  }
  // stb_easy_font's quads, scaled; returns the text's width in pixels.
  int text(int x, int y, const std::string& s, uint32_t scale) {
    static char quads[60000];
    std::string copy = s;
    const int n = stb_easy_font_print(0, 0, copy.data(), nullptr, quads, sizeof(quads));
    for (int q = 0; q < n; ++q) {
      const float* v = reinterpret_cast<const float*>(quads + q * 4 * 16);  // 4 vertices of 16 bytes
      const float* w = reinterpret_cast<const float*>(quads + q * 4 * 16 + 2 * 16);
      fill(x + int(v[0] * scale), y + int(v[1] * scale), x + int(w[0] * scale), y + int(w[1] * scale), kText);
    }
    return textWidth(s, scale);
  }
  static int textWidth(const std::string& s, uint32_t scale) {
    std::string copy = s;
    return stb_easy_font_width(copy.data()) * int(scale);
  }
};

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.4g", v);
  return text;
}

bool usesRamp(const HeatmapStats& h) { return h.scale == "linear" || h.scale == "log"; }

// The bar: the ramp for scalar views and ranks; the cell colours along the grid's diagonal for keys by
// cell; hit and miss halves for cell-hit; none for hashed keys.
void drawBar(Canvas& c, const LegendLayout& l, uint32_t top, const HeatmapStats& h) {
  const int y0 = int(top + l.barTop), y1 = int(top + l.barBottom);
  const uint32_t span = std::max(1u, l.barRight - l.barLeft - 1);
  for (uint32_t x = l.barLeft; x < l.barRight; ++x) {
    const float t = float(x - l.barLeft) / float(span);
    glm::vec3 colour;
    if (h.view == "cell-hit") colour = cellHitColour(t >= 0.5f);
    else if (h.keyColour == "cell") {
      // Three ramps, one per axis (x red, y green, z blue): one ramp along the diagonal was a grey
      // gradient that meant nothing for colours made of three positions.
      const int axis = std::min(2, int(t * 3.0f));
      glm::vec3 c(0.0f);
      c[axis] = std::clamp(t * 3.0f - float(axis), 0.0f, 1.0f);
      colour = c;
    }
    else if (usesRamp(h)) colour = heatmapRamp(t);
    else return;  // hashed keys have no order to show
    c.fill(int(x), y0, int(x) + 1, y1, packColour(colour));
  }
}

}  // namespace

LegendLayout LegendLayout::forWidth(uint32_t width) {
  LegendLayout l;
  l.scale = width >= 640 ? 2 : 1;
  const uint32_t s = l.scale;
  l.height = 53 * s;
  l.barTop = 3 * s, l.barBottom = 13 * s;
  const uint32_t pad = std::min(4 * s, width / 4);
  l.barLeft = pad, l.barRight = width > pad ? width - pad : width;
  l.textTop = 16 * s;
  return l;
}

LegendImage withHeatmapLegend(const std::vector<uint32_t>& image, uint32_t width, uint32_t height, const HeatmapStats& h) {
  LegendImage out{image, width, height};
  if (h.view.empty() || width == 0) return out;
  const LegendLayout l = LegendLayout::forWidth(width);
  out.height = height + l.height;
  out.rgba.resize(size_t(width) * out.height, kBackground);
  Canvas c{out.rgba, width, out.height};
  const int s = int(l.scale), top = int(height);
  drawBar(c, l, height, h);
  const int textY = top + int(l.textTop);
  // Min left, max right, what the colours stand for between (hashed keys, cell-hit: no numbers to show).
  std::string middle = h.view + ", bounce " + std::to_string(h.bounce);
  if (h.view == "cell-hit") {
    c.text(int(l.barLeft), textY, "hit", l.scale);
    c.text(int(l.barRight) - Canvas::textWidth("miss", l.scale), textY, "miss", l.scale);
  } else if (h.keyColour == "cell") {
    const int third = int(l.barRight - l.barLeft) / 3;
    for (int a = 0; a < 3; ++a) c.text(int(l.barLeft) + a * third + 2 * s, textY, a == 0 ? "x" : a == 1 ? "y" : "z", l.scale);
    middle = "key cell: x red, y green, z blue (low to high)";
  } else if (h.keyColour == "hash") {
    middle = "hashed keys: equal keys alike";
  } else {
    c.text(int(l.barLeft), textY, number(h.min), l.scale);
    const std::string hi = number(h.max);
    c.text(int(l.barRight) - Canvas::textWidth(hi, l.scale), textY, hi, l.scale);
    middle = h.unit + " (" + h.scale + (h.rangeLocked ? ", fixed range)" : ", frame's range)");
  }
  c.text(int(l.barLeft), textY + 9 * s, middle, l.scale);
  // The colours that are not values, with their shares of the image, one a row.
  const int x = int(l.barLeft), box = 7 * s;
  int swatchY = top + 34 * s;
  auto swatch = [&](const glm::vec3& colour, const std::string& text, uint32_t count) {
    char pct[16];
    std::snprintf(pct, sizeof(pct), " %.1f%%", h.pixels ? 100.0 * count / h.pixels : 0.0);
    c.fill(x, swatchY, x + box, swatchY + box, packColour(colour));
    c.text(x + box + 2 * s, swatchY, text + pct, l.scale);
    swatchY += 9 * s;
  };
  swatch(noPathColour(), "no path", h.pixelsWithoutPath);
  if (!h.noValueMeaning.empty()) swatch(noValueColour(), h.noValueMeaning, h.pixelsWithoutValue);
  return out;
}

std::string heatmapLegendLine(const HeatmapStats& h) {
  if (h.view.empty()) return "";
  std::string line = h.view + " bounce " + std::to_string(h.bounce) + ": ";
  if (usesRamp(h))
    line += number(h.min) + " .. " + number(h.max) + " " + h.unit + " (" + h.scale +
            (h.rangeLocked ? ", fixed range" : ", frame's range") + ")";
  else
    line += h.unit + (h.keyColour.empty() ? "" : " coloured by " + h.keyColour);
  auto pct = [&](uint32_t n) { return number(h.pixels ? 100.0 * n / h.pixels : 0.0) + "%"; };
  line += "; pixels: " + pct(h.pixelsWithValue) + " value, " + pct(h.pixelsWithoutPath) + " no path";
  if (!h.noValueMeaning.empty()) line += ", " + pct(h.pixelsWithoutValue) + " " + h.noValueMeaning;
  return line;
}

}  // namespace raylab

// The hover readout's input: while a heatmap is shown and the mouse is over the image (not over a panel),
// the render pixel under it is the tracer's heatmap probe (one 16-byte readback a frame); otherwise none.
#pragma once

namespace raylab {

class PathTracer;

// Call once per UI frame after the panels are drawn (ImGui knows then whether a panel holds the mouse).
// The image fills the window, so the pixel is the mouse position scaled by render size / window size.
void updateHeatmapHover(PathTracer& tracer, bool heatmapShown);

}  // namespace raylab

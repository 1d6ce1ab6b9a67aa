// Whether a panel cut off any of its text at its right edge, measured from what ImGui laid out, so the window
// screenshot's sidecar can say so and a test can require that nothing is cut off at 1280x720 (issue 38: the
// Timing line, the device name, an axis combo and a hint were cut). Two kinds of cut: an item that runs past
// the panel's work area (ImGui's widest cursor position, or a child such as a table that scrolls sideways),
// and a combo whose chosen value is wider than its box (ImGui clips it inside the box, so the panel's
// extent cannot show it): controls report those through fitsCombo.
#pragma once

#include <string>
#include <vector>

namespace raylab {

struct ClipReport {
  float hiddenWidth = 0.0f;        // how far the widest item or child content runs past the visible width
  std::vector<std::string> items;  // combo values cut inside their box this frame, by fitsCombo
};

// Before the panel's Begin..End: starts collecting fitsCombo's reports for it.
void startClipReport();
// After the panel's End: what the window `title` cut off this frame (nothing for a collapsed one).
ClipReport finishClipReport(const char* title);

// Inside a panel, before BeginCombo(label, preview) with the current item width: notes `preview` when it
// does not fit its box; returns whether it fits.
bool fitsCombo(const char* preview);

}  // namespace raylab

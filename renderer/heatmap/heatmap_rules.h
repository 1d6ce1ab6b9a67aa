// Which heatmap views given Settings can show. Most views read what a stage of the sorted wavefront writes
// (sort keys, predicted lengths, the length cache); when the settings run no such stage, the view has no
// data and this says why. One rule for everyone: the CLI refuses such settings (exit 2), the window greys
// the view out with the reason and shows the reason instead of the heatmap, and the renderer never gathers
// an unavailable view (the gather would read buffers that do not exist).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "renderer/settings/settings.h"

namespace raylab {

// Why `view` cannot be shown with `s` (its other fields), or nothing when it can.
std::optional<std::string> heatmapUnavailable(const Settings& s, HeatmapView view);
// The same for the view `s` asks for (s.heatmap).
inline std::optional<std::string> heatmapUnavailable(const Settings& s) { return heatmapUnavailable(s, s.heatmap); }
// The bounce a heatmap shows: the one asked for, within this path length (the request itself is kept, so
// a path length raised again shows the bounce asked for).
uint32_t heatmapBounceShown(const Settings& s);
// The view the renderer draws: s.heatmap when available, else None (the render).
HeatmapView heatmapShown(const Settings& s);

}  // namespace raylab

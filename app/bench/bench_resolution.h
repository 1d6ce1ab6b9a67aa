// What a sweep's rounds can and cannot tell apart (issue 34): per group of cells that race each other (one
// case, image size, samples per frame and bounce count), the fastest cell by median frame time over the
// rounds, the cells whose spread over the rounds overlaps its spread ("not distinguishable here") and those
// slower beyond it. The bench prints it at the end of a sweep and writes it to DIR/resolution.txt.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace raylab {

// From the cells' summaries (cellSummaries, app/bench/bench_rounds.h); empty for none.
std::string resolutionText(const std::vector<nlohmann::json>& cells);

}  // namespace raylab

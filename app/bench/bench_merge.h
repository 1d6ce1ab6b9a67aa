// `raylab bench --merge DIR... [--out-dir OUT] [--no-charts]`: the shard folders of one sweep (each made by
// `raylab bench ... --shard i/K`) put back together as the folder the unsharded sweep would have written:
// sweep.json (the whole sweep), results.jsonl with every cell's rounds in plan order, results.csv,
// cells.jsonl and resolution.txt (its rounds made one), and the charts; for a --camera-path sweep also
// path_frames.jsonl (the kept cell rounds' frames) with motion.json and motion.md from it. Refused with exit 2,
// before anything is written: folders of different sweeps or revisions, a shard missing or given twice, a
// shard that has not finished every round of its cells.
#pragma once

#include <string>
#include <vector>

namespace raylab {

// `args` are the bench's arguments, --merge among them; returns the exit code.
int runBenchMerge(const std::vector<std::string>& args);

}  // namespace raylab

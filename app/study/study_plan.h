// `raylab study`'s plan as a pure function of its options and preset: the image sizes in order, each with the
// arguments of its `raylab bench` sweep. A study's cells are the sizes' bench cells in that order (size by
// size, each size's cells in its bench plan's order); with --shard i/K the study runs its cells g (0-based,
// in that order) with g mod K = i, as bench's --shard does within one sweep. A size whose cells start at
// study cell o gives its bench `--shard ((i - o) mod K)/K`: the K study shards are then K distinct bench
// shards of every size, disjoint and together the whole size, and `raylab study --merge` merges each size
// with `raylab bench --merge`.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "app/bench/bench_shard.h"

namespace raylab {

// The standard study (issue 22) before --sizes, --bounces and --strategies.
struct StudyPreset {
  std::vector<std::string> sizes;
  std::string bounces, strategies, timedFrames, warmup, rounds;
};
StudyPreset studyPreset(bool quick, bool cpuDevice);
// A preset in words: "sizes 512x256, 2048x1024; 4 bounces; fixed, two-point; 6 timed frames after 3 warm-up;
// 3 rounds".
std::string presetText(const StudyPreset& preset);
// What --quick changes on a GPU or CPU device, from the presets themselves: for --help and the report's top.
std::string quickText(bool cpuDevice);

struct StudyOptions {
  std::string target;  // SCENE[@VIEW]
  std::string outDir = "study-out";
  bool quick = false;
  bool thesis = false;              // --thesis: the source study's table (app/study/study_thesis.h)
  std::vector<std::string> sizes;   // --sizes: the preset's otherwise
  std::string bounces, strategies;  // --bounces, --strategies: the preset's otherwise
  std::string rounds;               // --rounds: the preset's otherwise
  std::string device;
  std::vector<std::string> passOn;  // --validate flags, given to every bench run
  BenchShard shard;                 // --shard i/K (0/1: the whole study)
};

struct StudySize {
  std::string size;                    // WxH
  std::string folder;                  // OUT/size-WxH
  std::vector<std::string> benchArgs;  // the bench sweep of this size (with --shard when the study is sharded)
  size_t cells = 0;                    // the size's bench cells (all shards)
  size_t firstCell = 0;                // its first cell's index in the study
  BenchShard benchShard;               // which of its bench cells this study shard runs
  size_t shardCells() const;           // how many those are
};

// Throws UsageError for what bench would refuse (a bad size, strategy or scene name).
std::vector<StudySize> studyPlan(const StudyOptions& options, const StudyPreset& preset);

}  // namespace raylab

// `raylab study`'s plan as a pure function of its options and preset: the image sizes in order, each with the
// arguments of its `raylab bench` sweep. A study's cells are the sizes' bench cells in that order (size by
// size, each size's cells in its bench plan's order); with --shard i/K the study runs its cells g (0-based,
// in that order) with g mod K = i, as bench's --shard does within one sweep. A size whose cells start at
// study cell o gives its bench `--shard ((i - o) mod K)/K`: the K study shards are then K distinct bench
// shards of every size, disjoint and together the whole size, and `raylab study --merge` merges each size
// with `raylab bench --merge`.
// After the sizes come the motion sweeps (issue 37): one `raylab bench --camera-path` per built-in path of the
// scene (or the path given with --camera-path), at one size, so the report can say what reordering does under
// a moving camera.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "app/bench/bench_shard.h"

namespace raylab {

// The standard study (issue 22) before --sizes, --bounces and --strategies.
struct StudyPreset {
  std::vector<std::string> sizes;
  std::string bounces, strategies, timedFrames, warmup, rounds;
  std::string pathFrames;  // the motion sweeps' --frames: a camera path's first N frames (empty: all of it)
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
  std::string cameraPath;           // --camera-path FILE|builtin:NAME: the one motion sweep (empty: every built-in)
  bool noMotion = false;            // --no-motion: no motion sweeps (a study of still views only)
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

// One motion sweep: the study's strategies (always and auto, the unsorted wavefront being "never", and the
// megakernel) replaying one camera path with `raylab bench --camera-path`, whose motion.json the report reads.
struct StudyMotion {
  std::string path;                    // builtin:NAME or the given file
  std::string folder;                  // OUT/motion-NAME
  std::vector<std::string> benchArgs;
};

// The paths the motion sweeps replay: --camera-path's, else every built-in path of the target's scene
// (none for a scene without one). Throws UsageError for a path bench would refuse (a missing file, an
// unknown built-in), loading the scene as bench's checks do.
std::vector<std::string> studyMotionPaths(const StudyOptions& options);
// The motion sweeps of studyMotionPaths, at the largest of the study's sizes up to kMotionMaxPaths paths per
// frame (the size where a path's frames stay cheap enough to replay whole), the study's first bounce count,
// the preset's path-frame cap. None with --no-motion, and none with --shard: `raylab bench --merge` merges a
// path's frames, but `raylab study --merge` does not merge the motion sweeps' folders yet (kShardedMotionNote
// says so in the report).
inline constexpr uint64_t kMotionMaxPaths = 2048ull * 1024ull;
inline constexpr const char* kShardedMotionNote =
    "a sharded study measures no camera path: `raylab study --merge` does not merge the motion sweeps yet";
std::vector<StudyMotion> studyMotionPlan(const StudyOptions& options, const StudyPreset& preset,
                                         const std::vector<std::string>& paths);

}  // namespace raylab

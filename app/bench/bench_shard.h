// `raylab bench ... --shard i/K` runs a deterministic 1/K of a sweep's cells, so that a scheduler the user
// already has (GNU parallel over the GPUs of a host, a Slurm job array) can spread one sweep: the plan's
// cell order is fixed by the flags, and cell n (0-based, in plan order) belongs to shard n mod K. Shards are
// disjoint and together cover the plan; `raylab bench --merge DIR...` puts their folders back together.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "app/cli_options.h"

namespace raylab {

struct BenchShard {
  uint32_t index = 0, count = 1;  // 0 <= index < count; 0/1 is the whole sweep
  bool whole() const { return count == 1; }
  bool contains(size_t cell) const { return cell % count == index; }
  std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
  bool operator==(const BenchShard& o) const { return index == o.index && count == o.count; }
};

inline constexpr uint32_t kMaxShards = 4096;

// "i/K" with 0 <= i < K <= kMaxShards; throws UsageError naming the flag otherwise.
inline BenchShard parseShard(const std::string& text) {
  const size_t slash = text.find('/');
  auto number = [&](const std::string& part, uint32_t& out) {
    if (part.empty() || part.size() > 9 || part.find_first_not_of("0123456789") != std::string::npos) return false;
    out = static_cast<uint32_t>(std::stoul(part));
    return true;
  };
  BenchShard s;
  if (slash == std::string::npos || !number(text.substr(0, slash), s.index) || !number(text.substr(slash + 1), s.count) ||
      s.count < 1 || s.count > kMaxShards || s.index >= s.count)
    throw UsageError("--shard expects i/K with 0 <= i < K <= " + std::to_string(kMaxShards) + " (e.g. 0/3), got '" + text + "'");
  return s;
}

// `--shard i/K` taken out of the arguments (the whole sweep when absent).
inline BenchShard takeShard(std::vector<std::string>& args) {
  BenchShard shard;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] != "--shard") continue;
    if (i + 1 >= args.size()) throw UsageError("--shard needs i/K (e.g. 0/3)");
    shard = parseShard(args[i + 1]);
    args.erase(args.begin() + static_cast<std::ptrdiff_t>(i), args.begin() + static_cast<std::ptrdiff_t>(i) + 2);
    --i;
  }
  return shard;
}

}  // namespace raylab

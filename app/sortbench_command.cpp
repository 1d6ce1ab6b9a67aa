#include "app/sortbench_command.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <numeric>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/bench/bench_spread.h"
#include "app/cli_options.h"
#include "app/scene_setup.h"
#include "app/sortbench_steps.h"
#include "renderer/checked_write.h"
#include "renderer/reorder/gpu_sort.h"
#include "renderer/vk/gpu_buffer.h"
#include "renderer/vk/gpu_timer.h"
#include "renderer/vk/stage_timer.h"
#include "renderer/vk/vk_context.h"
#include "shaders/sort_types.h"

namespace raylab {
namespace {

constexpr uint32_t kMaxN = 1u << 27;
constexpr int kWarmups = 2;  // at least this many warm-up sorts, and at least kWarmUp of them
constexpr std::chrono::milliseconds kWarmUp{500};
constexpr uint32_t kRunsPerSubmission = 64;  // sorts recorded back to back in one command buffer
constexpr uint32_t kMaxScopesPerRun = 32;    // the sort and its dispatches (at most 4 passes of 3, small, copy)
constexpr const char* kSortScope = "sort";   // the timer scope of a whole sort; its steps' scopes follow it

const std::string kUsage =
    std::string("usage: raylab sortbench [options]\n"
    "  --n N[,N...]        pair counts (1 .. 2^27; default 2^21)\n"
    "  --n-range A:B       powers of two 2^A .. 2^B\n"
    "  --bits B            key bits, 1..32 (default 30; keys are uniform below 2^B unless --dist says otherwise)\n"
    "  --dist D            uniform|sorted|reversed|equal|few (default uniform)\n"
    "  --sort S            bitonic|radix|both|onesweep|all (default both; onesweep: the decoupled look-back\n"
    "                      radix variant, only on GPUs with forward progress; all: the three)\n"
    "  --repeat R          timed sorts per (sort, n), back to back (64 a submission) after at least half a\n"
    "                      second of warm-up sorts (default 10)\n"
    "  --device NAME|N     substring of the Vulkan device name, or its number in `raylab devices`\n"
    "  --validate[=sync|gpu-av]  enable the Khronos validation layer with synchronization (default)\n"
    "                      or GPU-assisted checks (exit 1 on any error)\n"
    "  --csv FILE          also write the results as CSV\n"
    "  --steps FILE        time each dispatch of the radix sorts too (histogram, scan and scatter of every\n"
    "                      pass; OneSweep's; the small sort; the copy): medians under each row, and as CSV\n"
    "  --radix-group G     radix scatter work-group size (tuning; default: device's)\n"
    "  --radix-kpt K       radix keys per invocation (tuning; default 8)\n"
    "  --radix-tiles T     consecutive tiles a radix work group counts and scatters, 1..64 (tuning; default ") +
    std::to_string(kDefaultRadixTilesPerGroup) + ")\n"
    "  --radix-rank R      auto|ballot|partition: how the radix scatter finds a subgroup's lanes holding a\n"
    "                      digit, a ballot per digit bit or one subgroupPartitionNV (devices with\n"
    "                      VK_NV_shader_subgroup_partitioned); auto: the partition where the device has it\n"
    "                      (default " + std::string(radixRankName(kDefaultRadixRank)) + ")\n";

// --help: not an error, but it ends the parse the same way.
struct HelpRequested {};

struct BenchOptions {
  std::vector<uint32_t> counts;
  uint32_t bits = 30;
  std::string dist = "uniform";
  std::vector<SortAlgorithm> sorts{SortAlgorithm::Bitonic, SortAlgorithm::Radix};
  uint32_t repeat = 10;
  std::string device;
  ValidationMode validation = ValidationMode::Off;
  std::string csv;
  std::string steps;  // --steps FILE: the per-dispatch CSV
  GpuSorter::Tuning tuning;
};

BenchOptions parseOptions(const std::vector<std::string>& args) {
  BenchOptions o;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& flag = args[i];
    if (flag == "--help" || flag == "-h") throw HelpRequested{};
    if (flag == "--validate" || flag.rfind("--validate=", 0) == 0) {
      std::optional<ValidationMode> mode =
          flag == "--validate" ? ValidationMode::Sync : parseValidationMode(flag.substr(std::strlen("--validate=")));
      if (!mode || *mode == ValidationMode::Off)
        throw UsageError(flag + ": expected --validate, --validate=sync or --validate=gpu-av");
      o.validation = *mode;
      continue;
    }
    if (i + 1 >= args.size()) throw UsageError(flag + " needs a value");
    const std::string& value = args[++i];
    if (flag == "--n") {
      size_t start = 0;
      while (start <= value.size()) {
        size_t comma = value.find(',', start);
        if (comma == std::string::npos) comma = value.size();
        o.counts.push_back(parseUint(flag, value.substr(start, comma - start), 1, kMaxN));
        start = comma + 1;
      }
    } else if (flag == "--n-range") {
      const size_t colon = value.find(':');
      if (colon == std::string::npos) throw UsageError("--n-range wants A:B, e.g. 16:23");
      const uint32_t a = parseUint(flag, value.substr(0, colon), 0, 27);
      const uint32_t b = parseUint(flag, value.substr(colon + 1), a, 27);
      for (uint32_t e = a; e <= b; ++e) o.counts.push_back(1u << e);
    } else if (flag == "--bits") {
      o.bits = parseUint(flag, value, 1, 32);
    } else if (flag == "--dist") {
      if (value != "uniform" && value != "sorted" && value != "reversed" && value != "equal" && value != "few")
        throw UsageError("--dist: unknown distribution '" + value + "'");
      o.dist = value;
    } else if (flag == "--sort") {
      const std::optional<SortAlgorithm> one = parseSortAlgorithm(value);
      if (value == "both") o.sorts = {SortAlgorithm::Bitonic, SortAlgorithm::Radix};
      else if (value == "all") o.sorts = {SortAlgorithm::Bitonic, SortAlgorithm::Radix, SortAlgorithm::OneSweep};
      else if (one == SortAlgorithm::Bitonic || one == SortAlgorithm::Radix || one == SortAlgorithm::OneSweep)
        o.sorts = {*one};
      else throw UsageError("--sort: unknown sort '" + value + "'");
    } else if (flag == "--repeat") {
      o.repeat = parseUint(flag, value, 1, 100000);
    } else if (flag == "--device") {
      o.device = value;
    } else if (flag == "--csv") {
      o.csv = value;
    } else if (flag == "--steps") {
      o.steps = value;
    } else if (flag == "--radix-group") {
      o.tuning.radixGroupSize = parseUint(flag, value, 1, 256);
    } else if (flag == "--radix-kpt") {
      o.tuning.radixKeysPerThread = parseUint(flag, value, 1, 32);
    } else if (flag == "--radix-tiles") {
      o.tuning.radixTilesPerGroup = parseUint(flag, value, 1, 64);
    } else if (flag == "--radix-rank") {
      const auto rank = std::find_if(std::begin(kRadixRanks), std::end(kRadixRanks),
                                     [&](RadixRank r) { return value == radixRankName(r); });
      if (rank == std::end(kRadixRanks)) throw UsageError("--radix-rank '" + value + "' is not auto, ballot or partition");
      o.tuning.radixRank = *rank;
    } else {
      throw UsageError("unknown flag '" + flag + "'");
    }
  }
  if (o.counts.empty()) o.counts.push_back(1u << 21);
  const bool radixOnly = o.sorts.size() == 1 && o.sorts.front() == SortAlgorithm::Radix;
  if (o.tuning.radixTilesPerGroup != kDefaultRadixTilesPerGroup && !radixOnly)
    throw UsageError("--radix-tiles shapes the portable radix passes only: pass --sort radix");
  if (o.tuning.radixRank == RadixRank::Partition && !radixOnly)
    throw UsageError("--radix-rank partition ranks in the portable radix passes only: pass --sort radix");
  if (!o.steps.empty() && std::count(o.sorts.begin(), o.sorts.end(), SortAlgorithm::Bitonic))
    throw UsageError("--steps times the radix sorts' dispatches, not bitonic's: pass --sort radix or onesweep");
  return o;
}

std::vector<uint32_t> makeKeys(const std::string& dist, uint32_t n, uint32_t bits) {
  std::mt19937 rng(12345u + n);
  const uint32_t mask = bits == 32 ? ~0u : (1u << bits) - 1u;
  std::vector<uint32_t> keys(n);
  if (dist == "equal") {
    std::fill(keys.begin(), keys.end(), rng() & mask);
    return keys;
  }
  if (dist == "few") {
    uint32_t values[5];
    for (uint32_t& v : values) v = rng() & mask;
    for (uint32_t& k : keys) k = values[rng() % 5];
    return keys;
  }
  for (uint32_t& k : keys) k = rng() & mask;
  if (dist == "sorted") std::sort(keys.begin(), keys.end());
  if (dist == "reversed") std::sort(keys.begin(), keys.end(), std::greater<>());
  return keys;
}

// Empty string when the GPU result is right: radix must equal the stable order exactly; bitonic must have
// the keys in that order and carry each value (the input index) with its key.
std::string checkResult(SortAlgorithm sort, const std::vector<uint32_t>& keys, uint32_t bits,
                        const std::vector<uint32_t>& gotKeys, const std::vector<uint32_t>& gotValues) {
  const uint32_t n = static_cast<uint32_t>(keys.size());
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    return gpu::sortEffectiveKey(keys[a], bits) < gpu::sortEffectiveKey(keys[b], bits);
  });
  std::vector<bool> seen(n, false);
  for (uint32_t i = 0; i < n; ++i) {
    if (gotKeys[i] != keys[order[i]]) return "key mismatch at index " + std::to_string(i);
    if (sort != SortAlgorithm::Bitonic) {  // the radix sorts are stable
      if (gotValues[i] != order[i]) return "value (stability) mismatch at index " + std::to_string(i);
    } else {
      const uint32_t v = gotValues[i];
      if (v >= n || seen[v] || keys[v] != gotKeys[i]) return "value not carried with its key at " + std::to_string(i);
      seen[v] = true;
    }
  }
  return "";
}

struct Row {
  std::string sort;
  uint32_t n = 0;
  double medianMs = 0, minMs = 0, maxMs = 0;
  bool ok = true;
};

// Sorts of fresh copies of the input, back to back in one submission (the copy of each outside its scopes), so
// that the GPU never idles between the timed sorts: with one sort a submission and the host's checks between
// them the GPU idled, and an H100 then ran every dispatch of a sort of 5-8M pairs 4-5x slower than the same sort
// timed back to back, as lowered clocks would (docs/results/sortbench-back-to-back). Returns each run's scopes
// in the order they began: the sort's, then its steps' (with --steps).
std::vector<std::vector<StageTime>> sortBackToBack(const VulkanContext& ctx, GpuTimer& timer, GpuSorter& sorter,
                                                   const GpuBuffer& srcKeys, const GpuBuffer& srcValues,
                                                   const GpuBuffer& keys, const GpuBuffer& values, uint32_t n,
                                                   uint32_t bits, uint32_t runs) {
  ctx.submitAndWait([&](VkCommandBuffer cmd) {
    timer.reset(cmd);
    const VkBufferCopy region{0, 0, VkDeviceSize(n) * 4};
    for (uint32_t run = 0; run < runs; ++run) {
      vkCmdCopyBuffer(cmd, srcKeys.handle(), keys.handle(), 1, &region);
      vkCmdCopyBuffer(cmd, srcValues.handle(), values.handle(), 1, &region);
      computeBarrier(cmd);
      {
        ScopedStage scope(&timer, cmd, kSortScope);
        sorter.record(cmd, keys.address(), values.address(), n, bits);
      }
      computeBarrier(cmd);  // the sort done before the next run's copy overwrites its pairs
    }
  });
  std::vector<std::vector<StageTime>> perRun;
  for (StageTime& t : timer.collect()) {
    if (t.stage == kSortScope) perRun.emplace_back();
    if (perRun.empty()) throw std::logic_error("sortbench: a step scope before the first sort's");
    perRun.back().push_back(std::move(t));
  }
  if (perRun.size() != runs)
    throw std::logic_error("sortbench: " + std::to_string(perRun.size()) + " sorts timed of " + std::to_string(runs));
  return perRun;
}

// One row: the table's line on the terminal, or a CSV line (with `extra` columns) for --csv.
std::string formatRow(const Row& r, bool csv, const std::string& extra = "") {
  const double pairsPerSec = r.medianMs > 0 ? r.n / (r.medianMs * 1e-3) : 0.0;
  char line[512];
  if (csv)
    std::snprintf(line, sizeof(line), "%s,%u,%.6f,%.6f,%.6f,%.0f,%s", r.sort.c_str(), r.n, r.medianMs, r.minMs,
                  r.maxMs, pairsPerSec, r.ok ? "ok" : "MISMATCH");
  else
    std::snprintf(line, sizeof(line), "%-8s %10u %11.4f %11.4f %11.4f %12.1f  %s", r.sort.c_str(), r.n, r.medianMs,
                  r.minMs, r.maxMs, pairsPerSec * 1e-6, r.ok ? "ok" : "MISMATCH");
  return line + (csv ? extra : std::string()) + "\n";
}

int runBench(const BenchOptions& o) {
  ContextOptions co;
  co.validation = o.validation;
  co.deviceName = o.device;
  co.quiet = true;
  VulkanContext ctx(co);
  const DeviceInfo& dev = ctx.info();
  if (!deviceTimesCompute(ctx, "raylab sortbench")) return kExitFailure;
  const uint32_t maxN = *std::max_element(o.counts.begin(), o.counts.end());
  // The ranking the portable radix scatter takes here (RadixRank resolved for this device).
  const char* rankName = radixRankName(GpuSorter::resolvedRadixRank(ctx, o.tuning));
  std::printf("sortbench: device %s (driver %s), subgroup %u, %u-bit keys, %s, %u sorts back to back (after >= %d "
              "warm-up sorts and %lld ms), radix ranking by %s\n", dev.name.c_str(), dev.driver.c_str(),
              dev.subgroupSize, o.bits, o.dist.c_str(), o.repeat, kWarmups, static_cast<long long>(kWarmUp.count()),
              rankName);
  std::printf("%-8s %10s %11s %11s %11s %12s  %s\n", "sort", "n", "median_ms", "min_ms", "max_ms", "Mpairs/s",
              "check");
  std::fflush(stdout);

  std::vector<Row> rows;
  bool allOk = true;
  GpuTimer timer(ctx, kRunsPerSubmission * kMaxScopesPerRun);  // each sort and, with --steps, its dispatches
  // The columns every CSV line ends with (both files), and their names.
  const std::string csvExtraHeader = ",bits,dist,repeat,device,driver,radix_rank";
  const std::string csvExtra = "," + std::to_string(o.bits) + "," + o.dist + "," + std::to_string(o.repeat) + "," +
                                 csvText(dev.name) + "," + csvText(dev.driver) + "," + rankName;
  std::string stepsCsv;
  GpuBuffer keys(ctx, VkDeviceSize(maxN) * 4), values(ctx, VkDeviceSize(maxN) * 4);
  for (SortAlgorithm sort : o.sorts) {
    GpuSorter sorter(ctx, sort, maxN, o.tuning);
    if (!o.steps.empty()) sorter.timeSteps(&timer);
    if (sorter.oneSweepSerial()) {  // one work group a dispatch: a correctness fallback, not a speed to report
      std::fprintf(stderr, "raylab sortbench: onesweep skipped: %s is not known to give forward progress between "
                   "work groups\n", dev.name.c_str());
      continue;
    }
    for (uint32_t n : o.counts) {
      const std::vector<uint32_t> hostKeys = makeKeys(o.dist, n, o.bits);
      std::vector<uint32_t> hostValues(n);
      std::iota(hostValues.begin(), hostValues.end(), 0u);
      GpuBuffer srcKeys = makeBufferFrom(ctx, hostKeys), srcValues = makeBufferFrom(ctx, hostValues);
      Row row{toString(sort), n};
      std::vector<double> ms;
      SortSteps steps;
      auto sortRuns = [&](uint32_t runs) {
        return sortBackToBack(ctx, timer, sorter, srcKeys, srcValues, keys, values, n, o.bits, runs);
      };
      sortRuns(1);  // checked: every later run sorts the same input the same way
      const std::string err =
          checkResult(sort, hostKeys, o.bits, keys.downloadVector<uint32_t>(n), values.downloadVector<uint32_t>(n));
      if (!err.empty()) {
        std::fprintf(stderr, "raylab sortbench: %s n=%u: %s\n", row.sort.c_str(), n, err.c_str());
        row.ok = allOk = false;
      }
      // Warm-up after the host's check (the GPU idled through it): at least kWarmUp of sorts, as the frame bench
      // warms up (bench_measure.cpp), then the timed sorts right after, kRunsPerSubmission a submission.
      const auto warmStart = std::chrono::steady_clock::now();
      for (uint32_t warm = 0; warm < uint32_t(kWarmups) || std::chrono::steady_clock::now() - warmStart < kWarmUp;)
        warm += static_cast<uint32_t>(sortRuns(std::min(kRunsPerSubmission, o.repeat + kWarmups)).size());
      for (uint32_t done = 0; done < o.repeat;) {
        for (const std::vector<StageTime>& scopes : sortRuns(std::min(kRunsPerSubmission, o.repeat - done))) {
          ms.push_back(scopes.front().ms);
          if (!o.steps.empty()) steps.addRun(scopes, kSortScope);
          ++done;
        }
      }
      const Spread spread = spreadOf(ms);  // as each step's (SortSteps)
      row.minMs = spread.min;
      row.maxMs = spread.max;
      row.medianMs = spread.median;
      std::fputs(formatRow(row, false).c_str(), stdout);
      if (!steps.empty()) {
        std::fputs(steps.table(row.medianMs).c_str(), stdout);
        stepsCsv += steps.csv(row.sort, n, row.medianMs, csvExtra);
      }
      std::fflush(stdout);
      rows.push_back(row);
    }
  }
  if (!o.csv.empty()) {
    std::string csv = "sort,n,median_ms,min_ms,max_ms,pairs_per_s,check" + csvExtraHeader + "\n";
    for (const Row& r : rows) csv += formatRow(r, true, csvExtra);
    writeFileChecked(o.csv, csv);  // a WriteError is reported by runSortBenchCommand: exit 1
  }
  if (!o.steps.empty())
    writeFileChecked(o.steps, SortSteps::kCsvHeader + csvExtraHeader + "\n" + stepsCsv);
  if (o.validation != ValidationMode::Off && ctx.validationErrors() > 0) {
    std::fprintf(stderr, "raylab sortbench: the validation layer reported %u errors\n", ctx.validationErrors());
    return kExitFailure;
  }
  return allOk ? kExitOk : kExitFailure;
}

}  // namespace

int runSortBenchCommand(const std::vector<std::string>& args) {
  BenchOptions options;
  try {
    options = parseOptions(args);
  } catch (const HelpRequested&) {
    std::fputs(kUsage.c_str(), stdout);
    return kExitOk;
  } catch (const UsageError& e) {
    printUsageError("raylab sortbench", e.what());
    return kExitUsage;
  }
  try {
    return runBench(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "raylab sortbench: %s\n", e.what());
    return kExitFailure;
  }
}

}  // namespace raylab

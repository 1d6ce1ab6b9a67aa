// The path count per frame as a bench axis (--sizes, --spps): one group of cells per size and spp, in a
// fixed order (size-major, then spp, then bounce count), each cell carrying its group's size and spp, and
// bad values refused before any cell is planned, with the flag named. And the device-side check that the
// bench and render run before rendering: a frame of more paths than the device launches or allocates.
#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <vector>

#include "app/bench/bench_sweep.h"
#include "renderer/device_limits.h"
#include "renderer/settings/settings_table.h"

namespace raylab {
namespace {

using PathGroup = std::tuple<uint32_t, uint32_t, uint32_t, uint32_t>;  // width, height, spp, bounces

std::vector<PathGroup> groupsOf(const BenchPlan& plan) {
  std::vector<PathGroup> out;
  for (const BenchCell& c : plan.cells) {
    PathGroup g{c.settings.width, c.settings.height, c.settings.sppPerFrame, c.settings.bounces};
    if (out.empty() || out.back() != g) out.push_back(g);
  }
  return out;
}

TEST(BenchPathAxes, OneGroupPerSizeSppAndBounceCountInOrder) {
  BenchPlan plan = parseBenchPlan({"--cases", "cornell@front", "--strategies", "fixed,two-point", "--sizes",
                                   "64x32,16x8", "--spps", "1,4", "--bounces", "2,3"});
  const std::vector<PathGroup> want{{64, 32, 1, 2}, {64, 32, 1, 3}, {64, 32, 4, 2}, {64, 32, 4, 3},
                                    {16, 8, 1, 2},  {16, 8, 1, 3},  {16, 8, 4, 2},  {16, 8, 4, 3}};
  EXPECT_EQ(groupsOf(plan), want);
  // megakernel, none, fixed, two-point in every group, baselines first.
  ASSERT_EQ(plan.cells.size(), want.size() * 4);
  for (size_t g = 0; g < want.size(); ++g) {
    EXPECT_EQ(plan.cells[4 * g].label, "megakernel");
    EXPECT_EQ(plan.cells[4 * g + 1].label, "none");
    EXPECT_EQ(plan.cells[4 * g + 2].settings.strategy, KeyStrategy::Fixed);
  }
}

TEST(BenchPathAxes, WithoutTheAxesTheRenderFlagsHold) {
  BenchPlan plan = parseBenchPlan({"--cases", "cornell@front", "--strategies", "fixed", "--size", "40x20", "--spp", "2"});
  EXPECT_EQ(groupsOf(plan), (std::vector<PathGroup>{{40, 20, 2, plan.common.settings.bounces}}));
  // One axis alone keeps the other flag's value.
  plan = parseBenchPlan({"--cases", "cornell@front", "--strategies", "fixed", "--spp", "3", "--sizes", "8x8,16x16"});
  EXPECT_EQ(groupsOf(plan), (std::vector<PathGroup>{{8, 8, 3, plan.common.settings.bounces},
                                                    {16, 16, 3, plan.common.settings.bounces}}));
}

std::string refusal(const std::vector<std::string>& args) {
  try {
    parseBenchPlan(args);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "accepted";
}

// The real-time sizes by name (renderer/named_sizes.h): --sizes and --size take them as their WxH, and the
// CSV names them (size_name), which the paths chart marks; other sizes have no name, and names are exact.
TEST(BenchPathAxes, NamedSizesAreTheirWidthAndHeight) {
  BenchPlan plan = parseBenchPlan({"--cases", "cornell@front", "--strategies", "fixed", "--sizes", "720p,1080p,33x17"});
  EXPECT_EQ(groupsOf(plan), (std::vector<PathGroup>{{1280, 720, 1, plan.common.settings.bounces},
                                                    {1920, 1080, 1, plan.common.settings.bounces},
                                                    {33, 17, 1, plan.common.settings.bounces}}));
  plan = parseBenchPlan({"--cases", "cornell@front", "--strategies", "fixed", "--size", "1080p"});
  EXPECT_EQ(groupsOf(plan), (std::vector<PathGroup>{{1920, 1080, 1, plan.common.settings.bounces}}));
  EXPECT_EQ(settingsCsvColumns(plan.cells.front().settings).at("size_name"), "1080p");
  Settings plain;
  plain.width = 1280, plain.height = 721;
  EXPECT_EQ(settingsCsvColumns(plain).at("size_name"), "");
  EXPECT_NE(refusal({"--cases", "cornell@front", "--sizes", "720P"}), "accepted");
}

TEST(BenchPathAxes, AbsurdSizesAndSppsAreRefusedNamingTheFlag) {
  EXPECT_EQ(refusal({"--sizes", "0x0"}), "--sizes: --size width must be between 1 and 8192, got 0");
  EXPECT_EQ(refusal({"--sizes", "512x256,100000x100000"}), "--sizes: --size width must be between 1 and 8192, got 100000");
  EXPECT_EQ(refusal({"--sizes", "wide"}), "--sizes: --size expects WxH (e.g. 512x256) or 720p, 1080p, got 'wide'");
  EXPECT_EQ(refusal({"--spps", "1,0"}), "--spps: --spp must be between 1 and 64, got 0");
  EXPECT_EQ(refusal({"--sizes", ","}), "--sizes needs at least one value, got ','");
  // Each size may pass alone and fail with an spp: the pair is checked as a whole.
  EXPECT_NE(refusal({"--sizes", "8192x8192", "--spps", "1,2"}).find("--sizes x --spps: --size x --spp gives 134217728 paths"),
            std::string::npos);
  EXPECT_EQ(refusal({"--cases", "cornell@front", "--sizes", "8192x8192", "--spps", "1"}), "accepted");
}

DeviceInfo someDevice() {
  DeviceInfo d;
  d.name = "test device";
  d.maxGroupCountX = d.dispatchRowGroups = 65535;
  d.maxGroupCountY = 65535;
  d.maxMemoryAllocationSize = uint64_t(1) << 32;
  return d;
}

Settings sized(uint32_t w, uint32_t h, uint32_t spp) {
  Settings s;
  s.width = w;
  s.height = h;
  s.sppPerFrame = spp;
  return s;
}

TEST(DeviceLimits, AFrameThatFitsIsAccepted) {
  EXPECT_EQ(pathsBeyondDevice(someDevice(), sized(4096, 2048, 4)), "");
  EXPECT_EQ(pathsBeyondDevice(someDevice(), sized(8192, 8192, 1)), "");
}

TEST(DeviceLimits, TooFewDispatchRowsAreNamed) {
  DeviceInfo d = someDevice();
  d.maxGroupCountY = 2;  // 2 rows of 65535 groups of 64 threads: 8388480 threads
  const std::string why = pathsBeyondDevice(d, sized(4096, 2048, 1));
  EXPECT_EQ(why, "4096x2048 at 1 spp is 8388608 paths per frame; test device launches at most 8388480 threads per dispatch");
  EXPECT_EQ(pathsBeyondDevice(d, sized(4096, 2047, 1)), "");
}

TEST(DeviceLimits, TheLargestBufferMustFitOneAllocation) {
  DeviceInfo d = someDevice();
  d.maxMemoryAllocationSize = uint64_t(1) << 30;  // 2^26 paths of 16 bytes fit exactly
  EXPECT_EQ(pathsBeyondDevice(d, sized(8192, 8192, 1)), "");
  d.maxMemoryAllocationSize -= 1;
  EXPECT_NE(pathsBeyondDevice(d, sized(8192, 8192, 1)).find("allocates at most 1073741823"), std::string::npos);
}

TEST(DeviceLimits, TheRtTracerIsBoundByItsLaunchSize) {
  DeviceInfo d = someDevice();
  d.maxRayDispatchInvocationCount = 1u << 20;
  Settings s = sized(2048, 1024, 1);
  EXPECT_EQ(pathsBeyondDevice(d, s), "");  // the compute tracer does not launch rays
  s.tracer = Tracer::Rt;
  EXPECT_NE(pathsBeyondDevice(d, s).find("at most 1048576 rays per ray-tracing dispatch"), std::string::npos);
}

}  // namespace
}  // namespace raylab

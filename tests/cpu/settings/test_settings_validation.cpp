// One validation for every way Settings come in: the command line, `set` in window scripts, screenshot
// sidecars (`--settings`), imgui.ini (the same JSON) and bench sweep files (command-line flags). Hostile
// values are refused with the command line's range and wording, before anything is allocated.
#include <functional>

#include <gtest/gtest.h>

#include "app/cli_options.h"
#include "app/setting_flags.h"
#include "renderer/settings/settings_validation.h"
#include "renderer/stats_json.h"

namespace raylab {
namespace {

// The error settingsFromJson gives for the default settings with `key` replaced by `value`.
std::string jsonError(const std::string& key, const nlohmann::json& value) {
  nlohmann::json j = toJson(Settings{});
  j[key] = value;
  try {
    settingsFromJson(j);
  } catch (const SettingsError& e) {
    return e.what();
  }
  return "";
}

std::string cliError(const std::vector<std::string>& args) {
  try {
    parseCommonOptions(args);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(SettingsValidation, DefaultsAndTheirJsonAreValid) {
  EXPECT_FALSE(settingsError(Settings{}));
  EXPECT_EQ(settingsFromJson(toJson(Settings{})), Settings{});
  // A sidecar from before Settings::fusion ran every reorder stage as a pass of its own.
  nlohmann::json old = toJson(Settings{});
  old.erase("fusion");
  EXPECT_EQ(settingsFromJson(old).fusion, Fusion::None);
  // ... and before Settings::compaction left finished paths in their slots.
  old = toJson(Settings{});
  old.erase("compaction");
  EXPECT_EQ(settingsFromJson(old).compaction, Compaction::None);
  old.erase("trace_shade");  // ... and before Settings::traceShade, trace and shade were always apart
  EXPECT_EQ(settingsFromJson(old).traceShade, TraceShade::Split);
  old.erase("bvh");  // ... and before Settings::bvh, the compute tracer walked the binary tree
  EXPECT_EQ(settingsFromJson(old).bvh, BvhLayout::Binary);
  Settings packed;
  packed.compaction = Compaction::None;
  packed.traceShade = TraceShade::Fused;
  packed.bvh = BvhLayout::Wide;
  EXPECT_EQ(settingsFromJson(toJson(packed)), packed);
  EXPECT_EQ(toJson(packed).at("bvh"), "wide");
}

TEST(SettingsValidation, HostileSidecarValuesAreRefusedLikeTheCommandLine) {
  EXPECT_EQ(jsonError("bounces", -5), "--bounces must be between 1 and 32, got -5");
  EXPECT_EQ(jsonError("width", 1000000), "--size width must be between 1 and 8192, got 1000000");
  EXPECT_EQ(jsonError("spp_per_frame", 100000), "--spp must be between 1 and 64, got 100000");
  EXPECT_EQ(jsonError("ema_alpha", -3), "--ema-alpha must be between 0.001 and 1, got -3");
  EXPECT_EQ(jsonError("clamp_distance", -50), "--clamp must be between 0 and 1000000, got -50");
  EXPECT_EQ(jsonError("grid_auto_cells", 0), "--grid (automatic cells) must be between 1 and 1024, got 0");
  EXPECT_EQ(jsonError("exposure", 1e300), "--exposure must be between 0 and 1000000, got 1e+300");
  EXPECT_EQ(jsonError("bounces", 2.5), "--bounces expects a whole number, got 2.5");
  EXPECT_EQ(jsonError("grid", nlohmann::json::array({0, 4, 4})), "--grid must be between 1 and 1024, got 0");
  EXPECT_EQ(jsonError("grid", "everywhere"), "settings: 'grid' must be \"auto\" or [x, y, z], got \"everywhere\"");
  EXPECT_EQ(jsonError("heatmap_bounce", 99), "--heatmap-bounce must be between 0 and 31, got 99");
  EXPECT_NE(jsonError("width", "wide").find("'width' must be a number"), std::string::npos);
  EXPECT_EQ(jsonError("fusion", "sideways"), "settings: 'fusion' must be none, keys, gather or both, got \"sideways\"");
  EXPECT_EQ(jsonError("compaction", "always"), "settings: 'compaction' must be none or shade, got \"always\"");
  EXPECT_EQ(jsonError("trace_shade", "both"), "settings: 'trace_shade' must be split, fused or loop, got \"both\"");
  EXPECT_EQ(jsonError("bvh", "bogus"), "settings: 'bvh' must be binary, sbvh or wide, got \"bogus\"");
  // The tile sort needs the finished paths packed out first: refused without compaction, with keys made in
  // shade (which does not compact) and on the rt tracer; fine where nothing sorts.
  Settings tile;
  tile.strategy = KeyStrategy::TwoPoint;
  tile.sort = SortAlgorithm::Tile;
  EXPECT_FALSE(settingsError(tile));
  for (auto breakIt : std::vector<std::function<void(Settings&)>>{[](Settings& s) { s.compaction = Compaction::None; },
                                                                   [](Settings& s) { s.fusion = Fusion::Both; },
                                                                   [](Settings& s) { s.tracer = Tracer::Rt; }}) {
    Settings bad = tile;
    breakIt(bad);
    ASSERT_TRUE(settingsError(bad));
    EXPECT_NE(settingsError(bad)->find("--sort tile"), std::string::npos) << *settingsError(bad);
    bad.strategy = KeyStrategy::None;
    EXPECT_FALSE(settingsError(bad));
  }
  // The same ranges on the command line, same words.
  EXPECT_EQ(cliError({"--spp", "100000"}), jsonError("spp_per_frame", 100000));
  EXPECT_EQ(cliError({"--ema-alpha", "-3"}), jsonError("ema_alpha", -3));
  EXPECT_EQ(cliError({"--size", "1000000x4"}), jsonError("width", 1000000));
}

TEST(SettingsValidation, DocumentedLimitsThemselvesAreAccepted) {
  EXPECT_EQ(cliError({"--ema-alpha", "0.001"}), "");
  EXPECT_EQ(cliError({"--ema-alpha", "1"}), "");
  EXPECT_EQ(cliError({"--fixed-factor", "4"}), "");
  EXPECT_EQ(cliError({"--size", "8192x8192"}), "");
  EXPECT_EQ(cliError({"--clamp", "1000000"}), "");
  EXPECT_NE(cliError({"--ema-alpha", "0.0009"}), "");
  EXPECT_EQ(jsonError("ema_alpha", 0.001), "");
  EXPECT_EQ(jsonError("frames", 2000000), "") << "a long window session's sidecar must load";
  EXPECT_EQ(jsonError("frames", 5e9), "--frames must be between 1 and 4294967295, got 5000000000");
}

// Every field fine on its own, too many paths together: width x height x spp must fit the path buffers.
TEST(SettingsValidation, PathsPerFrameAreBoundedWhicheverWayTheyArrive) {
  std::string e = cliError({"--size", "8192x8192", "--spp", "2"});
  EXPECT_NE(e.find("paths per frame"), std::string::npos) << e;
  nlohmann::json j = toJson(Settings{});
  j["width"] = 8192, j["height"] = 8192, j["spp_per_frame"] = 64;
  EXPECT_THROW(settingsFromJson(j), SettingsError);
  Settings s;
  s.width = s.height = 8192;
  EXPECT_THROW(applySettingFlag(s, "spp", "64"), UsageError);
  EXPECT_EQ(s.sppPerFrame, 1u) << "a refused `set` must leave the settings as they were";
  // Flags laid over settings are checked once all are in, so their order does not matter.
  Settings many;
  many.sppPerFrame = 64;
  Settings out = overlaySettingFlags(many, {"--size", "8192x8192", "--spp", "1"});
  EXPECT_EQ(out.width, 8192u);
  EXPECT_THROW(overlaySettingFlags(many, {"--size", "8192x8192"}), UsageError);
}

// The bounce loop leaves no time per bounce, which auto weighs; without a strategy nothing sorts and it goes.
TEST(SettingsValidation, TheBounceLoopDoesNotGoWithTheAutoPolicy) {
  EXPECT_NE(cliError({"--trace-shade", "loop", "--strategy", "two-point", "--sort-policy", "auto"})
                .find("--sort-policy auto"), std::string::npos);
  EXPECT_EQ(cliError({"--trace-shade", "loop", "--strategy", "two-point", "--sort-policy", "never"}), "");
  EXPECT_EQ(cliError({"--trace-shade", "loop", "--sort-policy", "auto"}), "");
  EXPECT_EQ(cliError({"--trace-shade", "loop", "--strategy", "two-point", "--sort-policy", "auto", "--kernel",
                      "megakernel"}), "");
}

}  // namespace
}  // namespace raylab

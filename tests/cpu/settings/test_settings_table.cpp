// The settings table (renderer/settings/settings_table.h), row by row: every Settings member has a row, and every row
// round-trips through the command line, the flag overlay, the JSON and imgui.ini, reaches the bench's CSV
// (or its JSONL, for the columns the CSV has never had), is in the help, and asks SettingsChange::between
// for what it declares. Each row's `sample` is a value other than the default, so a row that a reader, a
// writer or a comparison forgets fails here.
#include <algorithm>
#include <set>

#include <gtest/gtest.h>

#include "app/bench/bench_results.h"
#include "app/bench/bench_sweep.h"
#include "app/cli_options.h"
#include "app/setting_flags.h"
#include "renderer/settings/settings_json.h"
#include "renderer/settings/settings_table.h"

namespace raylab {

// Failures show settings as their JSON, changes by name (gtest's printers find these by argument lookup).
void PrintTo(const Settings& s, std::ostream* os) { *os << toJson(s).dump(); }
void PrintTo(const SettingsChange& c, std::ostream* os) {
  *os << "{reallocate " << c.reallocate << ", accumulation " << c.resetAccumulation << ", cache " << c.resetCache
      << ", key parameters " << c.keyParameters << ", sort costs " << c.resetSortCosts << "}";
}

namespace {

// How many members an aggregate has: the most initializers of a type that converts to anything.
struct AnyMember {
  template <class T>
  operator T() const;
};
template <class T, class... A>
constexpr size_t memberCount() {
  if constexpr (requires { T{A{}..., AnyMember{}}; }) return memberCount<T, A..., AnyMember>();
  else return sizeof...(A);
}

std::vector<std::string> flagArgs(const SettingRow& r, const std::string& value) {
  if (r.isSwitch()) return value == "on" ? std::vector<std::string>{r.dashed} : std::vector<std::string>{};
  return {r.dashed, value};
}

// Default Settings with the row's sample, as the command line makes them.
Settings sampled(const SettingRow& r) { return parseCommonOptions(flagArgs(r, r.sample)).settings; }

TEST(SettingsTable, EveryMemberOfSettingsHasOneRow) {
  std::set<std::string> members, flags, keys, columns;
  for (const SettingRow& r : settingRows()) {
    EXPECT_TRUE(flags.insert(r.flag).second) << "two rows of --" << r.flag;
    for (const std::string& m : r.members) EXPECT_TRUE(members.insert(m).second) << m << " is in two rows";
    for (const std::string& k : r.jsonKeys) EXPECT_TRUE(keys.insert(k).second) << "JSON key " << k << " twice";
    for (const std::string& c : r.csvColumns) EXPECT_TRUE(columns.insert(c).second) << "CSV column " << c << " twice";
    EXPECT_FALSE(r.jsonKeys.empty()) << "--" << r.flag << " has no JSON key";
    EXPECT_FALSE(r.sample.empty()) << "--" << r.flag << " has no sample";
  }
  // A member added to Settings without a row would be neither parsed, written, read, checked nor compared.
  EXPECT_EQ(members.size(), memberCount<Settings>()) << "a Settings member has no row in renderer/settings/settings_table.cpp";
}

TEST(SettingsTable, EveryRowRoundTripsThroughTheCommandLine) {
  const Settings defaults;
  for (const SettingRow& r : settingRows()) {
    SCOPED_TRACE("--" + r.flag + " " + r.sample);
    const Settings s = sampled(r);
    EXPECT_FALSE(r.same(s, defaults)) << "the sample is the default, or the row's comparison misses it";
    for (const SettingRow& other : settingRows())
      if (&other != &r) {
        EXPECT_TRUE(other.same(s, defaults)) << "--" << r.flag << " changed --" << other.flag;
      }
    // The row's text of the value reads back the same, from the command line and laid over other settings.
    EXPECT_EQ(parseCommonOptions(flagArgs(r, r.text(s))).settings, s) << r.text(s);
    EXPECT_EQ(overlaySettingFlags(defaults, flagArgs(r, r.text(s))), s);
    Settings applied = defaults;
    applySettingFlag(applied, r.flag, r.text(s));
    EXPECT_EQ(applied, s);
    Settings copied = defaults;
    r.copy(copied, s);
    EXPECT_EQ(copied, s) << "the row's copy misses a member";
  }
}

TEST(SettingsTable, EveryRowRoundTripsThroughJsonAndIni) {
  for (const SettingRow& r : settingRows()) {
    SCOPED_TRACE("--" + r.flag + " " + r.sample);
    const Settings s = sampled(r);
    const nlohmann::json j = toJson(s);
    for (const std::string& key : r.jsonKeys) EXPECT_TRUE(j.contains(key)) << key << " is not written";
    EXPECT_NE(j, toJson(Settings{})) << "the JSON does not show the value";
    EXPECT_EQ(settingsFromJson(j), s);
    EXPECT_EQ(settingsFromIniLine(settingsIniLine(s)), s);
    // Every key is read: another row's value under this row's keys must not come back as this sample.
    nlohmann::json defaultsUnderKeys = j;
    for (const std::string& key : r.jsonKeys) defaultsUnderKeys[key] = toJson(Settings{})[key];
    EXPECT_TRUE(r.same(settingsFromJson(defaultsUnderKeys), Settings{})) << "a key of the row is not read";
  }
  EXPECT_THROW(settingsFromIniLine("settings={broken"), SettingsError);
}

// The CSV keeps its layout of before the table; the settings it never had a column for are in the JSONL's
// "settings" (the test above). A new setting gets a column, after the others.
TEST(SettingsTable, EveryRowReachesTheCsv) {
  const std::set<std::string> jsonlOnly = {"view",          "frames",         "seed",          "exposure",
                                           "grid",          "clamp",          "fixed-factor",  "ema-alpha",
                                           "gauss-outlier", "gauss-reset",    "heatmap",       "heatmap-bounce",
                                           "heatmap-key-colour", "heatmap-scale", "heatmap-range", "count-simt"};
  const std::vector<std::string> columns = benchCsvColumns();
  const std::map<std::string, std::string> defaults = settingsCsvColumns(Settings{});
  for (const SettingRow& r : settingRows()) {
    SCOPED_TRACE("--" + r.flag);
    EXPECT_EQ(r.csvColumns.empty(), jsonlOnly.count(r.flag) == 1);
    const std::map<std::string, std::string> got = settingsCsvColumns(sampled(r));
    bool shows = r.csvColumns.empty();
    for (const std::string& c : r.csvColumns) {
      EXPECT_NE(std::find(columns.begin(), columns.end(), c), columns.end()) << c << " is not a CSV column";
      ASSERT_TRUE(got.count(c)) << c << " is not written";
      shows = shows || got.at(c) != defaults.at(c);
    }
    EXPECT_TRUE(shows) << "the CSV does not show the sample";
  }
  EXPECT_EQ(std::set<std::string>(columns.begin(), columns.end()).size(), columns.size());
}

// The implications, stated by hand: a change of anything voids the sort costs; caches and path buffers
// bring new key parameters; accumulation alone brings nothing else.
TEST(SettingsTable, EffectsImplyWhatTheyNeed) {
  EXPECT_EQ(SettingsChange::fromEffects(kEffectNone), SettingsChange{});
  SettingsChange sortCostsOnly;
  sortCostsOnly.resetSortCosts = true;
  EXPECT_EQ(SettingsChange::fromEffects(kEffectSortCosts), sortCostsOnly);
  const SettingsChange cache = SettingsChange::fromEffects(kEffectCache);
  EXPECT_TRUE(cache.resetCache && cache.keyParameters && cache.resetSortCosts);
  EXPECT_FALSE(cache.reallocate || cache.resetAccumulation);
  const SettingsChange reallocate = SettingsChange::fromEffects(kEffectReallocate);
  EXPECT_TRUE(reallocate.reallocate && reallocate.keyParameters && reallocate.resetSortCosts);
  const SettingsChange image = SettingsChange::fromEffects(kEffectAccumulation);
  EXPECT_TRUE(image.resetAccumulation && image.resetSortCosts);
  EXPECT_FALSE(image.keyParameters || image.resetCache || image.reallocate);
}

// Stated by hand, not read from the table: the rows' declarations themselves must be right. Auto's costs
// were measured with one tracer, kernel and SER mode (the tracer was once forgotten here).
TEST(SettingsTable, TracerKernelAndSerVoidTheSortCosts) {
  const Settings defaults;
  Settings rt = defaults, megakernel = defaults, ser = defaults;
  rt.tracer = Tracer::Rt;
  megakernel.kernel = Kernel::Megakernel;
  ser.ser = Ser::On;
  for (const Settings* s : {&rt, &megakernel, &ser}) EXPECT_TRUE(SettingsChange::between(defaults, *s).resetSortCosts);
}

// What a row declares is what the renderer is told: a setting between forgets (as it once forgot the tracer,
// whose change must void the sort policy's costs) fails here.
TEST(SettingsTable, BetweenHonoursEveryRowsEffect) {
  const Settings defaults;
  for (const SettingRow& r : settingRows()) {
    SCOPED_TRACE("--" + r.flag + " " + r.sample);
    const Settings s = sampled(r);
    EXPECT_EQ(SettingsChange::between(defaults, s), SettingsChange::fromEffects(r.effects));
    EXPECT_EQ(SettingsChange::between(s, defaults), SettingsChange::fromEffects(r.effects));
    EXPECT_EQ(s.requiresAccumulationReset(defaults), bool(r.effects & kEffectAccumulation));
    EXPECT_EQ(s.requiresCacheReset(defaults), bool(r.effects & kEffectCache));
  }
}

TEST(SettingsTable, EveryRowIsInTheHelpAndItsAxisInTheBenchHelp) {
  const std::string help = "\n" + commonOptionsHelp(), bench = benchHelp();
  for (const SettingRow& r : settingRows()) {
    EXPECT_NE(help.find("\n  " + r.dashed + (r.isSwitch() ? " " : " " + r.hint)), std::string::npos) << r.dashed;
    if (r.axis.flag) {
      EXPECT_NE(bench.find(std::string("  --") + r.axis.flag + " "), std::string::npos) << r.axis.flag;
    }
    if (r.lo <= r.hi) {
      EXPECT_EQ(settingRange(r.flag).hi, r.hi);
    }
  }
  EXPECT_EQ(settingRange("learn-every").hi, 64);
  EXPECT_EQ(settingRange("sort-bits").hi, 32);
}

// Each axis of a row sweeps its values: a plan over the axis alone has a cell per value.
TEST(SettingsTable, EveryAxisSweepsItsSetting) {
  for (const SettingRow& r : settingRows()) {
    if (!r.axis.flag) continue;
    SCOPED_TRACE(r.axis.flag);
    const std::string values = r.text(Settings{}) + "," + r.text(sampled(r));
    BenchPlan plan = parseBenchPlan({std::string("--") + r.axis.flag, values, "--strategies", "gaussian,fixed",
                                     "--cases", "cornell"});
    std::set<std::string> seen;
    for (const BenchCell& c : plan.cells)
      if (c.settings.strategy != KeyStrategy::None) seen.insert(r.text(c.settings));
    EXPECT_EQ(seen, (std::set<std::string>{r.text(Settings{}), r.text(sampled(r))}));
  }
}

}  // namespace
}  // namespace raylab

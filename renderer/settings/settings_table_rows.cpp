// The settings table's rows of several members, and the helpers of settings_rows.h.
#include <cstdio>
#include <cstdlib>

#include "renderer/reorder/key_strategies.h"
#include "renderer/named_sizes.h"
#include "renderer/settings/settings_rows.h"

namespace raylab::setting_rows {

using L = SettingLimits;

std::string floatText(float v) {
  char text[32];
  for (int digits = 6; digits <= 9; ++digits) {  // 9 always read back the same float
    std::snprintf(text, sizeof(text), "%.*g", digits, v);
    if (std::strtof(text, nullptr) == v) break;
  }
  return text;
}

std::string joined(const std::vector<std::string>& names, const std::string& sep, const std::string& last) {
  std::string s;
  for (size_t i = 0; i < names.size(); ++i) s += (i == 0 ? "" : i + 1 == names.size() ? last : sep) + names[i];
  return s;
}

double jsonNumber(const std::string& key, const json& v) {
  if (!v.is_number()) throw SettingsError("settings: '" + key + "' must be a number, got " + v.dump());
  return v.get<double>();
}

const json& jsonAt(const json& j, const std::string& key) {
  if (!j.contains(key)) throw SettingsError("settings: missing '" + key + "'");
  return j.at(key);
}

namespace {

SettingRow rowOf(const char* flag, std::vector<std::string> members, std::vector<std::string> jsonKeys, double lo,
                 double hi, unsigned effects) {
  SettingRow r;
  r.flag = flag;
  r.dashed = std::string("--") + flag;
  r.members = std::move(members);
  r.jsonKeys = std::move(jsonKeys);
  r.lo = lo, r.hi = hi, r.effects = effects;
  return r;
}

const NumberRange kWidth{"--size width", 1, L::kMaxSize}, kHeight{"--size height", 1, L::kMaxSize};
const NumberRange kGridCells{"--grid", 1, L::kMaxGridCellsPerAxis};
const NumberRange kGridAutoCells{"--grid (automatic cells)", 1, L::kMaxGridCellsPerAxis};
const NumberRange kClamp{"--clamp", 0, L::kMaxClampDistance};
const NumberRange kRangeMin{"--heatmap-range min", 0, L::kMaxHeatmapValue};
const NumberRange kRangeMax{"--heatmap-range max", 0, L::kMaxHeatmapValue};

uint32_t uintIn(const NumberRange& r, const json& v, const std::string& key) {
  double d = jsonNumber(key, v);
  checkUint(r, d, formatNumber(d));
  return static_cast<uint32_t>(d);
}
float floatIn(const NumberRange& r, const json& v, const std::string& key) {
  double d = jsonNumber(key, v);
  checkFloat(r, d, formatNumber(d));
  return static_cast<float>(d);
}

}  // namespace

SettingRow sizeRow() {
  SettingRow r = rowOf("size", {"width", "height"}, {"width", "height"}, 1, L::kMaxSize,
                       kEffectReallocate | kEffectAccumulation);
  r.hint = "WxH", r.help = "resolution, any size up to {hi}x{hi} or 720p (1280x720), 1080p (1920x1080) (default {default})";
  r.sample = "33x17";
  // size_name: the size's name where it has one (named_sizes.h), for the charts to mark.
  r.csvColumns = {"width", "height", "size_name"};
  r.parseFn = [](const SettingRow&, Settings& s, const std::string& t) {
    if (const NamedSize* named = findNamedSize(t)) {
      s.width = named->width, s.height = named->height;
      return;
    }
    size_t x = t.find('x');
    if (x == std::string::npos) throw SettingsError("--size expects WxH (e.g. 512x256) or 720p, 1080p, got '" + t + "'");
    s.width = uintFromText(kWidth, t.substr(0, x));
    s.height = uintFromText(kHeight, t.substr(x + 1));
  };
  r.text = [](const Settings& s) { return std::to_string(s.width) + "x" + std::to_string(s.height); };
  r.same = [](const Settings& a, const Settings& b) { return a.width == b.width && a.height == b.height; };
  r.copy = [](Settings& to, const Settings& from) { to.width = from.width, to.height = from.height; };
  r.write = [](const Settings& s, json& out) { out["width"] = s.width, out["height"] = s.height; };
  r.readFn = [](const SettingRow&, const json& j, Settings& s) {
    s.width = uintIn(kWidth, jsonAt(j, "width"), "width");
    s.height = uintIn(kHeight, jsonAt(j, "height"), "height");
  };
  r.checkFn = [](const SettingRow&, const Settings& s) {
    checkUint(kWidth, s.width, std::to_string(s.width));
    checkUint(kHeight, s.height, std::to_string(s.height));
  };
  r.csv = [](const Settings& s, std::map<std::string, std::string>& out) {
    out["width"] = std::to_string(s.width), out["height"] = std::to_string(s.height);
    const NamedSize* named = namedSizeOf(s.width, s.height);
    out["size_name"] = named ? named->name : "";
  };
  return r;
}

namespace {

void parseGrid(Settings& s, const std::string& text) {
  if (text == "auto") {
    s.grid.automatic = true;
    return;
  }
  std::vector<std::string> parts;
  size_t start = 0;
  for (size_t x; (x = text.find('x', start)) != std::string::npos; start = x + 1) parts.push_back(text.substr(start, x - start));
  parts.push_back(text.substr(start));
  if (parts.size() != 1 && parts.size() != 3) throw SettingsError("--grid expects auto, N or NXxNYxNZ, got '" + text + "'");
  s.grid.automatic = false;
  for (int a = 0; a < 3; ++a) s.grid.cells[a] = uintFromText(kGridCells, parts[parts.size() == 1 ? 0 : a]);
}

std::string gridText(const Settings& s) {
  const glm::uvec3 c = s.grid.cells;
  return s.grid.automatic ? "auto" : std::to_string(c.x) + "x" + std::to_string(c.y) + "x" + std::to_string(c.z);
}

void readGrid(const json& j, Settings& s) {
  const json& grid = jsonAt(j, "grid");
  if ((grid.is_string() && grid.get<std::string>() != "auto") || (!grid.is_string() && (!grid.is_array() || grid.size() != 3)))
    throw SettingsError("settings: 'grid' must be \"auto\" or [x, y, z], got " + grid.dump());
  s.grid.automatic = grid.is_string();
  if (!s.grid.automatic)
    for (int a = 0; a < 3; ++a) s.grid.cells[a] = uintIn(kGridCells, grid.at(a), "grid");
  s.grid.autoCells = uintIn(kGridAutoCells, jsonAt(j, "grid_auto_cells"), "grid_auto_cells");
}

}  // namespace

SettingRow gridRow() {
  SettingRow r = rowOf("grid", {"grid"}, {"grid", "grid_auto_cells"}, 1, L::kMaxGridCellsPerAxis, kEffectCache);
  r.hint = "auto|N|NXxNYxNZ", r.help = "key grid (default {default}, 64 cells on the largest axis)", r.sample = "4x5x6";
  r.axis = {"grids", "auto,32x8x32      grid settings to sweep", &KeyStrategyInfo::usesGrid,
            [](const Settings& s) { return strategyInfo(s.strategy).usesGrid ? " grid=" + gridText(s) : ""; }, {"auto"}};
  r.parseFn = [](const SettingRow&, Settings& s, const std::string& t) { parseGrid(s, t); };
  r.text = gridText;
  r.same = [](const Settings& a, const Settings& b) { return a.grid == b.grid; };
  r.copy = [](Settings& to, const Settings& from) { to.grid = from.grid; };
  r.write = [](const Settings& s, json& out) {
    const glm::uvec3 c = s.grid.cells;
    out["grid"] = s.grid.automatic ? json("auto") : json::array({c.x, c.y, c.z});
    out["grid_auto_cells"] = s.grid.autoCells;
  };
  r.readFn = [](const SettingRow&, const json& j, Settings& s) { readGrid(j, s); };
  r.checkFn = [](const SettingRow&, const Settings& s) {
    for (int a = 0; a < 3; ++a) checkUint(kGridCells, s.grid.cells[a], std::to_string(s.grid.cells[a]));
    checkUint(kGridAutoCells, s.grid.autoCells, std::to_string(s.grid.autoCells));
  };
  r.csv = [](const Settings&, std::map<std::string, std::string>&) {};
  return r;
}

// `--clamp D` clamps the key grid to the camera +- D; `clamp off` (a script's `set`, a sweep's --clamps)
// stops clamping and keeps D.
SettingRow clampRow() {
  SettingRow r = rowOf("clamp", {"clampToCamera", "clampDistance"}, {"clamp_to_camera", "clamp_distance"}, 0,
                       L::kMaxClampDistance, kEffectCache);
  r.hint = "D", r.help = "clamp the key grid to camera +- D", r.sample = "7";
  r.axis = {"clamps", "off,50           camera clamp distances to sweep",
            &KeyStrategyInfo::usesGrid,
            [](const Settings& s) {
              if (!strategyInfo(s.strategy).usesGrid) return std::string();
              return s.clampToCamera ? " clamp=" + std::to_string(int(s.clampDistance)) : std::string(" clamp=off");
            },
            {"off"}};
  r.parseFn = [](const SettingRow&, Settings& s, const std::string& t) {
    if (t == "off") {
      s.clampToCamera = false;
      return;
    }
    s.clampDistance = floatFromText(kClamp, t);
    s.clampToCamera = true;
  };
  r.text = [](const Settings& s) { return s.clampToCamera ? floatText(s.clampDistance) : std::string("off"); };
  r.same = [](const Settings& a, const Settings& b) {
    return a.clampToCamera == b.clampToCamera && a.clampDistance == b.clampDistance;
  };
  r.copy = [](Settings& to, const Settings& from) {
    to.clampToCamera = from.clampToCamera, to.clampDistance = from.clampDistance;
  };
  r.write = [](const Settings& s, json& out) {
    out["clamp_to_camera"] = s.clampToCamera, out["clamp_distance"] = s.clampDistance;
  };
  r.readFn = [](const SettingRow&, const json& j, Settings& s) {
    s.clampToCamera = jsonAt(j, "clamp_to_camera").get<bool>();
    s.clampDistance = floatIn(kClamp, jsonAt(j, "clamp_distance"), "clamp_distance");
  };
  r.checkFn = [](const SettingRow&, const Settings& s) { checkFloat(kClamp, s.clampDistance, formatNumber(s.clampDistance)); };
  r.csv = [](const Settings&, std::map<std::string, std::string>&) {};
  return r;
}

// "auto" (each frame's own range) or "MIN:MAX" (locked); the interval is checked as every source's is.
SettingRow heatmapRangeRow() {
  SettingRow r = rowOf("heatmap-range", {"heatmapRange"}, {"heatmap_range"}, 0, L::kMaxHeatmapValue, kEffectNone);
  r.hint = "auto|MIN:MAX", r.sample = "2:40";
  r.help = "colour range of scalar heatmaps: each frame's own (default;\nwarp-efficiency 0..1), or locked to MIN..MAX";
  r.parseFn = [](const SettingRow&, Settings& s, const std::string& t) {
    if (t == "auto") {
      s.heatmapRange.locked = false;
      return;
    }
    size_t colon = t.find(':');
    if (colon == std::string::npos)
      throw SettingsError("--heatmap-range expects auto or MIN:MAX (e.g. 0:200), got '" + t + "'");
    HeatmapRange range{true, floatFromText(kRangeMin, t.substr(0, colon)), floatFromText(kRangeMax, t.substr(colon + 1))};
    checkHeatmapRange(range);
    s.heatmapRange = range;
  };
  r.text = [](const Settings& s) {
    const HeatmapRange& h = s.heatmapRange;
    return h.locked ? floatText(h.min) + ":" + floatText(h.max) : std::string("auto");
  };
  r.same = [](const Settings& a, const Settings& b) { return a.heatmapRange == b.heatmapRange; };
  r.copy = [](Settings& to, const Settings& from) { to.heatmapRange = from.heatmapRange; };
  r.write = [](const Settings& s, json& out) {
    const HeatmapRange& h = s.heatmapRange;
    out["heatmap_range"] = {{"locked", h.locked}, {"min", h.min}, {"max", h.max}};
  };
  r.readFn = [](const SettingRow&, const json& j, Settings& s) {
    if (!j.contains("heatmap_range")) return;  // older sidecars: each frame's own range
    const json& h = j.at("heatmap_range");
    if (!h.is_object()) throw SettingsError("settings: 'heatmap_range' must be {locked, min, max}, got " + h.dump());
    s.heatmapRange.locked = h.at("locked").get<bool>();
    s.heatmapRange.min = floatIn(kRangeMin, h.at("min"), "min");
    s.heatmapRange.max = floatIn(kRangeMax, h.at("max"), "max");
  };
  r.checkFn = [](const SettingRow&, const Settings& s) { checkHeatmapRange(s.heatmapRange); };
  r.csv = [](const Settings&, std::map<std::string, std::string>&) {};
  return r;
}

}  // namespace raylab::setting_rows

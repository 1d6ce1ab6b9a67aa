#include "app/bench/bench_resolution.h"

#include <algorithm>
#include <map>
#include <tuple>

#include "app/bench/bench_spread.h"

namespace raylab {
namespace {

struct Raced {
  std::string label;
  Spread frame;
};

std::string text(const Raced& c, bool spread) {
  std::string t = c.label + " " + screenNumber(c.frame.median) + " ms";
  return spread ? t + " [" + screenNumber(c.frame.min) + "-" + screenNumber(c.frame.max) + "]" : t;
}

std::string csvText(const nlohmann::json& cell, const char* column) {
  const nlohmann::json& csv = cell.at("csv");
  std::string t = csv.contains(column) && csv[column].is_string() ? csv[column].get<std::string>() : std::string();
  if (t.size() >= 2 && t.front() == '"' && t.back() == '"') t = t.substr(1, t.size() - 2);  // the CSV's quoting
  return t;
}

// A frame spread of a summary: over its rounds (min and max null with one round).
Spread frameSpread(const nlohmann::json& cell) {
  const nlohmann::json& f = cell.at("result").at("frame_ms");
  auto v = [&](const char* k) { return f.contains(k) && f[k].is_number() ? f[k].get<double>() : f["median"].get<double>(); };
  return {v("median"), v("min"), v("max"), v("q1"), v("q3")};
}

}  // namespace

std::string resolutionText(const std::vector<nlohmann::json>& cells) {
  // (scene, view, width, height, spp, bounces) -> cells, in plan order.
  using Group = std::tuple<std::string, std::string, std::string, std::string, std::string, std::string>;
  std::map<Group, std::vector<Raced>> groups;
  std::map<Group, size_t> rounds;
  std::vector<Group> order;
  for (const nlohmann::json& c : cells) {
    const Group g{csvText(c, "scene"), csvText(c, "view"), csvText(c, "width"), csvText(c, "height"),
                  csvText(c, "spp_per_frame"), csvText(c, "bounces")};
    if (!groups.count(g)) order.push_back(g);
    groups[g].push_back({c.value("label", std::string("?")), frameSpread(c)});
    const size_t n = c.value("rounds", size_t(1));
    rounds[g] = rounds.count(g) ? std::min(rounds[g], n) : n;
  }
  std::string out;
  for (const Group& g : order) {
    std::vector<Raced> raced = groups[g];
    std::stable_sort(raced.begin(), raced.end(), [](const Raced& a, const Raced& b) { return a.frame.median < b.frame.median; });
    const auto& [scene, view, w, h, spp, bounces] = g;
    const bool spread = rounds[g] > 1;
    out += scene + "@" + view + " " + w + "x" + h + " spp " + spp + ", " + bounces + " bounces, " +
           std::to_string(rounds[g]) + " round" + (rounds[g] == 1 ? "" : "s") + ": fastest " + text(raced.front(), spread) + "\n";
    if (!spread) {
      out += "  one round shows no spread: no difference is resolved (run --rounds 3 or more)\n";
      continue;
    }
    std::string same, slower;
    for (size_t i = 1; i < raced.size(); ++i)
      (overlaps(raced[i].frame, raced.front().frame) ? same : slower) += (std::string("\n    ") + text(raced[i], true));
    if (!same.empty()) out += "  not distinguishable from it here (spreads over the rounds overlap):" + same + "\n";
    if (!slower.empty()) out += "  slower beyond the spread:" + slower + "\n";
  }
  return out;
}

}  // namespace raylab

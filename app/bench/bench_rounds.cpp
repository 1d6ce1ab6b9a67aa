#include "app/bench/bench_rounds.h"

#include <map>
#include <numeric>
#include <optional>
#include <string>

#include "app/bench/bench_spread.h"

namespace raylab {
namespace {

// splitmix64: a fixed, portable sequence (std::shuffle's algorithm is the library's choice, and would give
// another order on another standard library).
uint64_t splitmix(uint64_t& state) {
  uint64_t z = (state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// A time of a round's record: the median of a spread object, or of a bare number; none for null or absent.
std::optional<double> medianOf(const nlohmann::json& j) {
  if (j.is_object() && j.contains("median") && j["median"].is_number()) return j["median"].get<double>();
  if (j.is_number()) return j.get<double>();
  return std::nullopt;
}

// The values of one figure over the rounds (rounds that did not measure it left out).
struct Series {
  std::vector<double> values;
  void add(std::optional<double> v) {
    if (v) values.push_back(*v);
  }
  bool measured() const { return !values.empty(); }
};

// The trace stage's rays per second (CellResult): a median over the rounds, none where no round measured it.
constexpr const char* kTraceRateFigures[] = {"trace_camera_rays_per_second", "trace_bounce_rays_per_second"};

// The figures of a cell over its rounds, taken from the rounds' results.
struct RoundFigures {
  Series frame, wall, traceLater, rays, pathTotal;
  std::map<std::string, Series> stages, bounceStages, traceRates;

  void add(const nlohmann::json& result) {
    frame.add(medianOf(result.value("frame_ms", nlohmann::json())));
    wall.add(medianOf(result.value("wall_ms", nlohmann::json())));
    traceLater.add(medianOf(result.value("trace_after_first_ms", nlohmann::json())));
    rays.add(medianOf(result.value("rays_per_second", nlohmann::json())));
    for (const char* name : kTraceRateFigures) traceRates[name].add(medianOf(result.value(name, nlohmann::json())));
    const nlohmann::json path = result.value("camera_path", nlohmann::json());
    if (path.is_object() && path.value("total_ms", nlohmann::json()).is_number()) pathTotal.add(path["total_ms"].get<double>());
    // Copies: items() of the temporary value() returns would outlive it.
    const nlohmann::json stageMs = result.value("stage_ms", nlohmann::json::object());
    const nlohmann::json bounceMs = result.value("stage_bounce_ms", nlohmann::json::object());
    for (const auto& [name, s] : stageMs.items()) stages[name].add(medianOf(s));
    for (const auto& [name, s] : bounceMs.items()) bounceStages[name].add(medianOf(s));
  }
};

nlohmann::json summarise(const std::vector<const nlohmann::json*>& rounds) {
  nlohmann::json out = *rounds.front();
  out.erase("round");
  RoundFigures f;
  for (const nlohmann::json* r : rounds) f.add(r->at("result"));
  const size_t n = rounds.size();
  const bool spread = n > 1;  // one round shows no noise: its spread is not measured
  nlohmann::json& result = out["result"];
  nlohmann::json& csv = out["csv"];
  out["rounds"] = n;
  csv["rounds"] = std::to_string(n);

  const Spread frame = spreadOf(f.frame.values);
  result["frame_ms"] = toJson(frame, spread);
  result["round_frame_ms"] = f.frame.values;
  result["wall_ms"] = toJson(spreadOf(f.wall.values), spread);
  auto spreadCsv = [&](const std::string& prefix, const Spread& s, bool measured) {
    csv[prefix + "_min"] = csvNumber(measured && spread ? std::optional(s.min) : std::nullopt);
    csv[prefix + "_max"] = csvNumber(measured && spread ? std::optional(s.max) : std::nullopt);
  };
  csv["frame_ms_median"] = csvNumber(f.frame.measured() ? std::optional(frame.median) : std::nullopt);
  spreadCsv("frame_ms", frame, f.frame.measured());
  csv["frame_ms_q1"] = csvNumber(f.frame.measured() && spread ? std::optional(frame.q1) : std::nullopt);
  csv["frame_ms_q3"] = csvNumber(f.frame.measured() && spread ? std::optional(frame.q3) : std::nullopt);

  const Spread later = spreadOf(f.traceLater.values);
  result["trace_after_first_ms"] = f.traceLater.measured() ? toJson(later, spread) : nlohmann::json(nullptr);
  csv["trace_after_first_ms"] = csvNumber(f.traceLater.measured() ? std::optional(later.median) : std::nullopt);
  spreadCsv("trace_after_first_ms", later, f.traceLater.measured());

  nlohmann::json stages = nlohmann::json::object(), bounceStages = nlohmann::json::object();
  for (const auto& [name, s] : f.stages) {
    const Spread st = spreadOf(s.values);
    stages[name] = toJson(st, spread);
    csv[name + "_ms"] = csvNumber(st.median);
  }
  for (const auto& [name, s] : f.bounceStages) bounceStages[name] = spreadOf(s.values).median;
  result["stage_ms"] = stages;
  result["stage_bounce_ms"] = bounceStages;
  if (f.rays.measured()) {
    result["rays_per_second"] = spreadOf(f.rays.values).median;
    csv["rays_per_second"] = csvNumber(spreadOf(f.rays.values).median);
  }
  for (const auto& [name, s] : f.traceRates) {
    const std::optional<double> median = s.measured() ? std::optional(spreadOf(s.values).median) : std::nullopt;
    result[name] = median ? nlohmann::json(*median) : nlohmann::json(nullptr);
    csv[name] = csvNumber(median);
  }
  // A camera path's time: the median over the rounds of each round's total (and that per frame).
  if (f.pathTotal.measured() && result["camera_path"].is_object()) {
    const double total = spreadOf(f.pathTotal.values).median;
    const uint32_t frames = result["camera_path"].value("frames", 0u);
    const double mean = frames ? total / frames : 0.0;
    result["camera_path"]["total_ms"] = total;
    result["camera_path"]["mean_ms"] = mean;
    result["camera_path"]["round_total_ms"] = f.pathTotal.values;
    csv["path_total_ms"] = csvNumber(total);
    csv["path_mean_ms"] = csvNumber(mean);
  }
  // The equal-time curve's time axis: k frames of the cell's (median over rounds) frame time.
  if (result.contains("error_curve_ms") && result["error_curve_ms"].is_array()) {
    nlohmann::json curve = nlohmann::json::array();
    for (size_t k = 0; k < result["error_curve_ms"].size(); ++k) curve.push_back(double(k + 1) * frame.median);
    result["error_curve_ms"] = curve;
  }
  return out;
}

}  // namespace

std::vector<size_t> roundOrder(size_t count, uint32_t round) {
  std::vector<size_t> order(count);
  std::iota(order.begin(), order.end(), size_t(0));
  if (round == 0) return order;
  uint64_t state = 0x5eedull * (uint64_t(round) + 1);
  for (size_t i = count; i > 1; --i) std::swap(order[i - 1], order[splitmix(state) % i]);  // Fisher-Yates
  return order;
}

uint32_t roundOf(const nlohmann::json& record) {
  return record.contains("round") && record["round"].is_number_unsigned() ? record["round"].get<uint32_t>() : 0;
}

std::vector<nlohmann::json> cellSummaries(const std::vector<nlohmann::json>& records) {
  std::map<size_t, std::map<uint32_t, const nlohmann::json*>> byCell;
  for (const nlohmann::json& r : records) byCell[r.at("cell").get<size_t>()][roundOf(r)] = &r;
  std::vector<nlohmann::json> out;
  for (const auto& [cell, rounds] : byCell) {
    std::vector<const nlohmann::json*> list;
    for (const auto& [round, r] : rounds) list.push_back(r);
    out.push_back(summarise(list));
  }
  return out;
}

}  // namespace raylab

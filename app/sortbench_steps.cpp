#include "app/sortbench_steps.h"

#include <cstdio>
#include <stdexcept>

#include "app/bench/bench_spread.h"

namespace raylab {

void SortSteps::addRun(const std::vector<StageTime>& scopes, const std::string& sortStage) {
  if (scopes.empty() || scopes.front().stage != sortStage)
    throw std::logic_error("sortbench --steps: the run's first scope is not the sort");
  // Every run of one (sort, n) records the same steps in the same order.
  const size_t count = scopes.size() - 1;
  if (!steps_.empty() && steps_.size() != count)
    throw std::logic_error("sortbench --steps: a run recorded " + std::to_string(count) + " steps, another " +
                           std::to_string(steps_.size()));
  for (size_t i = 0; i < steps_.size(); ++i)  // checked whole before anything is kept
    if (steps_[i].name != scopes[i + 1].stage)
      throw std::logic_error("sortbench --steps: step " + scopes[i + 1].stage + " where a run had " + steps_[i].name);
  if (steps_.empty())
    for (size_t i = 0; i < count; ++i) steps_.push_back({scopes[i + 1].stage, {}});
  for (size_t i = 0; i < count; ++i) steps_[i].ms.push_back(scopes[i + 1].ms);
}

std::string SortSteps::table(double sortMedianMs) const {
  std::string out;
  for (const Step& s : steps_) {
    const Spread m = spreadOf(s.ms);
    char line[160];
    std::snprintf(line, sizeof(line), "    %-20s %11.4f ms  %5.1f%%\n", s.name.c_str(), m.median,
                  sortMedianMs > 0 ? 100.0 * m.median / sortMedianMs : 0.0);
    out += line;
  }
  return out;
}

std::string SortSteps::csv(const std::string& sort, uint32_t n, double sortMedianMs, const std::string& extra) const {
  std::string out;
  for (const Step& s : steps_) {
    const Spread m = spreadOf(s.ms);
    char line[256];
    std::snprintf(line, sizeof(line), "%s,%u,%s,%.6f,%.6f,%.6f,%.4f", sort.c_str(), n, s.name.c_str(), m.median,
                  m.min, m.max, sortMedianMs > 0 ? m.median / sortMedianMs : 0.0);
    out += line + extra + "\n";
  }
  return out;
}

}  // namespace raylab

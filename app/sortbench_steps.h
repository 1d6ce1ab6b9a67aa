// sortbench --steps: where a sort's time goes. GpuSorter::timeSteps makes each dispatch of a sort a scope of
// the bench's timer ("histogram/0", "scan/0", "scatter/0", ..., "small", "copy"); SortSteps keeps each step's
// times over the timed runs of one (sort, n) and reports their medians, as a share of the whole sort too.
#pragma once

#include <string>
#include <vector>

#include "renderer/frame_stats.h"

namespace raylab {

class SortSteps {
 public:
  // One timed run's scopes in the order they began: the whole sort's (`sortStage`) first, then its steps.
  void addRun(const std::vector<StageTime>& scopes, const std::string& sortStage);
  bool empty() const { return steps_.empty(); }
  // The steps' medians on one terminal line each, behind an indent.
  std::string table(double sortMedianMs) const;
  // CSV lines "sort,n,step,median_ms,min_ms,max_ms,share" + `extra` (kCsvHeader's columns, without extra's).
  std::string csv(const std::string& sort, uint32_t n, double sortMedianMs, const std::string& extra) const;
  static constexpr const char* kCsvHeader = "sort,n,step,median_ms,min_ms,max_ms,share";

 private:
  struct Step {
    std::string name;
    std::vector<double> ms;
  };
  std::vector<Step> steps_;  // in the order a sort records them
};

}  // namespace raylab

// `raylab bench` draws its charts itself once a sweep's results.csv is written: it runs
// `python3 app/bench/bench_charts.py DIR` as a child process (/usr/bin/python3 where it exists, else python3 from
// PATH; RAYLAB_PYTHON names another interpreter). The CSV
// and JSONL are written before and never touched by it, so a chart that fails loses no result.
#pragma once

#include <string>
#include <vector>

namespace raylab {

struct ChartsOutcome {
  enum class Kind {
    Drawn,        // every chart written
    Unavailable,  // no python3, no matplotlib or no script: said once, not an error of the sweep
    Failed,       // the script ran and failed (a chart it could not write, a crash): an error (exit 1)
  };
  Kind kind = Kind::Drawn;
  std::string why;  // for Unavailable and Failed: what happened, in words
};

// Runs one of the lab's Python scripts (app/PATH, e.g. bench/bench_charts.py, in the source tree) with `args` and
// waits for it; its output goes to this process's stdout and stderr. A script exits 3 when matplotlib is missing.
ChartsOutcome runLabScript(const std::string& path, const std::vector<std::string>& args);

// Runs the chart script on `dir` and waits for it; its output goes to this process's stdout and stderr.
ChartsOutcome drawBenchCharts(const std::string& dir);

// Draws the charts of a finished sweep and says what became of them; false when they failed. A machine
// without python3 or matplotlib is no failure: said once, the CSV is what the sweep is for.
bool drawAndReportCharts(const std::string& dir);

// A script of the lab: RAYLAB_SOURCE_DIR's app/PATH (the source tree this raylab was built from).
std::string labScript(const std::string& path);
std::string benchChartsScript();  // labScript("bench/bench_charts.py")

}  // namespace raylab

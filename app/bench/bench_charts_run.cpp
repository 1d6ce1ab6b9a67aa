#include "app/bench/bench_charts_run.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

extern char** environ;

namespace raylab {
namespace {

// The scripts' exit status when `import matplotlib` fails (EXIT_NO_MATPLOTLIB in bench_charts.py and
// study_report.py).
constexpr int kChartsNoMatplotlib = 3;
// A shell's status for a command it could not find; posix_spawnp reports ENOENT itself on glibc.
constexpr int kCommandNotFound = 127;
constexpr const char* kDebianPython = "/usr/bin/python3";

}  // namespace

std::string labScript(const std::string& name) { return std::string(RAYLAB_SOURCE_DIR) + "/app/" + name; }
std::string benchChartsScript() { return labScript("bench/bench_charts.py"); }

ChartsOutcome runLabScript(const std::string& path, const std::vector<std::string>& scriptArgs) {
  const std::string name = std::filesystem::path(path).filename().string();  // what the messages name
  // Debian's interpreter first: python3-matplotlib is installed for it, and a python3 earlier on PATH (a
  // pyenv or a virtual environment) may lack it; then whichever python3 PATH has.
  const char* env = std::getenv("RAYLAB_PYTHON");
  std::error_code ec;
  const std::string python = env && *env                                      ? env
                             : std::filesystem::exists(kDebianPython, ec) ? kDebianPython
                                                                          : "python3";
  const std::string script = labScript(path);
  if (!std::filesystem::is_regular_file(script, ec))
    return {ChartsOutcome::Kind::Unavailable, "the script " + script + " is not there (a moved source tree?)"};
  std::vector<std::string> args{python, script};
  args.insert(args.end(), scriptArgs.begin(), scriptArgs.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (int err = posix_spawnp(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ); err != 0) {
    if (err == ENOENT) return {ChartsOutcome::Kind::Unavailable, python + " is not installed"};
    return {ChartsOutcome::Kind::Failed, "cannot run " + python + ": " + std::strerror(err)};
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return {ChartsOutcome::Kind::Failed, "waiting for " + name + ": " + std::strerror(errno)};
  if (WIFSIGNALED(status))
    return {ChartsOutcome::Kind::Failed, "the script " + name + " was killed by signal " + std::to_string(WTERMSIG(status))};
  const int code = WEXITSTATUS(status);
  if (code == 0) return {ChartsOutcome::Kind::Drawn, ""};
  if (code == kChartsNoMatplotlib)
    return {ChartsOutcome::Kind::Unavailable, "matplotlib is missing for " + python + " (Debian: python3-matplotlib)"};
  if (code == kCommandNotFound) return {ChartsOutcome::Kind::Unavailable, python + " is not installed"};
  return {ChartsOutcome::Kind::Failed, "the script " + name + " exited " + std::to_string(code)};
}

ChartsOutcome drawBenchCharts(const std::string& dir) {
  // The bench reports a missing matplotlib itself (once, with the CSV's place): the script stays quiet then.
  return runLabScript("bench/bench_charts.py", {"--quiet-if-unavailable", dir});
}

bool drawAndReportCharts(const std::string& dir) {
  const ChartsOutcome charts = drawBenchCharts(dir);
  switch (charts.kind) {
    case ChartsOutcome::Kind::Drawn:
      std::printf("bench: charts in %s\n", dir.c_str());
      return true;
    case ChartsOutcome::Kind::Unavailable:
      std::fprintf(stderr, "raylab bench: no charts: %s; the results are in %s/results.csv\n", charts.why.c_str(),
                   dir.c_str());
      return true;
    case ChartsOutcome::Kind::Failed:
      break;
  }
  std::fprintf(stderr, "raylab bench: the charts failed: %s; the results are kept in %s/results.csv and "
               "results.jsonl (python3 %s %s draws them again)\n", charts.why.c_str(), dir.c_str(),
               benchChartsScript().c_str(), dir.c_str());
  return false;
}

}  // namespace raylab

// raylab: the lab's entry point. Wiring only: each mode lives in its own file.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "app/bench/bench_command.h"
#include "app/render_command.h"
#include "app/scene_setup.h"
#include "app/sortbench_command.h"
#include "app/tracebench/tracebench_command.h"
#include "app/study/study_command.h"
#include "app/window_command.h"
#include "renderer/vk/vk_check.h"

namespace {

// Every mode, then the window's own options and the render options it shares with `raylab render`: each
// option once (a mode's own options: raylab MODE --help).
void printHelp() {
  std::printf(
      "raylab: a lab for ray reordering in a wavefront path tracer\n\n"
      "usage:\n"
      "  raylab [options]            open the interactive lab (without a display: render headless instead)\n"
      "  raylab render [options]     render headless to a PNG (raylab render --help)\n"
      "  raylab sortbench [options]  time the GPU sorts alone (raylab sortbench --help)\n"
      "  raylab tracebench [options] time the BVH traversal alone on camera, bounce and shadow rays\n"
      "                              (raylab tracebench --help)\n"
      "  raylab bench [options]      sweep strategies and sorts, write CSV/JSON (raylab bench --help;\n"
      "                              charts: app/bench/bench_charts.py)\n"
      "  raylab study SCENE[@VIEW]   where sorting pays on a scene: a standard sweep and an HTML report\n"
      "                              (raylab study --help)\n"
      "  raylab devices              list Vulkan devices and whether each can run --tracer rt and --ser\n"
      "  raylab help, --help, -h     this text\n\n"
      "%s\nrender options (raylab render's; the window takes the settings among them, and --out and --stats\n"
      "where it renders headless for want of a display):\n%s",
      raylab::windowOptionsHelp().c_str(), raylab::commonOptionsHelp().c_str());
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  std::string mode = args.empty() || args[0].rfind("--", 0) == 0 ? "" : args[0];
  std::vector<std::string> rest(args.begin() + (mode.empty() ? 0 : 1), args.end());
  try {
    if (mode == "render") return raylab::runRenderCommand(rest);
    if (mode == "bench") return raylab::runBenchCommand(rest);
    if (mode == "study") return raylab::runStudyCommand(rest);
    if (mode == "sortbench") return raylab::runSortBenchCommand(rest);
    if (mode == "tracebench") return raylab::runTraceBenchCommand(rest);
    if (mode == "devices") {
      for (const std::string& line : raylab::VulkanContext::describeDevices()) std::puts(line.c_str());
      return raylab::kExitOk;
    }
    if (mode == "help" || mode == "-h" || (!args.empty() && (args[0] == "--help" || args[0] == "-h"))) {
      printHelp();
      return raylab::kExitOk;
    }
    if (mode.empty()) return raylab::runWindowCommand(rest);
    // The error and where the help is: the whole help after it scrolled the error away.
    const std::string near = raylab::nearestName(mode, {"render", "sortbench", "tracebench", "bench", "study", "devices", "help"});
    raylab::printUsageError("raylab", "unknown mode '" + mode + "'" + (near.empty() ? "" : " (did you mean " + near + "?)"));
    return raylab::kExitUsage;
  } catch (const raylab::UnknownDeviceError& e) {  // any mode's --device
    std::fprintf(stderr, "raylab: %s\n", e.what());
    return raylab::kExitUsage;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "raylab: %s\n", e.what());
    return raylab::kExitFailure;
  }
}

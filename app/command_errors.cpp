#include "app/command_errors.h"

#include <algorithm>
#include <cstdio>

#include "app/cli_options.h"
#include "app/scene_setup.h"
#include "app/ui_script.h"

namespace raylab {

void printUsageError(const std::string& command, const std::string& message) {
  std::fprintf(stderr, "%s: %s\nfor usage: %s --help\n", command.c_str(), message.c_str(), command.c_str());
}

std::string nearestName(const std::string& word, const std::vector<std::string>& names) {
  // Levenshtein distance, one row at a time.
  auto distance = [](const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
      size_t diagonal = row[0];
      row[0] = i;
      for (size_t j = 1; j <= b.size(); ++j) {
        const size_t up = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
        diagonal = up;
      }
    }
    return row[b.size()];
  };
  const size_t limit = std::max<size_t>(1, word.size() / 3);
  std::string best;
  size_t bestDistance = limit + 1;
  for (const std::string& n : names)
    if (size_t d = distance(word, n); d < bestDistance) best = n, bestDistance = d;
  return best;
}

std::string unknownOptionMessage(const std::string& given, const std::vector<std::string>& known) {
  const std::string near = nearestName(given, known);
  return "unknown option '" + given + "'" + (near.empty() ? "" : " (did you mean " + near + "?)");
}

int withCommandErrors(const std::function<void(const std::string&)>& printUsage, const std::function<int()>& body) {
  try {
    return body();
  } catch (const UsageError& e) {
    printUsage(e.what());
    return kExitUsage;
  } catch (const ScriptError& e) {
    std::fprintf(stderr, "raylab: %s\n", e.what());
    return kExitUsage;
  } catch (const SceneLoadError& e) {
    std::fprintf(stderr, "raylab: cannot load scene: %s\n", e.what());
    return kExitBadScene;
  }
}

}  // namespace raylab

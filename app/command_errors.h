// The errors every command reports the same way, turned into exit codes in one place.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace raylab {

// Exit codes shared by every mode.
enum ExitCode : int { kExitOk = 0, kExitFailure = 1, kExitUsage = 2, kExitBadScene = 3, kExitValidation = 4 };

// Runs `body` and returns its exit code, or: UsageError -> printUsage(message), kExitUsage; ScriptError ->
// the message, kExitUsage; SceneLoadError -> "cannot load scene: ...", kExitBadScene. Anything else
// propagates (main reports it with kExitFailure).
// A usage error as every command prints it: "COMMAND: MESSAGE" and where the help is, nothing more (the whole
// usage after it scrolled the message out of view: 60 to 90 lines).
void printUsageError(const std::string& command, const std::string& message);
// The name in `names` nearest to `word` by edit distance, when it is near (at most a third of the word's
// length, at least 1): for "did you mean"; empty otherwise.
std::string nearestName(const std::string& word, const std::vector<std::string>& names);
// "unknown option '--bouncs' (did you mean --bounces?)", the hint where one of `known` is near.
std::string unknownOptionMessage(const std::string& given, const std::vector<std::string>& known);

int withCommandErrors(const std::function<void(const std::string&)>& printUsage, const std::function<int()>& body);

}  // namespace raylab

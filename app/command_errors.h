// The errors every command reports the same way, turned into exit codes in one place.
#pragma once

#include <functional>
#include <string>

namespace raylab {

// Exit codes shared by every mode.
enum ExitCode : int { kExitOk = 0, kExitFailure = 1, kExitUsage = 2, kExitBadScene = 3, kExitValidation = 4 };

// Runs `body` and returns its exit code, or: UsageError -> printUsage(message), kExitUsage; ScriptError ->
// the message, kExitUsage; SceneLoadError -> "cannot load scene: ...", kExitBadScene. Anything else
// propagates (main reports it with kExitFailure).
int withCommandErrors(const std::function<void(const std::string&)>& printUsage, const std::function<int()>& body);

}  // namespace raylab

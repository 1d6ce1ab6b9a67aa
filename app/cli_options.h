// Command-line flags shared by every mode, parsed into Settings. Bad values throw UsageError, which the
// modes turn into a usage message and exit code 2.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "renderer/settings/settings.h"
#include "renderer/vk/validation_mode.h"

namespace raylab {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct CommonOptions {
  Settings settings;
  std::string device;     // --device NAME
  ValidationMode validation = ValidationMode::Off;  // --validate (sync), --validate=gpu-av
  std::string out;        // --out FILE.png
  std::string statsPath;  // --stats FILE.json
};

// Parses the flags in `args`; flags this function does not know are returned in `rest` (in order, with
// their values) for the mode to handle, or rejected when `rest` is null.
CommonOptions parseCommonOptions(const std::vector<std::string>& args, std::vector<std::string>* rest = nullptr);

// The flags parseCommonOptions accepts ("--bounces", ...), for "did you mean".
std::vector<std::string> commonOptionNames();

// Text of the flags parseCommonOptions accepts, for usage messages.
std::string commonOptionsHelp();

// Takes `flag VALUE` out of `args` (a mode's own flags, before the common ones are parsed): the last value
// given, or nullopt. Throws UsageError when the flag ends the list.
std::optional<std::string> takeFlag(std::vector<std::string>& args, const std::string& flag);
// Takes every `flag` (a switch, without a value) out of `args`: whether it was given.
bool takeSwitch(std::vector<std::string>& args, const std::string& flag);

// Strict number parsing for flags: the whole string must be a number within [lo, hi].
uint32_t parseUint(const std::string& flag, const std::string& text, uint32_t lo, uint32_t hi);
float parseFloat(const std::string& flag, const std::string& text, float lo, float hi);

}  // namespace raylab

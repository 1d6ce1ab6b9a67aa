// What every fuzz target shares: the input as a file (the loaders under test take paths, as the commands
// call them) and the rule for what a finding is.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace raylab::fuzz {

// Writes the input to <per-process temporary folder>/input<extension> and returns that path. The folder
// holds nothing else, so a glTF's relative URIs find no files; it is removed at exit.
std::string writeInput(const uint8_t* data, size_t size, const std::string& extension);

// The input as text (the parsers take std::string; embedded NULs stay).
inline std::string inputText(const uint8_t* data, size_t size) { return std::string(reinterpret_cast<const char*>(data), size); }

}  // namespace raylab::fuzz

// A target runs the parser inside try { ... } catch (const DocumentedError&) {} and nothing else: any
// other exception escapes LLVMFuzzerTestOneInput, which libFuzzer reports as a crash (an uncaught
// exception aborts), as it does sanitizer reports, aborts, timeouts and running out of memory.

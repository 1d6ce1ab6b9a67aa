// Window scripts (`raylab --script FILE`, app/ui_script.h): parseScript is what loadScript runs on the
// file's text. The only acceptable failure is ScriptError.
#include "app/ui_script.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    raylab::parseScript(raylab::fuzz::inputText(data, size), "fuzz.txt");
  } catch (const raylab::ScriptError&) {
  }
  return 0;
}

// imgui.ini (ui/settings_ini.h): the bytes go through Dear ImGui's own ini parser, as at startup, which
// hands the [Raylab][State] lines to raylab's handler. Nothing may escape: the handler skips what it cannot
// use. Saved settings that are accepted must pass validateSettings.
#include <imgui.h>

#include "renderer/settings/settings_validation.h"
#include "tests/fuzz/fuzz_input.h"
#include "ui/settings_ini.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // A fresh context per input: ImGui keeps every [Window] section it reads, which would pile up.
  ImGuiContext* context = ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // never write an imgui.ini
  raylab::IniState state;
  raylab::installIniHandler(&state);
  std::string text = raylab::fuzz::inputText(data, size);
  ImGui::LoadIniSettingsFromMemory(text.data(), text.size());
  ImGui::DestroyContext(context);
  if (state.loadedSettings && raylab::settingsError(*state.loadedSettings)) __builtin_trap();
  return 0;
}

#include "ui/settings_ini.h"

#include <cstdio>
#include <cstring>
#include <string>

#include <imgui.h>
#include <imgui_internal.h>

#include "renderer/settings/settings_json.h"

namespace raylab {
namespace {

IniState* stateOf(ImGuiSettingsHandler* h) { return static_cast<IniState*>(h->UserData); }

void* readOpen(ImGuiContext*, ImGuiSettingsHandler* h, const char* name) {
  return std::strcmp(name, "State") == 0 ? h->UserData : nullptr;
}

// A damaged or outdated line is skipped: the lab then starts from the defaults for that part.
void readLine(ImGuiContext*, ImGuiSettingsHandler*, void* entry, const char* line) {
  auto* s = static_cast<IniState*>(entry);
  float f = 0.0f;
  int a = 0, b = 0;
  if (std::strncmp(line, "settings=", 9) == 0) {
    try {
      s->loadedSettings = settingsFromIniLine(line);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "raylab: imgui.ini: ignoring the saved settings (%s)\n", e.what());
    }
  } else if (std::sscanf(line, "scale=%f", &f) == 1 && f >= ViewOptions::kMinScale && f <= ViewOptions::kMaxScale) {
    s->loadedScale = f;
  } else if (std::sscanf(line, "detailed=%d", &a) == 1) {
    s->loadedDetailed = a != 0;
  } else if (std::sscanf(line, "window=%dx%d", &a, &b) == 2 && a > 0 && b > 0) {
    s->loadedWidth = a, s->loadedHeight = b;
  }
}

void writeAll(ImGuiContext*, ImGuiSettingsHandler* h, ImGuiTextBuffer* out) {
  const IniState* s = stateOf(h);
  out->appendf("[%s][State]\n", h->TypeName);
  if (s->settings) out->appendf("%s\n", settingsIniLine(*s->settings).c_str());
  if (s->view) out->appendf("scale=%.3f\ndetailed=%d\n", s->view->resolutionScale, s->view->detailedStats ? 1 : 0);
  if (s->width > 0 && s->height > 0) out->appendf("window=%dx%d\n", s->width, s->height);
  out->append("\n");
}

}  // namespace

void installIniHandler(IniState* state) {
  ImGuiSettingsHandler h;
  h.TypeName = "Raylab";
  h.TypeHash = ImHashStr("Raylab");
  h.ReadOpenFn = readOpen;
  h.ReadLineFn = readLine;
  h.WriteAllFn = writeAll;
  h.UserData = state;
  ImGui::GetCurrentContext()->SettingsHandlers.push_back(h);
}

}  // namespace raylab

#include "app/ui_script.h"

#include <cctype>
#include <fstream>
#include <sstream>

#include "app/cli_options.h"
#include "app/fly_camera.h"
#include "app/setting_flags.h"

namespace raylab {
namespace {

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> w;
  for (std::string s; in >> s;) w.push_back(s);
  return w;
}

// Screenshot names become file names in the screenshot folder: no paths, nothing a shell would mangle.
bool validFileName(const std::string& name) {
  if (name.empty() || name[0] == '.') return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.')) return false;
  return true;
}

// A name that must be a plain file name (screenshots) or label (memory reports).
std::string checkedName(const std::string& what, const std::string& name) {
  if (!validFileName(name)) throw ScriptError(what + " '" + name + "' must be letters, digits, '-', '_' or '.'");
  return name;
}

ScriptAction parseLine(const std::vector<std::string>& w) {
  using K = ScriptAction::Kind;
  ScriptAction a;
  const std::string& verb = w[0];
  auto expectArgs = [&](size_t n, const char* form) {
    if (w.size() != n + 1) throw ScriptError(std::string("expected '") + form + "'");
  };
  if (verb == "set") {
    expectArgs(2, "set KEY VALUE");
    a.kind = K::Set, a.key = w[1], a.value = w[2];
    Settings probe;
    applySettingFlag(probe, a.key, a.value);  // the CLI's validation, now rather than mid-run
  } else if (verb == "camera") {
    std::string text;
    for (const std::string& s : w) text += (text.empty() ? "" : " ") + s;
    std::string error;
    if (!cameraFromText(text, Viewpoint{}, &error)) throw ScriptError(error);
    a.kind = K::Camera, a.value = text;
  } else if (verb == "view") {
    expectArgs(1, "view NAME");
    a.kind = K::View, a.value = w[1];
  } else if (verb == "wait") {
    expectArgs(1, "wait FRAMES");
    a.kind = K::Wait, a.frames = parseUint("wait", w[1], 0, 1000000);
  } else if (verb == "screenshot" || verb == "screenshot-window") {
    expectArgs(1, "screenshot NAME");
    a.kind = verb == "screenshot" ? K::Screenshot : K::ScreenshotWindow, a.value = checkedName("screenshot name", w[1]);
  } else if (verb == "restart-learning") {
    expectArgs(0, "restart-learning");
    a.kind = K::RestartLearning;
  } else if (verb == "reset-layout") {
    expectArgs(0, "reset-layout");
    a.kind = K::ResetLayout;
  } else if (verb == "memory") {
    expectArgs(1, "memory LABEL");
    a.kind = K::Memory, a.value = checkedName("memory label", w[1]);
  } else if (verb == "press") {
    expectArgs(1, "press KEY");
    a.kind = K::Press, a.value = scriptKeyName(w[1]);
    if (a.value.empty()) throw ScriptError("press: unknown key '" + w[1] + "' (a letter, F1..F12, Tab or Esc, optionally shift+)");
  } else if (verb == "quit") {
    expectArgs(0, "quit");
    a.kind = K::Quit;
  } else {
    throw ScriptError("unknown action '" + verb + "' (set, camera, view, wait, screenshot, screenshot-window, reset-layout, restart-learning, memory, press, quit)");
  }
  return a;
}

}  // namespace

std::vector<ScriptAction> parseScript(const std::string& text, const std::string& source) {
  std::vector<ScriptAction> actions;
  std::istringstream in(text);
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    std::vector<std::string> w = words(line);
    if (w.empty() || w[0][0] == '#') continue;
    try {
      actions.push_back(parseLine(w));
    } catch (const std::exception& e) {  // ScriptError and the CLI's UsageError alike
      throw ScriptError(source + ":" + std::to_string(number) + ": " + e.what());
    }
    actions.back().line = number;
  }
  return actions;
}

std::vector<ScriptAction> loadScript(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ScriptError("cannot open script '" + path + "'");
  std::stringstream text;
  text << in.rdbuf();
  return parseScript(text.str(), path);
}

std::string scriptKeyName(const std::string& text) {
  std::string t;
  for (char c : text) t += char(std::toupper(static_cast<unsigned char>(c)));
  std::string shift;
  if (t.rfind("SHIFT+", 0) == 0) shift = "shift+", t = t.substr(6);
  if (t.size() == 1 && t[0] >= 'A' && t[0] <= 'Z') return shift + t;
  if (t == "TAB") return shift + "Tab";
  if (t == "ESC") return shift + "Esc";
  if (t.size() >= 2 && t.size() <= 3 && t[0] == 'F' && std::isdigit(static_cast<unsigned char>(t[1])) &&
      (t.size() == 2 || std::isdigit(static_cast<unsigned char>(t[2])))) {
    const int n = std::stoi(t.substr(1));
    if (n >= 1 && n <= 12) return shift + "F" + std::to_string(n);
  }
  return "";
}

const ScriptAction* ScriptRunner::next() {
  if (waitFrames_ > 0 || pos_ >= actions_.size()) return nullptr;
  const ScriptAction* a = &actions_[pos_++];
  if (a->kind == ScriptAction::Kind::Wait) waitFrames_ = a->frames;
  return a;
}

}  // namespace raylab

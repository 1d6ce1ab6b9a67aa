// Scripted mode (`raylab --script FILE`): UI actions, one per line, run by the window in order, so tests
// and documentation screenshots drive the real window. The whole file is checked before the window
// opens; anything wrong is reported with its line and the program exits with a usage error.
//
//   set KEY VALUE            any render flag without dashes: set strategy gaussian, set heatmap sort-key
//   camera X Y Z TX TY TZ    move the camera (optionally "fov DEGREES" at the end)
//   view NAME                jump to a named viewpoint of the scene
//   wait N                   render N frames
//   screenshot NAME          save the render as NAME.png + NAME.json in the screenshot folder
//   screenshot-window NAME   the same with the panels
//   reset-layout             put the panels back where they open by default (the "Reset layout" button)
//   restart-learning         a fresh length cache and accumulation (the L key): what a re-render learns
//   press KEY                press a hotkey as the keyboard would: a letter, F1..F12, Tab or Esc, with an
//                            optional "shift+" (press K starts or stops recording a camera path)
//   memory LABEL             print the process's resident memory as one JSON line on stdout:
//                            {"memory":LABEL,"frame":N,"vm_rss_kib":K,"vm_hwm_kib":K} (the soak reads it)
//   quit                     close the window (the end of the file does too)
// Blank lines and lines starting with # are ignored.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace raylab {

struct ScriptError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ScriptAction {
  enum class Kind { Set, Camera, View, Wait, Screenshot, ScreenshotWindow, ResetLayout, RestartLearning, Memory, Quit, Press };
  Kind kind = Kind::Quit;
  int line = 0;
  std::string key;    // Set: the flag name
  std::string value;  // Set: its value; View: the viewpoint; Screenshot*: the file name; Camera: the text;
                      // Memory: the label; Press: the key (scriptKeyName's form)
  uint32_t frames = 0;  // Wait
};

// Parses and validates a script (settings with the CLI's rules, camera text, names). `source` names the
// file in messages ("FILE:LINE: ..."). Throws ScriptError.
std::vector<ScriptAction> parseScript(const std::string& text, const std::string& source);
std::vector<ScriptAction> loadScript(const std::string& path);

// A key `press` takes, as "A".."Z", "F1".."F12", "Tab" or "Esc" with an optional "shift+" (any case in the
// script); empty when `text` names none.
std::string scriptKeyName(const std::string& text);

// Where the script is: the window asks it for the next action each frame.
class ScriptRunner {
 public:
  explicit ScriptRunner(std::vector<ScriptAction> actions) : actions_(std::move(actions)) {}
  // The next action to run now, or nullptr while frames are still to be waited (or at the end).
  const ScriptAction* next();
  // Called once per rendered frame.
  void frameDone() {
    if (waitFrames_ > 0) --waitFrames_;
  }
  bool finished() const { return pos_ >= actions_.size() && waitFrames_ == 0; }

 private:
  std::vector<ScriptAction> actions_;
  size_t pos_ = 0;
  uint32_t waitFrames_ = 0;
};

}  // namespace raylab

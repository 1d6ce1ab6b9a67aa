// Where the window keeps what it writes unasked (imgui.ini with the last settings, F12 screenshots): the
// user's config folder, never the working directory, which may be the source tree or anywhere else.
#pragma once

#include <string>

namespace raylab {

// $XDG_CONFIG_HOME/raylab when XDG_CONFIG_HOME is an absolute path (as the XDG spec requires), else
// $HOME/.config/raylab; empty when neither is set (then nothing is kept).
std::string configDir();

}  // namespace raylab

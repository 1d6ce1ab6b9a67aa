// The window's files go to the user's config folder, never the working directory.
#include <cstdlib>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "app/config_dir.h"

namespace raylab {
namespace {

// Sets an environment variable for one scope and restores it after.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value) setenv(name, value, 1);
    else unsetenv(name);
  }
  ~ScopedEnv() {
    if (old_) setenv(name_, old_->c_str(), 1);
    else unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(ConfigDir, FollowsXdgThenHome) {
  ScopedEnv home("HOME", "/home/someone");
  {
    ScopedEnv xdg("XDG_CONFIG_HOME", "/tmp/cfg");
    EXPECT_EQ(configDir(), "/tmp/cfg/raylab");
  }
  {
    ScopedEnv xdg("XDG_CONFIG_HOME", "relative/cfg");  // not absolute: ignored, as the XDG spec says
    EXPECT_EQ(configDir(), "/home/someone/.config/raylab");
  }
  ScopedEnv xdg("XDG_CONFIG_HOME", nullptr);
  EXPECT_EQ(configDir(), "/home/someone/.config/raylab");
  ScopedEnv noHome("HOME", nullptr);
  EXPECT_EQ(configDir(), "");
}

}  // namespace
}  // namespace raylab

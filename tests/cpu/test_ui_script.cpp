// Scripted mode (app/ui_script.h): parsing, the CLI's validation of `set`, and the frame counting.
#include <gtest/gtest.h>

#include "app/ui_script.h"

namespace raylab {
namespace {

using K = ScriptAction::Kind;

TEST(UiScript, ParsesEveryAction) {
  auto actions = parseScript(
      "# a comment\n"
      "set strategy gaussian\n"
      "\n"
      "set heatmap sort-key\n"
      "camera 1 2 3 0 0 0\n"
      "view openings\n"
      "wait 3\n"
      "screenshot a\n"
      "screenshot-window b.window\n"
      "quit\n",
      "t.txt");
  ASSERT_EQ(actions.size(), 8u);
  EXPECT_EQ(actions[0].kind, K::Set);
  EXPECT_EQ(actions[0].key, "strategy");
  EXPECT_EQ(actions[0].value, "gaussian");
  EXPECT_EQ(actions[0].line, 2);
  EXPECT_EQ(actions[2].kind, K::Camera);
  EXPECT_EQ(actions[3].kind, K::View);
  EXPECT_EQ(actions[4].kind, K::Wait);
  EXPECT_EQ(actions[4].frames, 3u);
  EXPECT_EQ(actions[5].kind, K::Screenshot);
  EXPECT_EQ(actions[6].kind, K::ScreenshotWindow);
  EXPECT_EQ(actions[6].value, "b.window");
  EXPECT_EQ(actions[7].kind, K::Quit);
  EXPECT_EQ(actions[7].line, 10);
}

// Each bad line is reported with the file and line, and the reason.
TEST(UiScript, RejectsBadLinesWithTheirLineNumber) {
  const std::pair<const char*, const char*> cases[] = {
      {"set strategy fastest", "--strategy must be one of"},
      {"set bounces 0", "--bounces must be between"},
      {"set nonsense 1", "not a render setting"},
      {"set strategy", "set KEY VALUE"},
      {"set heatmap hot", "--heatmap must be one of"},
      {"camera 1 2", "camera X Y Z"},
      {"wait soon", "whole number"},
      {"screenshot ../escape", "screenshot name"},
      {"screenshot", "screenshot NAME"},
      {"jump 3", "unknown action 'jump'"},
      {"quit now", "expected 'quit'"},
  };
  for (const auto& [line, message] : cases) {
    try {
      parseScript("wait 1\n" + std::string(line) + "\n", "s.txt");
      ADD_FAILURE() << "accepted: " << line;
    } catch (const ScriptError& e) {
      std::string what = e.what();
      EXPECT_EQ(what.rfind("s.txt:2: ", 0), 0u) << what;
      EXPECT_NE(what.find(message), std::string::npos) << line << " -> " << what;
    }
  }
}

TEST(UiScript, RunnerWaitsTheGivenFrames) {
  ScriptRunner runner(parseScript("set bounces 2\nwait 2\nscreenshot a\n", "s"));
  const ScriptAction* a = runner.next();
  ASSERT_TRUE(a);
  EXPECT_EQ(a->kind, K::Set);
  a = runner.next();
  ASSERT_TRUE(a);
  EXPECT_EQ(a->kind, K::Wait);
  EXPECT_EQ(runner.next(), nullptr);  // frame 1 of 2
  runner.frameDone();
  EXPECT_EQ(runner.next(), nullptr);  // frame 2 of 2
  runner.frameDone();
  a = runner.next();
  ASSERT_TRUE(a);
  EXPECT_EQ(a->kind, K::Screenshot);
  EXPECT_EQ(runner.next(), nullptr);
  EXPECT_TRUE(runner.finished());
}

TEST(UiScript, MissingFileIsAScriptError) {
  EXPECT_THROW(loadScript("/nonexistent/script.txt"), ScriptError);
}

}  // namespace
}  // namespace raylab

namespace raylab {
namespace {

TEST(UiScript, LayoutAndMemoryActions) {
  auto actions = parseScript("reset-layout\nmemory warm-up.1\n", "t.txt");
  ASSERT_EQ(actions.size(), 2u);
  EXPECT_EQ(actions[0].kind, ScriptAction::Kind::ResetLayout);
  EXPECT_EQ(actions[1].kind, ScriptAction::Kind::Memory);
  EXPECT_EQ(actions[1].value, "warm-up.1");
  for (const char* bad : {"memory", "memory a b", "memory ../x", "reset-layout now"})
    EXPECT_THROW(parseScript(std::string(bad) + "\n", "t.txt"), ScriptError) << bad;
}

}  // namespace
}  // namespace raylab

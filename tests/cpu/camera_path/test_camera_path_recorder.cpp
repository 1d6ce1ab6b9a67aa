// Recording a camera path in the window (app/camera_path/camera_path_recorder.h) and saving it (app/camera_path/camera_path_file.h):
// what was recorded comes back from the saved text through the parser `--camera-path` uses, every keyframe
// bit for bit, and replays the recorded cameras exactly at their frames; a recording the parser would refuse
// is refused when it stops, not when it is replayed. And the script's `press KEY`, which the window test
// records through.
#include <gtest/gtest.h>

#include <cstring>

#include "app/camera_path/camera_path_file.h"
#include "app/camera_path/camera_path_recorder.h"
#include "app/ui_script.h"

namespace raylab {
namespace {

const glm::vec3 kRecordUp(0.0f, 1.0f, 0.0f);

Viewpoint recordedView(glm::vec3 position, glm::vec3 target, float fovDegrees) {
  Viewpoint v;
  v.position = position;
  v.target = target;
  v.up = kRecordUp;
  v.yfovRadians = glm::radians(fovDegrees);
  return v;
}

bool sameFloatBits(const glm::vec3& a, const glm::vec3& b) { return std::memcmp(&a, &b, sizeof(a)) == 0; }

// A fly over a few UI frames, with awkward floats (thirds, tiny and large values) and a camera that stands
// still for two frames, as a recording has them.
std::vector<Viewpoint> recordedFlight() {
  return {recordedView({0.1f, 4.0f, -29.0f}, {0.0f, 6.0f, -66.0f}, 45.0f),
          recordedView({0.1f, 4.0f, -29.0f}, {0.0f, 6.0f, -66.0f}, 45.0f),
          recordedView({1.0f / 3.0f, 4.000001f, -31.7f}, {1e-7f, 6.0f, -66.0f}, 44.123456f),
          recordedView({12345.678f, -3.25f, 1e-5f}, {12340.0f, -3.0f, 7.0f}, 60.0f)};
}

TEST(CameraPathRecorder, RecordsOneKeyframePerFrameOnlyWhileRecording) {
  CameraPathRecorder r;
  r.add(recordedFlight()[0]);  // not recording: ignored
  EXPECT_FALSE(r.recording());
  EXPECT_EQ(r.frames(), 0u);
  r.start(kRecordUp);
  for (const Viewpoint& v : recordedFlight()) r.add(v);
  EXPECT_TRUE(r.recording());
  EXPECT_EQ(r.frames(), 4u);
  const std::optional<CameraPath> path = r.stop("rec.path.json");
  ASSERT_TRUE(path);
  EXPECT_FALSE(r.recording());
  EXPECT_EQ(path->name, "rec.path.json");
  EXPECT_EQ(path->frames, 4u);
  for (uint32_t i = 0; i < 4; ++i) {
    EXPECT_EQ(path->keyframes[i].frame, i);
    EXPECT_FALSE(path->keyframes[i].cut);
  }
  r.add(recordedFlight()[0]);  // stopped: ignored again
  EXPECT_EQ(r.frames(), 0u);
  r.start(kRecordUp);
  EXPECT_FALSE(r.stop("empty").has_value()) << "a recording of no frame is no path";
}

TEST(CameraPathRecorder, SavedTextParsesBackToTheRecordedCamerasBitForBit) {
  const std::vector<Viewpoint> views = recordedFlight();
  CameraPathRecorder r;
  r.start(kRecordUp);
  for (const Viewpoint& v : views) r.add(v);
  const CameraPath recorded = *r.stop("rec.path.json");
  const std::string text = cameraPathFileText(recorded);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 3 + long(views.size())) << "one keyframe a line:\n" << text;
  const CameraPath parsed = parseCameraPath(text, "rec.path.json", kRecordUp);
  ASSERT_EQ(parsed.keyframes.size(), recorded.keyframes.size());
  EXPECT_EQ(parsed.frames, recorded.frames);
  for (size_t i = 0; i < views.size(); ++i) {
    const CameraKeyframe &a = recorded.keyframes[i], &b = parsed.keyframes[i];
    EXPECT_EQ(a.frame, b.frame);
    EXPECT_TRUE(sameFloatBits(a.position, b.position)) << i;
    EXPECT_TRUE(sameFloatBits(a.target, b.target)) << i;
    EXPECT_EQ(std::memcmp(&a.fovDegrees, &b.fovDegrees, sizeof(float)), 0) << i;
    EXPECT_EQ(a.cut, b.cut);
    // The replay's camera at frame i is the recorded one: position and target exactly, the fov as the
    // degrees it was saved in give it back.
    const PathCamera c = cameraAt(parsed, uint32_t(i), kRecordUp);
    EXPECT_TRUE(sameFloatBits(c.view.position, views[i].position)) << i;
    EXPECT_TRUE(sameFloatBits(c.view.target, views[i].target)) << i;
    EXPECT_NEAR(c.view.yfovRadians, views[i].yfovRadians, 1e-6f) << i;
    EXPECT_FALSE(c.cut);
  }
  // The JSON form and the text are one: the text parses to the JSON cameraPathFileJson makes.
  EXPECT_EQ(nlohmann::json::parse(text), cameraPathFileJson(recorded));
}

TEST(CameraPathRecorder, ARecordingTheReplayWouldRefuseIsRefusedWhenItStops) {
  CameraPathRecorder r;
  r.start(kRecordUp);
  r.add(recordedView({0, 1, 0}, {0, 5, 0}, 45.0f));  // straight up: no horizon
  try {
    r.stop("up.path.json");
    ADD_FAILURE() << "a camera looking straight up was saved";
  } catch (const CameraPathError& e) {
    EXPECT_NE(std::string(e.what()).find("looks straight up or down"), std::string::npos) << e.what();
  }
}

TEST(UiScriptPress, NamesHotkeysAndRefusesOthers) {
  EXPECT_EQ(scriptKeyName("K"), "K");
  EXPECT_EQ(scriptKeyName("k"), "K");
  EXPECT_EQ(scriptKeyName("Shift+F12"), "shift+F12");
  EXPECT_EQ(scriptKeyName("f1"), "F1");
  EXPECT_EQ(scriptKeyName("tab"), "Tab");
  EXPECT_EQ(scriptKeyName("ESC"), "Esc");
  for (const char* bad : {"", "F0", "F13", "KK", "shift+", "ctrl+K", "1", "F1x"}) EXPECT_EQ(scriptKeyName(bad), "") << bad;
  const std::vector<ScriptAction> actions = parseScript("press k\npress shift+f12\n", "s.txt");
  ASSERT_EQ(actions.size(), 2u);
  EXPECT_EQ(actions[0].kind, ScriptAction::Kind::Press);
  EXPECT_EQ(actions[0].value, "K");
  EXPECT_EQ(actions[1].value, "shift+F12");
  for (const char* line : {"press", "press F13", "press K L"}) {
    try {
      parseScript(std::string(line) + "\n", "s.txt");
      ADD_FAILURE() << "accepted: " << line;
    } catch (const ScriptError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("s.txt:1: ", 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace raylab

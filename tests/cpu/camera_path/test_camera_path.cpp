// Camera paths (app/camera_path/camera_path.h): the camera is each keyframe exactly at its frame, moves continuously
// between keyframes, jumps at a cut and nowhere else, and bad files are refused naming the keyframe.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "app/camera_path/camera_path.h"

namespace raylab {
namespace {

const glm::vec3 kUp(0.0f, 1.0f, 0.0f);
const std::string kData = RAYLAB_SOURCE_DIR "/tests/data/camera_paths/";

CameraPath path(std::vector<CameraKeyframe> keyframes, uint32_t frames) {
  CameraPath p;
  p.name = "test";
  p.keyframes = std::move(keyframes);
  p.frames = frames;
  checkCameraPath(p, kUp);
  return p;
}

// Unevenly spaced in frames and in space, turning and zooming: what a hand-written path looks like.
CameraPath winding(uint32_t scale = 1) {
  return path({{0 * scale, {0, 2, 0}, {0, 2, -10}, 40.0f, false},
               {7 * scale, {3, 2.5f, -1}, {10, 2, -5}, 55.0f, false},
               {20 * scale, {4, 3, -9}, {-5, 1, -12}, 60.0f, false},
               {24 * scale, {1, 2, -11}, {1, 2, 0}, 30.0f, false}},
              25 * scale);
}

float lookAngle(const Viewpoint& a, const Viewpoint& b) {
  const float c = glm::dot(glm::normalize(a.target - a.position), glm::normalize(b.target - b.position));
  return std::acos(std::clamp(c, -1.0f, 1.0f));
}

TEST(CameraPath, KeyframesAreHitExactlyAtTheirFrames) {
  const CameraPath p = winding();
  for (const CameraKeyframe& k : p.keyframes) {
    const PathCamera c = cameraAt(p, k.frame, kUp);
    EXPECT_EQ(c.view.position, k.position) << "frame " << k.frame;
    EXPECT_EQ(c.view.target, k.target) << "frame " << k.frame;
    EXPECT_EQ(c.view.yfovRadians, glm::radians(k.fovDegrees)) << "frame " << k.frame;
    EXPECT_FALSE(c.cut);
  }
  // Before the first keyframe the camera waits at it; after the last it stays there.
  const CameraPath late = path({{5, {0, 1, 0}, {0, 1, -1}, 45.0f, false}, {9, {2, 1, 0}, {2, 1, -1}, 45.0f, false}}, 20);
  EXPECT_EQ(cameraAt(late, 0, kUp).view.position, late.keyframes[0].position);
  EXPECT_EQ(cameraAt(late, 19, kUp).view.position, late.keyframes[1].position);
}

// Continuity: rendered at 100 times the frame rate, no frame-to-frame step is more than a small share of the
// way (a discontinuity would stay as large however finely the path is sampled).
TEST(CameraPath, MovesContinuouslyBetweenKeyframes) {
  const uint32_t scale = 100;
  const CameraPath p = winding(scale);
  float travelled = 0.0f, largestStep = 0.0f, largestTurn = 0.0f, largestZoom = 0.0f;
  for (uint32_t f = 1; f < p.frames; ++f) {
    const Viewpoint a = cameraAt(p, f - 1, kUp).view, b = cameraAt(p, f, kUp).view;
    const float step = glm::length(b.position - a.position);
    travelled += step;
    largestStep = std::max(largestStep, step);
    largestTurn = std::max(largestTurn, lookAngle(a, b));
    largestZoom = std::max(largestZoom, std::fabs(b.yfovRadians - a.yfovRadians));
    EXPECT_FALSE(cameraAt(p, f, kUp).cut);
  }
  EXPECT_GT(travelled, 10.0f);
  EXPECT_LT(largestStep, 0.02f * travelled);
  EXPECT_LT(largestTurn, 0.01f);      // radians a frame
  EXPECT_LT(largestZoom, 0.0014f);    // the fov changes linearly: 30 degrees over 400 frames at most
  // In between, the camera is between its keyframes' neighbourhood, not flung away (centripetal: no overshoot loops).
  for (uint32_t f = 0; f < p.frames; ++f) {
    const glm::vec3 q = cameraAt(p, f, kUp).view.position;
    EXPECT_TRUE(q.x > -1.5f && q.x < 5.5f && q.y > 1.5f && q.y < 3.5f && q.z > -12.5f && q.z < 1.5f) << f;
  }
}

TEST(CameraPath, ACutIsAJumpAndTheSegmentBeforeItHolds) {
  const CameraPath p = path({{0, {0, 2, 0}, {0, 2, -10}, 40.0f, false},
                             {5, {1, 2, 0}, {1, 2, -10}, 40.0f, false},
                             {12, {50, 9, 50}, {60, 9, 50}, 70.0f, true},
                             {16, {52, 9, 50}, {60, 9, 52}, 70.0f, false}},
                            20);
  for (uint32_t f = 6; f < 12; ++f) {  // nothing is interpolated across the cut: the last keyframe holds
    EXPECT_EQ(cameraAt(p, f, kUp).view.position, p.keyframes[1].position) << f;
    EXPECT_FALSE(cameraAt(p, f, kUp).cut) << f;
  }
  const PathCamera atCut = cameraAt(p, 12, kUp);
  EXPECT_TRUE(atCut.cut);
  EXPECT_EQ(atCut.view.position, p.keyframes[2].position);
  EXPECT_EQ(atCut.view.target, p.keyframes[2].target);
  EXPECT_GT(glm::length(atCut.view.position - cameraAt(p, 11, kUp).view.position), 50.0f);
  // The segment after the cut starts from the cut's keyframe, not from the segment before: it moves
  // only towards keyframe 3 (its x between 50 and 52).
  for (uint32_t f = 13; f < 16; ++f) {
    const glm::vec3 q = cameraAt(p, f, kUp).view.position;
    EXPECT_FALSE(cameraAt(p, f, kUp).cut);
    EXPECT_GT(q.x, 50.0f) << f;
    EXPECT_LT(q.x, 52.0f) << f;
  }
}

TEST(CameraPath, SlerpKeepsUnitLength) {
  std::mt19937 rng(7);
  std::normal_distribution<float> n;
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 a = glm::normalize(glm::vec3(n(rng), n(rng), n(rng)));
    const glm::vec3 b = glm::normalize(glm::vec3(n(rng), n(rng), n(rng)));
    const float t = float(i % 11) / 10.0f;
    const glm::vec3 d = slerpDirection(a, b, t, kUp);
    EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
    // Constant angular speed: the angle from a is t times the whole angle.
    const float whole = std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f));
    EXPECT_NEAR(std::acos(std::clamp(glm::dot(a, d), -1.0f, 1.0f)), t * whole, 2e-3f);
  }
  // Opposite directions turn about the up vector (a pan): half way is horizontal and perpendicular.
  const glm::vec3 half = slerpDirection({1, 0, 0}, {-1, 0, 0}, 0.5f, kUp);
  EXPECT_NEAR(glm::length(half), 1.0f, 1e-6f);
  EXPECT_NEAR(half.y, 0.0f, 1e-6f);
  EXPECT_NEAR(half.x, 0.0f, 1e-6f);
}

// What a malformed path says: each message names the problem and, where there is one, the keyframe.
struct BadPath {
  std::string json;
  const char* says;
};

TEST(CameraPath, MalformedPathsAreRefusedNamingTheKeyframe) {
  const std::string ok0 = R"({"frame": 0, "position": [0, 2, 0], "target": [0, 2, -1], "fov": 45})";
  const BadPath cases[] = {
      {R"({"keyframes": []})", "at least one keyframe"},
      {R"({"frames": 3})", "missing 'keyframes'"},
      {R"([1, 2])", "must be an object"},
      {R"({"keyframes": [{"frame": 0, "position": [0, 2, 0], "fov": 45}]})", "keyframe 0: missing 'target'"},
      {R"({"keyframes": [{"position": [0, 2, 0], "target": [1, 2, 0], "fov": 45}]})", "keyframe 0: missing 'frame'"},
      {R"({"keyframes": [{"frame": 0, "position": [0, 2, 0], "target": [1, 2, 0]}]})", "keyframe 0: missing 'fov'"},
      {(R"({"keyframes": [)" + ok0 + R"(, {"frame": 0, "position": [1, 2, 0], "target": [1, 2, -1], "fov": 45}]})"),
       "keyframe 1: frame 0 is not after keyframe 0's frame 0"},
      {R"({"keyframes": [{"frame": 0, "position": [1e300, 2, 0], "target": [1, 2, 0], "fov": 45}]})",
       "keyframe 0: 'position' must be finite"},
      {R"({"keyframes": [{"frame": 0, "position": [0, 2], "target": [1, 2, 0], "fov": 45}]})",
       "keyframe 0: 'position' must be [x, y, z]"},
      {R"({"keyframes": [{"frame": 0, "position": [1, 2, 0], "target": [1, 2, 0], "fov": 45}]})",
       "keyframe 0: the target equals the position"},
      {R"({"keyframes": [{"frame": -1, "position": [0, 2, 0], "target": [1, 2, 0], "fov": 45}]})",
       "keyframe 0: 'frame' must be a whole number"},
      {R"({"keyframes": [{"frame": 0, "position": [0, 2, 0], "target": [1, 2, 0], "fov": 200}]})",
       "keyframe 0: 'fov' must be between 0.5 and 179.5"},
      {R"({"keyframes": [{"frame": 0, "position": [0, 2, 0], "target": [0, 9, 0], "fov": 45}]})",
       "keyframe 0: looks straight up or down"},
      {R"({"keyframes": [{"frame": 0, "position": [0, 2, 0], "target": [1, 2, 0], "fov": 45, "cut": true}]})",
       "keyframe 0: cannot be a cut"},
      {R"({"keyframes": [{"frame": 0, "position": [0, 2, 0], "target": [1, 2, 0], "fov": 45, "cuts": true}]})",
       "keyframe 0: unknown field 'cuts' (did you mean 'cut'?)"},
      {R"({"keyframes": [{"frame": 0, "position": [0, 2, 0], "target": [1, 2, 0], "fov": 45, "cut": 1}]})",
       "keyframe 0: 'cut' must be true or false"},
      {R"({"frames": 0, "keyframes": [)" + ok0 + "]}", "'frames' must be at least 1"},
      // Through the pole: from looking north and up to looking south and up the short arc passes straight up.
      {R"({"keyframes": [{"frame": 0, "position": [0, 0, 0], "target": [0, 1, 1], "fov": 45},
                         {"frame": 9, "position": [0, 0, 0], "target": [0, 1, -1], "fov": 45}]})",
       "keyframe 0 to keyframe 1: the view turns through straight up or down"},
      {"{\"keyframes\": [\n  {\"frame\": 0,}\n]}", "line 2, column"},
  };
  for (const BadPath& c : cases) {
    try {
      parseCameraPath(c.json, "p.json", kUp);
      ADD_FAILURE() << "accepted: " << c.json;
    } catch (const CameraPathError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind("p.json: ", 0), 0u) << message;
      EXPECT_NE(message.find(c.says), std::string::npos) << "expected '" << c.says << "' in: " << message;
    }
  }
}

TEST(CameraPath, FramesDefaultToTheLastKeyframeAndCanBeGiven) {
  const std::string keys = R"("keyframes": [{"frame": 0, "position": [0, 2, 0], "target": [0, 2, -1], "fov": 45},
                                            {"frame": 9, "position": [1, 2, 0], "target": [1, 2, -1], "fov": 45}])";
  EXPECT_EQ(parseCameraPath("{" + keys + "}", "p", kUp).frames, 10u);
  EXPECT_EQ(parseCameraPath(R"({"frames": 30, )" + keys + "}", "p", kUp).frames, 30u);
}

TEST(CameraPath, FilesLoadAndReportTheirErrors) {
  const CameraPath p = loadCameraPath(kData + "cut_at_2.json", kUp);
  EXPECT_EQ(p.frames, 6u);
  EXPECT_FALSE(cameraAt(p, 1, kUp).cut);
  EXPECT_TRUE(cameraAt(p, 2, kUp).cut);
  EXPECT_THROW(loadCameraPath(kData + "no_such_file.json", kUp), CameraPathError);
  try {
    loadCameraPath(kData + "not_increasing.json", kUp);
    ADD_FAILURE();
  } catch (const CameraPathError& e) {
    EXPECT_NE(std::string(e.what()).find("not_increasing.json: keyframe 2: frame 10 is not after"), std::string::npos) << e.what();
  }
  try {
    loadCameraPath(kData + "syntax_error.json", kUp);
    ADD_FAILURE();
  } catch (const CameraPathError& e) {
    EXPECT_NE(std::string(e.what()).find("line 2, column"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace raylab

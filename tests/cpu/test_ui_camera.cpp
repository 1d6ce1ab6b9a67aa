// The window's fly/orbit camera and its text form (app/fly_camera.h): CPU only.
#include <cmath>

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include "app/fly_camera.h"

namespace raylab {
namespace {

Viewpoint view(glm::vec3 position, glm::vec3 target) {
  Viewpoint v;
  v.name = "test";
  v.position = position;
  v.target = target;
  v.yfovRadians = glm::radians(50.0f);
  return v;
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float eps = 1e-4f) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

TEST(UiCamera, ResetKeepsTheViewpointExactly) {
  FlyCamera c;
  Viewpoint v = view({1, 2, 3}, {4, 2, -1});
  c.reset(v, 1.0f);
  Viewpoint out = c.viewpoint();
  EXPECT_EQ(out.position, v.position);
  EXPECT_EQ(out.target, v.target);
  EXPECT_EQ(out.yfovRadians, v.yfovRadians);
  EXPECT_FALSE(c.update(CameraInput{}));  // no input, no movement: accumulation must not restart
}

TEST(UiCamera, WasdMovesAlongTheViewAtSpeedTimesTime) {
  FlyCamera c;
  c.reset(view({0, 0, 0}, {0, 0, -10}), 2.0f);
  CameraInput in;
  in.move = {0, 0, 1};  // W
  in.seconds = 0.5f;
  EXPECT_TRUE(c.update(in));
  expectNear(c.viewpoint().position, {0, 0, -1});
  in.move = {1, 0, 0};  // D: right of -Z with +Y up is +X
  in.fast = true;
  c.update(in);
  expectNear(c.viewpoint().position, {2.0f * 0.5f * FlyCamera::kFastFactor, 0, -1});
  in = CameraInput{};
  in.move = {0, 1, 0};  // E: up
  in.seconds = 1.0f;
  c.update(in);
  EXPECT_NEAR(c.viewpoint().position.y, 2.0f, 1e-4f);
}

TEST(UiCamera, MouseLookTurnsAndStopsShortOfThePole) {
  FlyCamera c;
  c.reset(view({0, 0, 0}, {0, 0, -1}), 1.0f);
  CameraInput in;
  in.look = {-glm::half_pi<float>() / FlyCamera::kLookRadiansPerPixel, 0};  // 90 degrees to the left
  c.update(in);
  glm::vec3 dir = glm::normalize(c.viewpoint().target - c.viewpoint().position);
  expectNear(dir, {-1, 0, 0}, 1e-3f);
  in.look = {0, -10.0f / FlyCamera::kLookRadiansPerPixel};  // far past straight up
  for (int i = 0; i < 5; ++i) c.update(in);
  dir = glm::normalize(c.viewpoint().target - c.viewpoint().position);
  EXPECT_LT(dir.y, 1.0f);
  EXPECT_GT(dir.y, 0.9f);
  EXPECT_TRUE(std::isfinite(dir.x) && std::isfinite(dir.z));
}

TEST(UiCamera, OrbitKeepsThePivotAndDistance) {
  FlyCamera c;
  c.reset(view({0, 0, 5}, {0, 0, 0}), 1.0f);
  c.setOrbit(true, {0, 0, 0});
  CameraInput in;
  in.look = {200, 50};
  for (int i = 0; i < 10; ++i) c.update(in);
  Viewpoint v = c.viewpoint();
  EXPECT_EQ(v.target, glm::vec3(0.0f));
  EXPECT_NEAR(glm::length(v.position), 5.0f, 1e-3f);
  in = CameraInput{};
  in.zoom = 3;  // scroll towards the pivot
  c.update(in);
  EXPECT_LT(glm::length(c.viewpoint().position), 5.0f);
}

TEST(UiCamera, TextRoundTripsExactly) {
  Viewpoint v = view({1.25f, -3.5f, 1e-7f}, {0.1f, 0.2f, 0.3f});
  std::string error;
  std::optional<Viewpoint> back = cameraFromText(cameraToText(v), Viewpoint{}, &error);
  ASSERT_TRUE(back) << error;
  EXPECT_EQ(back->position, v.position);
  EXPECT_EQ(back->target, v.target);
  EXPECT_FLOAT_EQ(back->yfovRadians, v.yfovRadians);
}

TEST(UiCamera, TextAcceptsTheScriptFormAndRejectsJunk) {
  Viewpoint base = view({0, 0, 0}, {0, 0, -1});
  std::string error;
  std::optional<Viewpoint> v = cameraFromText("camera 1 2 3 4 5 6", base, &error);
  ASSERT_TRUE(v) << error;
  EXPECT_EQ(v->position, glm::vec3(1, 2, 3));
  EXPECT_EQ(v->yfovRadians, base.yfovRadians);  // no fov: kept
  EXPECT_TRUE(cameraFromText("  1 2 3 4 5 6 fov 30 ", base, &error));
  for (const char* bad : {"camera 1 2 3", "camera 1 2 3 4 5 x", "camera 1 2 3 1 2 3", "camera 1 2 3 4 5 6 fov 0",
                          "camera 1 2 3 4 5 6 7", "camera nan 0 0 1 1 1", ""}) {
    error.clear();
    EXPECT_FALSE(cameraFromText(bad, base, &error)) << bad;
    EXPECT_FALSE(error.empty()) << bad;
  }
}

TEST(UiCamera, ShortTextRoundsForReading) {
  Viewpoint v = view({1.05202198e-05f, -2.5f, 12.3456789f}, {-0.0000004f, 1.2f, 1000.0f});
  std::string text = cameraToShortText(v);
  EXPECT_EQ(text.rfind("camera 0 -2.5 12.346 0 1.2 1000 fov ", 0), 0u) << text;
  EXPECT_EQ(text.find("e-"), std::string::npos) << text;  // no exponent
  std::string error;
  EXPECT_TRUE(cameraFromText(text, Viewpoint{}, &error)) << error;  // still a camera that can be pasted
}

TEST(UiCamera, UnnamedViewpointIsLabelledByWhereItStands) {
  Viewpoint v = view({0.3f, 1.6f, 9.0f}, {0, 1.2f, 0});
  v.name.clear();
  EXPECT_EQ(viewpointLabel(v), "camera at (0.3, 1.6, 9)");
  v.name = "alley";
  EXPECT_EQ(viewpointLabel(v), "alley");
}

}  // namespace
}  // namespace raylab

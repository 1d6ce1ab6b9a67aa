// The built-in camera paths (app/camera_path/camera_path_builtin.h): they exist for the scenes named, start and end
// where they say, stay in or near the scene, cut where they say, and the walks pass through no wall.
#include <gtest/gtest.h>

#include <string>

#include "app/camera_path/camera_path_builtin.h"
#include "renderer/bvh/embree_scene.h"
#include "scenes/clutter.h"
#include "scenes/procedural.h"
#include "scenes/scene_library.h"

namespace raylab {
namespace {

const Scene& temple() {
  static const Scene s = makeTemple();
  return s;
}
const Scene& clutter() {
  static const Scene s = makeClutter(kClutterMinTriangles);
  return s;
}

bool inside(const Bounds& b, const glm::vec3& p) {
  return p.x >= b.min.x && p.y >= b.min.y && p.z >= b.min.z && p.x <= b.max.x && p.y <= b.max.y && p.z <= b.max.z;
}

// The steps the camera takes between two frames of a segment that pass through a triangle (each step as a
// segment against the scene's triangles); a cut is a jump, not a step.
int wallsCrossed(const Scene& scene, const CameraPath& path) {
  const EmbreeScene embree(scene.triangles);
  const glm::vec3 up = sceneUp(scene);
  int crossed = 0;
  for (uint32_t f = 1; f < path.frames; ++f) {
    const PathCamera now = cameraAt(path, f, up);
    if (now.cut) continue;
    const glm::vec3 a = cameraAt(path, f - 1, up).view.position, b = now.view.position;
    const float length = glm::length(b - a);
    if (length > 1e-6f && embree.intersect(a, (b - a) / length, length).t >= 0.0f) ++crossed;
  }
  return crossed;
}

TEST(CameraPathBuiltin, ThePathsOfEachScene) {
  EXPECT_EQ(builtinCameraPathNames(temple()), (std::vector<std::string>{"orbit", "walk", "cut"}));
  EXPECT_EQ(builtinCameraPathNames(clutter()), (std::vector<std::string>{"orbit", "pan", "cut"}));
  EXPECT_EQ(builtinCameraPathNames(loadSceneByName("cornell")), (std::vector<std::string>{"orbit"}));
  // The temple with detail is the temple: its paths too.
  EXPECT_EQ(builtinCameraPathNames(loadSceneByName("temple-detail:300000")).size(), 3u);
}

// Within one diagonal of the bounds' centre: the orbits from the bounds stand just outside them (a scene of
// unknown layout may fill its bounds, and a flat one has no inside), the rest inside.
TEST(CameraPathBuiltin, EveryPathStaysInOrNearTheScene) {
  const Scene gltf = loadSceneByName(RAYLAB_SOURCE_DIR "/tests/data/valid_triangle.gltf");
  for (const Scene* scene : {&temple(), &clutter(), &gltf}) {
    const Bounds b = scene->bounds();
    ASSERT_GT(glm::length(b.extent()), 0.0f);
    for (const std::string& name : builtinCameraPathNames(*scene)) {
      const CameraPath p = builtinCameraPath(*scene, name);
      EXPECT_EQ(p.name, "builtin:" + name);
      EXPECT_EQ(p.frames, kBuiltinPathFrames);
      for (uint32_t f = 0; f < p.frames; ++f)
        EXPECT_LE(glm::length(cameraAt(p, f, sceneUp(*scene)).view.position - b.center()), glm::length(b.extent()))
            << scene->name << " " << name << " frame " << f;
    }
  }
  // The clutter room's paths stay in the room itself.
  for (const std::string& name : builtinCameraPathNames(clutter())) {
    const CameraPath p = builtinCameraPath(clutter(), name);
    for (uint32_t f = 0; f < p.frames; ++f)
      EXPECT_TRUE(inside(clutterRoomInterior(), cameraAt(p, f, sceneUp(clutter())).view.position)) << name << " frame " << f;
  }
}

TEST(CameraPathBuiltin, TheWalkGoesFromTheAlleyToTheHallThroughNoWall) {
  const CameraPath walk = builtinCameraPath(temple(), "walk");
  const glm::vec3 up = sceneUp(temple());
  EXPECT_EQ(cameraAt(walk, 0, up).view.position, temple().findViewpoint("alley")->position);
  EXPECT_EQ(cameraAt(walk, walk.frames - 1, up).view.position, temple().findViewpoint("hall")->position);
  EXPECT_EQ(cameraAt(walk, walk.frames - 1, up).view.target, temple().findViewpoint("hall")->target);
  EXPECT_EQ(wallsCrossed(temple(), walk), 0);
  EXPECT_EQ(wallsCrossed(temple(), builtinCameraPath(temple(), "orbit")), 0);
  EXPECT_EQ(wallsCrossed(clutter(), builtinCameraPath(clutter(), "pan")), 0);
  // The check can fail: straight from the alley to the hall goes through the buildings and walls between.
  CameraPath straight = walk;
  straight.keyframes = {walk.keyframes.front(), walk.keyframes.back()};
  EXPECT_GT(wallsCrossed(temple(), straight), 0);
}

TEST(CameraPathBuiltin, TheCutPathsAlternateTheirViewsEveryShot) {
  for (const auto& [scene, views] : {std::pair{&temple(), std::pair{"hall", "openings"}},
                                     std::pair{&clutter(), std::pair{"shelves", "floor"}}}) {
    const CameraPath p = builtinCameraPath(*scene, "cut");
    const glm::vec3 up = sceneUp(*scene);
    for (uint32_t f = 0; f < p.frames; ++f) {
      const PathCamera c = cameraAt(p, f, up);
      const bool shotStart = f % kBuiltinShotFrames == 0;
      EXPECT_EQ(c.cut, shotStart && f > 0) << f;
      if (shotStart) {
        const Viewpoint& v = *scene->findViewpoint((f / kBuiltinShotFrames) % 2 == 0 ? views.first : views.second);
        EXPECT_EQ(c.view.position, v.position) << f;
        EXPECT_EQ(c.view.target, v.target) << f;
      }
    }
  }
}

TEST(CameraPathBuiltin, UnknownNamesAndListSayWhatThereIs) {
  try {
    resolveCameraPath("builtin:list", temple());
    ADD_FAILURE();
  } catch (const CameraPathError& e) {
    EXPECT_EQ(std::string(e.what()), "the built-in paths of temple are: orbit, walk, cut (as builtin:NAME)");
  }
  try {
    resolveCameraPath("builtin:pann", clutter());
    ADD_FAILURE();
  } catch (const CameraPathError& e) {
    EXPECT_NE(std::string(e.what()).find("no built-in path 'pann' (did you mean builtin:pan?)"), std::string::npos) << e.what();
  }
  EXPECT_THROW(resolveCameraPath("builtin:walk", loadSceneByName("cornell")), CameraPathError);
}

}  // namespace
}  // namespace raylab

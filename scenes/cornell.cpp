// The Cornell box after the Cornell program of computer graphics' measured scene (walls 5.55 units,
// i.e. the original millimetres / 100, axis-aligned for simplicity). It is the reference scene every
// path tracer is checked against by eye: colour bleeding from the red and green walls, soft shadows of
// the two blocks under a small area light. Closed but for the front, so skyColor is black.
#include <cmath>

#include "scenes/mesh_builder.h"
#include "scenes/procedural.h"

namespace raylab {

namespace {

Material lambert(const char* name, glm::vec3 color) {
  Material m;
  m.name = name;
  m.baseColor = color;
  m.roughness = 1.0f;
  m.specularWeight = 0.0f;  // the classic box is purely diffuse
  return m;
}

// A block standing on the floor: footprint centred at (cx, cz), rotated by `yaw` around +y.
void block(MeshBuilder& b, float cx, float cz, float half, float height, float yaw, uint32_t mat) {
  b.orientedBox({cx, 0.5f * height, cz}, {half, 0.5f * height, half}, yaw, 0.0f, mat);
}

}  // namespace

Scene makeCornell() {
  Scene scene;
  scene.name = "cornell";
  scene.skyColor = glm::vec3(0.0f);
  MeshBuilder b(scene);
  uint32_t white = b.material(lambert("white", {0.73f, 0.73f, 0.73f}));
  uint32_t red = b.material(lambert("red", {0.65f, 0.05f, 0.05f}));
  uint32_t green = b.material(lambert("green", {0.12f, 0.45f, 0.15f}));
  Material lightMat = lambert("light", {0.78f, 0.78f, 0.78f});
  lightMat.emissive = {17.0f, 12.0f, 4.0f};  // the usual RGB stand-in for the measured spectrum
  uint32_t light = b.material(lightMat);

  // The camera looks along +z from z < 0, so +x is on the image's left: red at x = 5.55, green at 0.
  const float w = 5.55f;
  b.quad({0, 0, 0}, {0, 0, w}, {w, 0, w}, {w, 0, 0}, white);  // floor, facing up
  b.quad({0, w, 0}, {w, w, 0}, {w, w, w}, {0, w, w}, white);  // ceiling, facing down
  b.quad({0, 0, w}, {0, w, w}, {w, w, w}, {w, 0, w}, white);  // back wall, facing the camera
  b.quad({w, 0, 0}, {w, 0, w}, {w, w, w}, {w, w, 0}, red);    // left wall in the image
  b.quad({0, 0, 0}, {0, w, 0}, {0, w, w}, {0, 0, w}, green);  // right wall in the image
  // The light hangs just below the ceiling, facing down, so it does not coincide with the ceiling.
  const float ly = w - 0.01f;
  b.quad({2.13f, ly, 2.27f}, {3.43f, ly, 2.27f}, {3.43f, ly, 3.32f}, {2.13f, ly, 3.32f}, light);

  block(b, 1.85f, 1.69f, 0.83f, 1.65f, -0.29f, white);  // short block, front right
  block(b, 3.68f, 3.51f, 0.83f, 3.30f, 0.29f, white);   // tall block, back left

  Viewpoint front;
  front.name = "front";
  front.position = {2.78f, 2.73f, -8.0f};
  front.target = {2.78f, 2.73f, 0.0f};
  front.yfovRadians = 2.0f * std::atan(0.025f / (2.0f * 0.035f));  // the original 35 mm lens, 25 mm film
  scene.viewpoints.push_back(front);
  return scene;
}

}  // namespace raylab

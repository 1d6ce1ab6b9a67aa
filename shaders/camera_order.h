// The order camera paths take in the first bounce's arrays, shared by C++ (the tests' twin) and GLSL (generate,
// the megakernels, the heatmap gather). Slot order is free: a path's id is its pixel and sample, and its random
// numbers and radiance follow the id, so any order of slots renders the same image bit for bit. Scanline order
// puts one row's 32 pixels in a warp; tiles of 8x4 pixels put a compact patch there, whose camera rays (and the
// first bounce's rays from their hits) traverse more of the same nodes. Aila and Laine's kernels trace tiles
// for that reason (4x4 gave tinybvh's kernel 19% on Sponza's camera rays; docs/results/h200-sbvh).
// The image is cut into bands of RL_CAMERA_TILE_H rows and each band into tiles of RL_CAMERA_TILE_W columns,
// row-major within a tile; the last band and each band's last tile may be smaller, so every size is one
// bijection of its pixels. Samples of one pixel stay adjacent.
#ifndef RAYLAB_CAMERA_ORDER_H
#define RAYLAB_CAMERA_ORDER_H

#define RL_CAMERA_TILE_W 8u
#define RL_CAMERA_TILE_H 4u

#ifdef __cplusplus
#include <cstdint>
namespace raylab::gpu {
#define RL_CAMERA_ORDER_FN inline uint32_t
#define uint uint32_t
#else
#define RL_CAMERA_ORDER_FN uint
#endif

// The pixel (y * width + x) whose camera path goes to slot `slot` < width * height.
RL_CAMERA_ORDER_FN cameraPixelOfSlot(uint slot, uint width, uint height) {
  const uint band = slot / (width * RL_CAMERA_TILE_H);
  const uint bandRows = height - band * RL_CAMERA_TILE_H < RL_CAMERA_TILE_H ? height - band * RL_CAMERA_TILE_H
                                                                            : RL_CAMERA_TILE_H;
  const uint inBand = slot - band * width * RL_CAMERA_TILE_H;
  const uint tile = inBand / (RL_CAMERA_TILE_W * bandRows);
  const uint tileCols = width - tile * RL_CAMERA_TILE_W < RL_CAMERA_TILE_W ? width - tile * RL_CAMERA_TILE_W
                                                                            : RL_CAMERA_TILE_W;
  const uint inTile = inBand - tile * RL_CAMERA_TILE_W * bandRows;
  return (band * RL_CAMERA_TILE_H + inTile / tileCols) * width + tile * RL_CAMERA_TILE_W + inTile % tileCols;
}

// The path id (pixel * spp + sample) generated into slot `slot` of the first bounce.
RL_CAMERA_ORDER_FN cameraPathOfSlot(uint slot, uint width, uint height, uint spp) {
  return cameraPixelOfSlot(slot / spp, width, height) * spp + slot % spp;
}

#undef RL_CAMERA_ORDER_FN
#ifdef __cplusplus
#undef uint
}  // namespace raylab::gpu
#endif

#endif

#version 460
// Bounce 0 setup: one camera path per (pixel, sample), its id = pixel * sppPerFrame + sample, in the slots of
// camera_order.h (tiles of pixels).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "shared_types.h"
#include "path_shading.glsl"
#include "path_stage.glsl"
#include "live_paths.glsl"
#include "dispatch_index.glsl"
#include "camera_order.h"

void main() {
  GpuFrame f = FrameBuf(pc.frame).f;
  uint i = flatInvocationIndex();
  if (i == 0u) writeLivePaths(f, f.pathCount);
  if (i >= f.pathCount) return;
  GpuPathState s = f.state[pc.stateSet];
  const uint id = cameraPathOfSlot(i, f.width, f.height, f.sppPerFrame);
  uint rng = rngSeed(id, f.frameIndex, 0u, f.seed, RL_RNG_CAMERA);
  PathVars p = cameraPath(f.camera, id / f.sppPerFrame, f.width, f.height, rng);
  storePath(s, i, p, id);
}

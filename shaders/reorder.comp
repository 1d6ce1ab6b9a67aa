#version 460
// Moves every path-state array of the current set to its sorted slot in the other set, so the next
// bounce reads coherent memory (indexing through the permutation without moving the data made the
// study's tracer slower). Each thread reads one path in order and scatters it to rank[j]. Slots from the
// live prefix's end on (GpuFrame::live, after the sort) hold finished paths: they are only marked
// finished, so no stale state from an earlier bounce looks alive to the key stage.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "shared_types.h"

layout(local_size_x_id = 0) in;
layout(push_constant, scalar) uniform Push {
  FrameBuf frame;
  UintBuf rank;   // new slot of each path of the source set
  uint stateSet;  // source set; the destination is the other one
  uint count;
} pc;

void main() {
  uint j = gl_GlobalInvocationID.x;
  if (j >= pc.count) return;
  GpuFrame f = pc.frame.f;
  GpuPathState dst = f.state[1u - pc.stateSet];
  uint i = pc.rank.v[j];
  if (i >= f.live.v[0]) {
    dst.alive.v[i] = 0u;
    return;
  }
  GpuPathState src = f.state[pc.stateSet];
  dst.origin.v[i] = src.origin.v[j];
  dst.direction.v[i] = src.direction.v[j];
  dst.throughput.v[i] = src.throughput.v[j];
  dst.radiance.v[i] = src.radiance.v[j];
  dst.pathId.v[i] = src.pathId.v[j];
  dst.alive.v[i] = 1u;  // every path in the live prefix is alive: finished ones sorted behind it
  dst.predictedLength.v[i] = src.predictedLength.v[j];
}

// A stage's flat thread index in a dispatch laid out by dispatch_grid.h (rows of work groups), and the
// indirect dispatch size of `threads` threads for the stages that write one. Every stage dispatched by a
// thread count (ComputePipeline::dispatchThreads, or indirectly) finds its index here, never from
// gl_GlobalInvocationID.x alone, and returns at or past its count.
#ifndef RAYLAB_DISPATCH_INDEX_GLSL
#define RAYLAB_DISPATCH_INDEX_GLSL

#include "spec_ids.h"
#include "dispatch_grid.h"

#ifndef RL_RAY_TRACING_STAGE  // ray-generation shaders have gl_LaunchIDEXT instead
// The work-group size is specialization constant 0 in every compute stage (ComputePipeline). Declared here
// too (a repeated, equal declaration is allowed) because gl_WorkGroupSize before any declaration is (1, 1, 1)
// to glslang: a stage that declared its size below this include got every index wrong.
layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;

uint flatInvocationIndex() {
  return (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
}
#endif

// Groups of `groupSize` threads covering `threads`, as x, y, z of a VkDispatchIndirectCommand.
uvec3 dispatchGridFor(uint threads, uint groupSize, uint rowGroups) {
  uint groups = (threads + groupSize - 1u) / groupSize;
  return uvec3(RL_GRID_X(groups, rowGroups), RL_GRID_Y(groups, rowGroups), 1u);
}

#endif

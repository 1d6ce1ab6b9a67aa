#version 460
// Does nothing: what a dispatch costs before any work (renderer/vk/empty_dispatch.h). It takes a path
// stage's push constants, so each dispatch binds and pushes as the wavefront's stages do.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#include "spec_ids.h"
#include "shared_types.h"

layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;
layout(push_constant, scalar) uniform Push { PathStagePush pc; };

void main() {
  // Never true (stages are numbered from 0): keeps the push block declared without touching memory.
  if (pc.stateSet == 0xFFFFFFFFu && pc.bounce == 0xFFFFFFFFu) barrier();
}

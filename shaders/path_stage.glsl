// Preamble of the wavefront stages: push constants, the frame block and the path-state accessors
// (path_state.glsl).
#ifndef RAYLAB_PATH_STAGE_GLSL
#define RAYLAB_PATH_STAGE_GLSL

#include "shared_types.h"
#include "path_shading.glsl"
#include "path_state.glsl"

layout(local_size_x_id = 0) in;
layout(push_constant, scalar) uniform Push { PathStagePush pc; };

#endif

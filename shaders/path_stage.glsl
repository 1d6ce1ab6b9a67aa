// Preamble of the wavefront stages (compute, and the rt tracer's ray-generation shaders): push constants,
// the frame block and the path-state accessors (path_state.glsl).
#ifndef RAYLAB_PATH_STAGE_GLSL
#define RAYLAB_PATH_STAGE_GLSL

#include "spec_ids.h"
#include "shared_types.h"
#include "path_shading.glsl"
#include "path_state.glsl"

#ifndef RL_RAY_TRACING_STAGE
layout(local_size_x_id = RL_SPEC_GROUP_SIZE) in;  // ray-generation shaders have a launch size instead
#endif
layout(push_constant, scalar) uniform Push { PathStagePush pc; };

#endif

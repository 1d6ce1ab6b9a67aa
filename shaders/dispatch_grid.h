// How a count of work groups is laid out as a grid, shared by C++ (renderer/vk/dispatch_size.h, direct
// dispatches) and GLSL (dispatch_index.glsl, the indirect dispatch sizes shaders write). A device may launch
// as few as 65535 groups in x (Vulkan's minimum; lavapipe's limit), fewer than 2048x2048 paths need at 64
// a group, so a dispatch is rows of at most `rowGroups` groups (the device's maxComputeWorkGroupCount[0]):
// x = min(groups, rowGroups), y = the rows. Only the last row can be short of threads past the count,
// which every shader skips, as it skips the tail of the last group.
#ifndef RAYLAB_DISPATCH_GRID_H
#define RAYLAB_DISPATCH_GRID_H

#define RL_GRID_X(groups, rowGroups) ((groups) < (rowGroups) ? (groups) : (rowGroups))
#define RL_GRID_Y(groups, rowGroups) ((groups) <= (rowGroups) ? 1u : ((groups) + (rowGroups) - 1u) / (rowGroups))

#endif

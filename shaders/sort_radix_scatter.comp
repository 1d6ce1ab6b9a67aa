#version 460
// Radix sort, step (c) of a pass: the scatter (sort_radix_scatter.glsl), ranking a tile's keys with ballots.
#extension GL_GOOGLE_include_directive : require
#include "sort_radix_scatter.glsl"

#version 460
// The radix scatter (sort_radix_scatter.glsl) ranking a tile's keys with subgroupPartitionNV: the lanes of a
// subgroup holding the same digit in one instruction (NVIDIA's match), where the portable ranking takes a ballot
// per digit bit. Only for devices with VK_NV_shader_subgroup_partitioned (GpuSorter::Tuning::radixRankPartitioned),
// so it is a module of its own: its capability must not reach a device without it.
#extension GL_GOOGLE_include_directive : require
#extension GL_NV_shader_subgroup_partitioned : require
#define RL_RANK_PARTITIONED
#include "sort_radix_scatter.glsl"

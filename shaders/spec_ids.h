// Specialization-constant ids, one per meaning across every shader: GLSL declares
// `layout(constant_id = RL_SPEC_*)`, the host passes {RL_SPEC_*, value} pairs (renderer/vk/spec_constants.h).
// An id keeps its meaning in every shader, so a pipeline may pass one its shader does not declare: Vulkan
// ignores map entries whose id the module lacks. Plain macros, readable from C++ and GLSL alike.
#ifndef RAYLAB_SPEC_IDS_H
#define RAYLAB_SPEC_IDS_H

#define RL_SPEC_GROUP_SIZE 0          // local_size_x_id: threads per work group
#define RL_SPEC_KEY_STRATEGY 1        // RL_KEY_*: keys, key_learn, key_merge, shade's fused keys, SER's hint
#define RL_SPEC_COUNT_SIMT 2          // bool: traversal counts active lanes (simt_counting.glsl)
#define RL_SPEC_COMPACT 3             // bool: shade appends the survivors (Settings::compaction)
#define RL_SPEC_FUSES_TRACE_SHADE 4   // bool: shade traces its own ray first (Settings::fusesTraceShade)
#define RL_SPEC_FUSES_GATHER 5        // bool: trace reads its path through the sort's order (Settings::fusesGather)
#define RL_SPEC_SUBGROUP_SIZE 6       // the sorts' subgroup width
#define RL_SPEC_KEYS_PER_THREAD 7     // the radix sorts' keys per invocation
#define RL_SPEC_LOOPS_BOUNCES 8       // bool: shade traces and shades every bounce left (Settings::loopsBounces)
#define RL_SPEC_COUNTS_STEPS 9        // bool: the traversal counts its loop iterations (HitRecord::steps)
#define RL_SPEC_BVH_LAYOUT 10         // RL_BVH_*, or RL_BVH_FROM_SCENE: the tree traceSceneBvh walks
#define RL_SPEC_HIT_QUERIES 11        // RL_HIT_QUERY_* bits: the traversals hit_query.comp runs
#define RL_SPEC_TILES_PER_GROUP 12    // the portable radix passes' consecutive tiles a work group

#endif

// Work-group wide exclusive prefix sum for the sort shaders: subgroup scans, then one subgroup scans the
// subgroup sums. Call from uniform control flow (it has barriers); it ends with a barrier so back-to-back
// calls cannot race on the shared scratch. Portable to any subgroup size (lavapipe 8, NVIDIA 32, AMD 64).
#ifndef RAYLAB_SORT_SCAN_GLSL
#define RAYLAB_SORT_SCAN_GLSL

// One slot per possible subgroup (a subgroup has at least one invocation) plus the total.
shared uint sGroupScan[gl_WorkGroupSize.x + 1];

uint groupExclusiveAdd(uint v, out uint total) {
  uint inclusive = subgroupInclusiveAdd(v);
  uint subgroupSum = subgroupAdd(v);
  if (subgroupElect()) sGroupScan[gl_SubgroupID] = subgroupSum;
  barrier();
  if (gl_SubgroupID == 0) {
    uint carry = 0;
    for (uint base = 0; base < gl_NumSubgroups; base += gl_SubgroupSize) {
      uint i = base + gl_SubgroupInvocationID;
      uint x = i < gl_NumSubgroups ? sGroupScan[i] : 0u;
      uint xi = subgroupInclusiveAdd(x);
      if (i < gl_NumSubgroups) sGroupScan[i] = carry + xi - x;
      carry += subgroupAdd(x);
    }
    if (subgroupElect()) sGroupScan[gl_WorkGroupSize.x] = carry;
  }
  barrier();
  uint result = sGroupScan[gl_SubgroupID] + inclusive - v;
  total = sGroupScan[gl_WorkGroupSize.x];
  barrier();
  return result;
}

#endif

// Closest-hit and any-hit traversal of the compressed 8-wide BVH (shared_types.h: BvhWideNode), after Ylitie,
// Karras and Laine (HPG 2017). Included by bvh_traverse.glsl, whose HitRecord, box and triangle tests it uses;
// its C++ twin is renderer/bvh/bvh_traverse_cpu.cpp (keep the two in step).
//
// The stack holds node groups, not nodes (CWBVH's): (first child node, the children's interior-slot mask << 8 |
// a hit mask over visit positions). Visit position i of slot s is s ^ octant(ray), so the lowest set bit is the
// child nearest in the direction-slot order. The current group stays in registers; it is pushed only when the
// visited node has interior children to descend into, at most once per level, so the stack never holds more
// than the tree's depth (BvhWideStats::maxDepth + 1 <= RL_BVH_STACK). The leaves hit at a node are its
// triangle group: (the node's triBase, a mask over its leaf block's triangles, each leaf's bits from its meta
// byte), tested in the same iteration, before the next node; no leaf record is read.
//
// One loop iteration, and one step (HitRecord::steps, RL_TRAVERSAL_STEP()), is one wide node visited: its 8
// quantized child boxes tested, then the triangles of the leaves among them that the ray entered. The binary
// traversal's step is one binary node (two child boxes) or one leaf. Steps of the two layouts count different
// work; compare them as what they are, the spread within a warp that reordering shrinks.
//
// On an H200: 1.4-1.6x the binary frame time before the node's vector loads and the ray's per-node transform,
// 1.21-1.32x with them, level with it unsorted once leaves lost their records and took no iteration of their
// own, and faster than it sorted (docs/results/h200-wide-bvh/cwbvh). Leaves deferred behind nearer interior
// children (the node pushed again, its leaves re-tested with the shorter tMax) cost 11-14% of the trace there
// (docs/results/h200-wide-bvh/deferred-leaves): a node's triangles are tested in its own iteration, as in CWBVH.
// The box tests are what the trace spends its instructions on (docs/results/h200-wide-bvh/box-tests): plane
// bytes converted by the exponent trick instead of the driver's one-instruction conversion cost 11%; the
// loop setting one hit bit a slot, with the interior and leaf bookkeeping after it, saved 2% of the wavefront
// frame and 6-8% of the megakernel.
#ifndef RAYLAB_BVH_TRAVERSE_WIDE_GLSL
#define RAYLAB_BVH_TRAVERSE_WIDE_GLSL

uint wideByte(uint word, uint slot) { return (word >> ((slot & 3u) * 8u)) & 0xFFu; }

// A mask over slots as a mask over visit positions (position s ^ octant): bit s moves to bit s ^ octant, one
// swap of bits, pairs or nibbles for each set bit of the octant.
uint slotsInVisitOrder(uint slots, uint octant) {
  if ((octant & 1u) != 0u) slots = ((slots & 0x55u) << 1) | ((slots >> 1) & 0x55u);
  if ((octant & 2u) != 0u) slots = ((slots & 0x33u) << 2) | ((slots >> 2) & 0x33u);
  if ((octant & 4u) != 0u) slots = ((slots & 0x0Fu) << 4) | (slots >> 4);
  return slots;
}

HitRecord traverseBvhWide(GpuScene scene, vec3 origin, vec3 dir, float tMax, bool anyHit) {
  HitRecord hit = noHit();
  vec3 invDir = safeInverse(dir);
  uint octant = (dir.x < 0.0 ? 1u : 0u) | (dir.y < 0.0 ? 2u : 0u) | (dir.z < 0.0 ? 4u : 0u);
  uvec2 stack[RL_BVH_STACK];
  uint sp = 0u;
  BvhWideNodeQuads quads = BvhWideNodeQuads(scene.wideNodes);
  TriangleQuads triangleQuads = TriangleQuads(scene.triangles);
  // A virtual parent whose only child, interior slot 0, is the root: the loop's first visit is the root's.
  uvec2 nodeGroup = uvec2(0u, (1u << 8) | (1u << octant));
  while (true) {
    if ((nodeGroup.y & 0xFFu) == 0u) {
      if (sp == 0u) break;
      nodeGroup = stack[--sp];
    }
    uint position = findLSB(nodeGroup.y & 0xFFu);
    nodeGroup.y &= ~(1u << position);
    uint slot = position ^ octant;
    uint interiorBelow = (nodeGroup.y >> 8) & ((1u << slot) - 1u);
    uint nodeIndex = nodeGroup.x + bitCount(interiorBelow);

    if (kCountsSteps) hit.steps++;
    RL_TRAVERSAL_STEP();
    // The node in five 16-byte loads: origin + exponents/interior mask, bases + meta, then the 12 words of planes.
    uint base = nodeIndex * 5u;
    uvec4 w0 = quads.v[base], w1 = quads.v[base + 1u], w2 = quads.v[base + 2u], w3 = quads.v[base + 3u],
          w4 = quads.v[base + 4u];
    // Each axis's near and far planes chosen by the ray's sign once per node (CWBVH): the entry and exit
    // distances then need no min and max per child. Words 2k, 2k + 1 hold axis k's 8 planes.
    uvec2 loX = w2.xy, loY = w2.zw, loZ = w3.xy, hiX = w3.zw, hiY = w4.xy, hiZ = w4.zw;
    uvec2 nearX = (octant & 1u) != 0u ? hiX : loX, farX = (octant & 1u) != 0u ? loX : hiX;
    uvec2 nearY = (octant & 2u) != 0u ? hiY : loY, farY = (octant & 2u) != 0u ? loY : hiY;
    uvec2 nearZ = (octant & 4u) != 0u ? hiZ : loZ, farZ = (octant & 4u) != 0u ? loZ : hiZ;
    vec3 scale = vec3(uintBitsToFloat((w0.w & 0xFFu) << 23), uintBitsToFloat(((w0.w >> 8) & 0xFFu) << 23),
                      uintBitsToFloat(((w0.w >> 16) & 0xFFu) << 23));
    // The ray in the node's quantized frame, once per node: a child plane q is at t = q * tScale + tOrigin.
    vec3 tScale = scale * invDir;
    vec3 tOrigin = (uintBitsToFloat(w0.xyz) - origin) * invDir;
    uint interiorMask = w0.w >> 24;
    // The box tests set one bit a slot and nothing else (the loop is unrolled; the shift is a constant): the
    // interior and leaf work below touch only the slots hit.
    uint hitSlots = 0u;
    for (uint s = 0u; s < RL_BVH_WIDTH; ++s) {
      uint word = s >> 2;
      vec3 qnear = vec3(wideByte(nearX[word], s), wideByte(nearY[word], s), wideByte(nearZ[word], s));
      vec3 qfar = vec3(wideByte(farX[word], s), wideByte(farY[word], s), wideByte(farZ[word], s));
      // The slab test's min and max of the two planes, without them: tScale has the ray's sign per axis and
      // the lower plane is never above the upper one (an empty slot has both 0).
      vec3 tn = qnear * tScale + tOrigin;
      vec3 tf = qfar * tScale + tOrigin;
      float enter = max(max(tn.x, tn.y), max(tn.z, 0.0));
      float leave = min(min(tf.x, tf.y), min(tf.z, tMax));
      if (!(enter > leave)) hitSlots |= 1u << s;  // not <=: a NaN box test counts as a hit, as it always did
    }
    uint nodeHits = slotsInVisitOrder(hitSlots & interiorMask, octant);
    uint triangleHits = 0u;
    for (uint leaves = hitSlots & ~interiorMask; leaves != 0u; leaves &= leaves - 1u) {
      uint s = uint(findLSB(leaves));
      // A leaf's meta byte (0: an empty slot): (count - 1) << 5 | offset, its bits in the triangle mask.
      uint meta = wideByte(s < 4u ? w1.z : w1.w, s);
      if (meta != 0u) triangleHits |= ((2u << (meta >> 5)) - 1u) << (meta & 31u);
    }
    // Descending: the siblings still to visit wait on the stack (only then: a node without interior hits
    // leaves the current group as it is, no push and pop).
    if (nodeHits != 0u) {
      if ((nodeGroup.y & 0xFFu) != 0u) stack[sp++] = nodeGroup;
      nodeGroup = uvec2(w1.x, (interiorMask << 8) | nodeHits);
    }
    // The node's triangle group, in the same iteration: every lane that visited a node tests its triangles
    // together, before the next node's box tests (which then cull with the shorter tMax).
    while (triangleHits != 0u) {
      uint index = w1.y + uint(findLSB(triangleHits));
      triangleHits &= triangleHits - 1u;
      // Three 16-byte loads (v0, e1, e2 and the shading words beside them), not a field at a time.
      vec4 a = triangleQuads.v[3u * index], b = triangleQuads.v[3u * index + 1u], c = triangleQuads.v[3u * index + 2u];
      intersectTriangleEdges(a.xyz, b.xyz, c.xyz, index, origin, dir, hit, tMax);
      if (anyHit && hit.t > 0.0) return hit;
    }
  }
  return hit;
}

#endif

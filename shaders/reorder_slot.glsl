// The reorder of slot i after a sort, shared by gather_path_state.comp (the reorder as a pass of its own) and
// trace.comp's gathering variant (Settings::fusion gather): the path the sort put at i (GpuFrame::sortValues)
// moves from state set `srcSet` into slot i of the other set, and the live prefix's new length goes to
// GpuFrame::live: the sorted keys (GpuFrame::sortKeys) put every finished path (RL_DEAD_KEY) behind the
// live ones, so exactly one slot sees the boundary. Slots behind it are marked empty. Needs shared_types.h,
// live_paths.glsl and path_state.glsl. Returns whether slot i holds a live path, and its ray.
#ifndef RAYLAB_REORDER_SLOT_GLSL
#define RAYLAB_REORDER_SLOT_GLSL

bool reorderSlot(GpuFrame f, uint srcSet, uint i, out vec3 origin, out vec3 direction) {
  bool live = f.sortKeys.v[i] != RL_DEAD_KEY;
  if (i == 0u && !live) writeLivePaths(f, 0u);
  if (live && (i + 1u == f.pathCount || f.sortKeys.v[i + 1u] == RL_DEAD_KEY)) writeLivePaths(f, i + 1u);
  GpuPathState dst = f.state[1u - srcSet];
  if (!live) {
    markSlotEmpty(dst, f.hits, i);
    return false;
  }
  return movePath(dst, i, f.state[srcSet], f.sortValues.v[i], origin, direction);
}

#endif

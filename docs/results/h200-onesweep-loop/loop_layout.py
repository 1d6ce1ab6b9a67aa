# Variant for the next device run (issue 36, the 512x256 Sponza gap): the bounce loop (shade.comp with
# RL_SPEC_LOOPS_BOUNCES) holds one traversal, Settings::bvh's, as the megakernel does (RL_SPEC_BVH_LAYOUT).
# Apply in the repository root: python3 loop_layout.py; build; measure against the unpatched binary with
# bench --trace-shades loop --sizes 512x256,720p (cases of the real-time table), then revert or keep.
import re
def edit(p, pairs):
    s = open(p).read()
    for old, new in pairs:
        assert s.count(old) == 1, (p, old)
        s = s.replace(old, new)
    open(p, 'w').write(s)
edit('renderer/path_tracer.h', [("  LazyPipeline shadeLoop_;  // shade.comp's bounce loop (Settings::loopsBounces)",
                                 "  LazyPipeline shadeLoop_[2];  // shade.comp's bounce loop (Settings::loopsBounces), by traversal")])
edit('renderer/path_tracer.cpp', [("      shadeLoop_(pathStage(ctx, \"shade\", {{RL_SPEC_COMPACT, 0}, {RL_SPEC_FUSES_TRACE_SHADE, 1}, {RL_SPEC_LOOPS_BOUNCES, 1}})),",
  "      shadeLoop_{pathStage(ctx, \"shade\", {{RL_SPEC_COMPACT, 0}, {RL_SPEC_FUSES_TRACE_SHADE, 1}, {RL_SPEC_LOOPS_BOUNCES, 1}, {RL_SPEC_BVH_LAYOUT, 0}}),\n"
  "                 pathStage(ctx, \"shade\", {{RL_SPEC_COMPACT, 0}, {RL_SPEC_FUSES_TRACE_SHADE, 1}, {RL_SPEC_LOOPS_BOUNCES, 1}, {RL_SPEC_BVH_LAYOUT, 1}})},")])
edit('renderer/frame_steps.cpp', [("shadeLoop_.get().dispatchIndirect(", "shadeLoop_[traversalOf(settings_.bvh)].get().dispatchIndirect(")])

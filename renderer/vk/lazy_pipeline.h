// A compute pipeline built on its first use. Creating a pipeline compiles its shader, which on lavapipe takes
// 1-90 ms (shade 90, megakernel 32, trace 14 on the 2-core CI machine) and was 360 ms of a 500 ms one-frame
// `raylab render`: most of it for variants the settings never pick (the megakernel's in a wavefront render,
// the counting trace without --count-simt, plain shade under compaction, the heatmap's passes without a
// heatmap). Built lazily, a render compiles only what it records.
#pragma once

#include <optional>
#include <string>

#include "renderer/vk/compute_pipeline.h"

namespace raylab {

class LazyPipeline {
 public:
  LazyPipeline(const VulkanContext& ctx, std::string shader, uint32_t pushBytes, uint32_t groupSize,
               SpecConstants variant = {}, WritesSizes writesSizes = WritesSizes::No)
      : ctx_(&ctx), shader_(std::move(shader)), pushBytes_(pushBytes), groupSize_(groupSize),
        variant_(std::move(variant)), writesSizes_(writesSizes) {}

  // The pipeline, built now if it was not yet (throws as ComputePipeline's constructor does).
  const ComputePipeline& get() {
    if (!pipeline_) pipeline_.emplace(*ctx_, shader_, pushBytes_, groupSize_, variant_, writesSizes_);
    return *pipeline_;
  }

 private:
  const VulkanContext* ctx_;
  std::string shader_;
  uint32_t pushBytes_, groupSize_;
  SpecConstants variant_;
  WritesSizes writesSizes_;
  std::optional<ComputePipeline> pipeline_;
};

}  // namespace raylab

// Specialization constants as {id, value} pairs, the ids being shaders/spec_ids.h's RL_SPEC_*: a pipeline
// names what it sets rather than relying on positions that each shader numbers its own way.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "shaders/spec_ids.h"

namespace raylab {

struct SpecConstant {
  uint32_t id;     // RL_SPEC_*
  uint32_t value;  // a uint, or 0/1 for a bool
};
using SpecConstants = std::vector<SpecConstant>;

// The map entries and data behind one VkSpecializationInfo. `info` points into this object: keep it alive
// (and unmoved) until the pipeline is created. Throws when an id is given twice (`shader` names the
// pipeline in the message).
class Specialization {
 public:
  Specialization(const SpecConstants& constants, const std::string& shader);
  Specialization(const Specialization&) = delete;
  Specialization& operator=(const Specialization&) = delete;

  const VkSpecializationInfo* info() const { return entries_.empty() ? nullptr : &info_; }

 private:
  std::vector<VkSpecializationMapEntry> entries_;
  std::vector<uint32_t> values_;
  VkSpecializationInfo info_{};
};

}  // namespace raylab

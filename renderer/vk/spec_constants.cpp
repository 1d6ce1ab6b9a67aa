#include "renderer/vk/spec_constants.h"

#include "renderer/vk/vk_check.h"

namespace raylab {

Specialization::Specialization(const SpecConstants& constants, const std::string& shader) {
  for (const SpecConstant& c : constants) {
    for (const VkSpecializationMapEntry& e : entries_)
      if (e.constantID == c.id)
        throw VulkanError(shader + ": specialization constant " + std::to_string(c.id) + " given twice");
    entries_.push_back({c.id, static_cast<uint32_t>(values_.size() * sizeof(uint32_t)), sizeof(uint32_t)});
    values_.push_back(c.value);
  }
  info_ = {static_cast<uint32_t>(entries_.size()), entries_.data(), values_.size() * sizeof(uint32_t),
           values_.data()};
}

}  // namespace raylab

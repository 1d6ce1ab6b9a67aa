// What the host reads from a shader's SPIR-V instead of restating it (as zeux/niagara does): the size of
// the push-constant block, so a C++ push struct and the shader's block cannot drift apart.
#pragma once

#include <cstdint>
#include <span>

namespace raylab {

// Bytes of the push-constant block (the end of its last member, as laid out by the shader's offsets);
// 0 when the shader declares none. Throws std::runtime_error on malformed SPIR-V.
uint32_t spirvPushConstantBytes(std::span<const uint32_t> spirv);

}  // namespace raylab

// SPIR-V of every shader in shaders/, compiled by glslang at build time and embedded in the binary, so the
// program runs from any directory and a carried build folder needs no shader files beside it.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace raylab {

// Throws std::runtime_error if no shader of that name (file name without .comp) was built.
std::span<const uint32_t> shaderSpirv(std::string_view name);

}  // namespace raylab

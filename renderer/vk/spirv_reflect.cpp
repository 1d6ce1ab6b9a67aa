#include "renderer/vk/spirv_reflect.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <vector>

namespace raylab {
namespace {

// The few opcodes, decorations and storage classes a push-constant block is built from (SPIR-V 1.5 spec).
enum : uint32_t {
  kOpTypeBool = 20, kOpTypeInt = 21, kOpTypeFloat = 22, kOpTypeVector = 23, kOpTypeMatrix = 24,
  kOpTypeArray = 28, kOpTypeStruct = 30, kOpTypePointer = 32, kOpConstant = 43, kOpVariable = 59,
  kOpDecorate = 71, kOpMemberDecorate = 72,
  kDecorationArrayStride = 6, kDecorationMatrixStride = 7, kDecorationOffset = 35,
  kStoragePushConstant = 9,
};

struct Module {
  std::map<uint32_t, std::vector<uint32_t>> types;  // result id -> the instruction's words (opcode first)
  std::map<uint32_t, uint32_t> constants;           // result id -> first literal word
  std::map<uint32_t, uint32_t> arrayStrides;
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> memberOffsets;  // (struct, member) -> offset
  uint32_t pushPointerType = 0;

  uint32_t sizeOf(uint32_t type, int depth = 0) const {
    auto it = types.find(type);
    if (it == types.end() || depth > 16) throw std::runtime_error("SPIR-V: unknown type in push constants");
    const std::vector<uint32_t>& w = it->second;
    switch (w[0]) {
      case kOpTypeBool: return 4;
      case kOpTypeInt:
      case kOpTypeFloat: return w[2] / 8;
      case kOpTypeVector: return w[3] * sizeOf(w[2], depth + 1);
      case kOpTypePointer: return 8;  // PhysicalStorageBuffer addresses (GL_EXT_buffer_reference)
      case kOpTypeArray: {
        auto stride = arrayStrides.find(type);
        auto length = constants.find(w[3]);
        if (stride == arrayStrides.end() || length == constants.end())
          throw std::runtime_error("SPIR-V: push-constant array without stride or length");
        return stride->second * length->second;
      }
      case kOpTypeStruct: {
        uint32_t end = 0;
        for (uint32_t m = 0; m + 2 < w.size(); ++m) {
          auto offset = memberOffsets.find({type, m});
          if (offset == memberOffsets.end()) throw std::runtime_error("SPIR-V: struct member without offset");
          end = std::max(end, offset->second + sizeOf(w[m + 2], depth + 1));
        }
        return end;
      }
      default: throw std::runtime_error("SPIR-V: unsupported type in push constants");
    }
  }
};

Module parse(std::span<const uint32_t> spirv) {
  if (spirv.size() < 5 || spirv[0] != 0x07230203u) throw std::runtime_error("SPIR-V: bad header");
  Module m;
  for (size_t i = 5; i < spirv.size();) {
    uint32_t count = spirv[i] >> 16, op = spirv[i] & 0xFFFFu;
    if (count == 0 || i + count > spirv.size()) throw std::runtime_error("SPIR-V: truncated instruction");
    std::span<const uint32_t> w = spirv.subspan(i, count);
    if ((op >= kOpTypeBool && op <= kOpTypeMatrix) || op == kOpTypeArray || op == kOpTypeStruct ||
        op == kOpTypePointer) {
      m.types[w[1]] = std::vector<uint32_t>{op};
      m.types[w[1]].insert(m.types[w[1]].end(), w.begin() + 1, w.end());
    } else if (op == kOpConstant && count >= 4) {
      m.constants[w[2]] = w[3];
    } else if (op == kOpDecorate && count >= 4 && w[2] == kDecorationArrayStride) {
      m.arrayStrides[w[1]] = w[3];
    } else if (op == kOpMemberDecorate && count >= 5 && w[3] == kDecorationOffset) {
      m.memberOffsets[{w[1], w[2]}] = w[4];
    } else if (op == kOpVariable && count >= 4 && w[3] == kStoragePushConstant) {
      m.pushPointerType = w[1];
    }
    i += count;
  }
  return m;
}

}  // namespace

uint32_t spirvPushConstantBytes(std::span<const uint32_t> spirv) {
  Module m = parse(spirv);
  if (m.pushPointerType == 0) return 0;
  auto pointer = m.types.find(m.pushPointerType);
  if (pointer == m.types.end() || pointer->second[0] != kOpTypePointer)
    throw std::runtime_error("SPIR-V: push-constant variable without a pointer type");
  return m.sizeOf(pointer->second[3]);
}

}  // namespace raylab

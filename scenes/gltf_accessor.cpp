// Validated accessor reads. tinygltf hands back accessors, buffer views and buffers as parsed, with
// indices and byte ranges unchecked, so each read first proves that every byte it will touch lies
// inside the buffer's data, then copies element by element (memcpy: glTF data need not be aligned).
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <iostream>

#include "scenes/gltf_internal.h"

namespace raylab::gltf {

void Source::fail(const std::string& message) const { throw SceneLoadError(file + ": " + message); }

void Source::warn(const std::string& message) const {
  std::cerr << "warning: " << file << ": " << message << "\n";
  warnings.push_back(message);
}

namespace {

const char* typeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
      return "VEC2";
    case TINYGLTF_TYPE_VEC3:
      return "VEC3";
    case TINYGLTF_TYPE_VEC4:
      return "VEC4";
    case TINYGLTF_TYPE_MAT2:
      return "MAT2";
    case TINYGLTF_TYPE_MAT3:
      return "MAT3";
    case TINYGLTF_TYPE_MAT4:
      return "MAT4";
    default:
      return "unknown type";
  }
}

const char* componentName(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_INT:
      return "INT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return "FLOAT";
    case TINYGLTF_COMPONENT_TYPE_DOUBLE:
      return "DOUBLE";
    default:
      return "unknown component type";
  }
}

// A checked window onto an accessor's elements: element i starts at first + i * stride and all
// `count` elements of `elementSize` bytes lie inside the buffer's data.
struct ElementView {
  const unsigned char* first = nullptr;
  size_t stride = 0;
  size_t count = 0;
  int componentType = 0;
  bool normalized = false;
};

template <typename T>
bool contains(std::initializer_list<T> list, T value) {
  for (T v : list)
    if (v == value) return true;
  return false;
}

ElementView checkedView(const Source& src, int index, const std::string& what, int type,
                        std::initializer_list<int> componentTypes) {
  const tinygltf::Model& m = src.model;
  std::string ctx = "accessor " + std::to_string(index) + " (" + what + ")";
  if (index < 0 || static_cast<size_t>(index) >= m.accessors.size())
    src.fail(ctx + ": out of range (file has " + std::to_string(m.accessors.size()) + " accessors)");
  const tinygltf::Accessor& a = m.accessors[static_cast<size_t>(index)];
  if (a.sparse.isSparse) src.fail(ctx + ": sparse accessors are not supported");
  if (a.type != type) src.fail(ctx + ": type " + typeName(a.type) + ", expected " + typeName(type));
  if (!contains(componentTypes, a.componentType)) {
    std::string expected;
    for (int c : componentTypes) expected += std::string(expected.empty() ? "" : " or ") + componentName(c);
    src.fail(ctx + ": component type " + componentName(a.componentType) + ", expected " + expected);
  }
  ElementView view;
  view.count = a.count;
  view.componentType = a.componentType;
  view.normalized = a.normalized;
  if (a.count == 0) return view;
  if (a.bufferView < 0)
    src.fail(ctx + ": has no bufferView (implicit zero data and compressed meshes are not supported)");
  if (static_cast<size_t>(a.bufferView) >= m.bufferViews.size())
    src.fail(ctx + ": bufferView " + std::to_string(a.bufferView) + " out of range (file has " +
             std::to_string(m.bufferViews.size()) + ")");
  const tinygltf::BufferView& bv = m.bufferViews[static_cast<size_t>(a.bufferView)];
  std::string bvCtx = ctx + ": bufferView " + std::to_string(a.bufferView);
  if (bv.buffer < 0 || static_cast<size_t>(bv.buffer) >= m.buffers.size())
    src.fail(bvCtx + ": buffer " + std::to_string(bv.buffer) + " out of range (file has " +
             std::to_string(m.buffers.size()) + ")");
  const tinygltf::Buffer& buffer = m.buffers[static_cast<size_t>(bv.buffer)];
  size_t bufferSize = buffer.data.size();
  if (bufferSize == 0)
    src.fail(bvCtx + ": buffer " + std::to_string(bv.buffer) + " has no data" +
             (buffer.uri.empty() ? "" : " (missing or unreadable '" + buffer.uri.substr(0, 80) + "'?)"));
  if (bv.byteOffset > bufferSize || bv.byteLength > bufferSize - bv.byteOffset)
    src.fail(bvCtx + ": bytes " + std::to_string(bv.byteOffset) + " + " + std::to_string(bv.byteLength) +
             " exceed buffer " + std::to_string(bv.buffer) + " (" + std::to_string(bufferSize) + " bytes)");

  size_t elementSize =
      static_cast<size_t>(tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType)) *
                          tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type)));
  size_t componentSize =
      static_cast<size_t>(tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType)));
  view.stride = bv.byteStride != 0 ? bv.byteStride : elementSize;
  if (view.stride < elementSize || view.stride % componentSize != 0)
    src.fail(bvCtx + ": byteStride " + std::to_string(bv.byteStride) + " does not fit elements of " +
             std::to_string(elementSize) + " bytes");
  // Overflow-free form of: byteOffset + stride * (count - 1) + elementSize <= byteLength.
  size_t length = bv.byteLength;
  if (a.byteOffset > length || elementSize > length - a.byteOffset ||
      a.count - 1 > (length - a.byteOffset - elementSize) / view.stride)
    src.fail(ctx + ": " + std::to_string(a.count) + " elements of " + std::to_string(elementSize) +
             " bytes (stride " + std::to_string(view.stride) + ") from offset " +
             std::to_string(a.byteOffset) + " read past the end of bufferView " +
             std::to_string(a.bufferView) + " (" + std::to_string(length) + " bytes)");
  view.first = buffer.data.data() + bv.byteOffset + a.byteOffset;
  return view;
}

// One component as float; integer types are normalized as glTF defines for texture coordinates.
float component(const ElementView& v, size_t element, int c) {
  const unsigned char* p = v.first + element * v.stride;
  switch (v.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return static_cast<float>(p[c]) / 255.0f;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t x;
      std::memcpy(&x, p + 2 * c, sizeof x);
      return static_cast<float>(x) / 65535.0f;
    }
    default: {
      float x;
      std::memcpy(&x, p + 4 * c, sizeof x);
      return x;
    }
  }
}

}  // namespace

std::vector<glm::vec3> readPositions(const Source& src, int accessor, const std::string& what) {
  ElementView v = checkedView(src, accessor, what, TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT});
  std::vector<glm::vec3> out(v.count);
  for (size_t i = 0; i < v.count; ++i) {
    out[i] = {component(v, i, 0), component(v, i, 1), component(v, i, 2)};
    if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y) || !std::isfinite(out[i].z))
      src.fail("accessor " + std::to_string(accessor) + " (" + what + "): element " + std::to_string(i) +
               " is not finite");
  }
  return out;
}

std::vector<glm::vec2> readTexcoords(const Source& src, int accessor, const std::string& what) {
  ElementView v = checkedView(src, accessor, what, TINYGLTF_TYPE_VEC2,
                              {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                               TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT});
  if (v.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !v.normalized)
    src.fail("accessor " + std::to_string(accessor) + " (" + what +
             "): integer texture coordinates must be normalized");
  std::vector<glm::vec2> out(v.count);
  for (size_t i = 0; i < v.count; ++i) {
    out[i] = {component(v, i, 0), component(v, i, 1)};
    if (!std::isfinite(out[i].x) || !std::isfinite(out[i].y))
      src.fail("accessor " + std::to_string(accessor) + " (" + what + "): element " + std::to_string(i) +
               " is not finite");
  }
  return out;
}

std::vector<uint32_t> readIndices(const Source& src, int accessor, const std::string& what) {
  ElementView v = checkedView(src, accessor, what, TINYGLTF_TYPE_SCALAR,
                              {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                               TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT});
  std::vector<uint32_t> out(v.count);
  for (size_t i = 0; i < v.count; ++i) {
    const unsigned char* p = v.first + i * v.stride;
    if (v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
      out[i] = p[0];
    } else if (v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
      uint16_t x;
      std::memcpy(&x, p, sizeof x);
      out[i] = x;
    } else {
      std::memcpy(&out[i], p, sizeof out[i]);
    }
  }
  return out;
}

}  // namespace raylab::gltf

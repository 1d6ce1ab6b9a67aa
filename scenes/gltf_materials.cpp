// glTF materials to the Scene's metallic-roughness materials, and their base colour images to RGBA8
// textures. Only what the path tracer uses is kept: base colour (factor and texture), metallic and
// roughness factors, emission (times KHR_materials_emissive_strength).
#include <stb_image.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>

#include "scenes/gltf_internal.h"

namespace raylab::gltf {

bool storeEncodedImage(tinygltf::Image* image, int, std::string*, std::string*, int, int,
                       const unsigned char* bytes, int size, void*) {
  if (bytes != nullptr && size > 0) image->image.assign(bytes, bytes + size);
  image->as_is = true;  // tells later code (and tinygltf) these are encoded bytes
  return true;
}

namespace {

// Decodes images on first use, once each, however many materials share them.
class ImageDecoder {
 public:
  explicit ImageDecoder(const Source& src, Scene& scene) : src_(src), scene_(scene) {}

  // Scene texture index for glTF texture `texture`, or -1 where its image is absent or undecodable.
  int texture(int texture, const std::string& what) {
    int image = imageOf(texture, what);
    if (image < 0) return -1;
    auto [it, inserted] = cache_.try_emplace(image, -1);
    if (inserted) {
      std::optional<Texture> t = decode(image);
      if (t) {
        scene_.textures.push_back(std::move(*t));
        it->second = static_cast<int>(scene_.textures.size() - 1);
      }
    }
    return it->second;
  }

  // The mean linear colour of a texture, to stand in for an emissive texture (the Scene has only a
  // constant emission per material): it keeps the material's emitted power about right. The image
  // is decoded only for this and not kept, unless a material also samples it as base colour.
  glm::vec3 meanLinearColor(int texture, const std::string& what) {
    int image = imageOf(texture, what);
    if (image < 0) return glm::vec3(1.0f);
    auto cached = cache_.find(image);
    std::optional<Texture> decoded;
    if (cached == cache_.end()) decoded = decode(image);
    const Texture* t = cached != cache_.end() && cached->second >= 0
                           ? &scene_.textures[static_cast<size_t>(cached->second)]
                           : (decoded ? &*decoded : nullptr);
    if (t == nullptr || t->rgba8.empty()) return glm::vec3(1.0f);
    glm::dvec3 sum(0.0);
    for (uint32_t texel : t->rgba8)
      for (int c = 0; c < 3; ++c)
        sum[c] += std::pow(static_cast<double>((texel >> (8 * c)) & 0xffu) / 255.0, 2.2);
    return glm::vec3(sum / static_cast<double>(t->rgba8.size()));
  }

 private:
  // The image index behind glTF texture `texture` (validated), -1 if it names none.
  int imageOf(int texture, const std::string& what) const {
    const tinygltf::Model& m = src_.model;
    if (texture < 0 || static_cast<size_t>(texture) >= m.textures.size())
      src_.fail(what + ": texture " + std::to_string(texture) + " out of range (file has " +
                std::to_string(m.textures.size()) + ")");
    int image = m.textures[static_cast<size_t>(texture)].source;
    if (image < 0) return -1;  // e.g. only an extension's image (MSFT_texture_dds) is given
    if (static_cast<size_t>(image) >= m.images.size())
      src_.fail(what + ": texture " + std::to_string(texture) + ": image " + std::to_string(image) +
                " out of range (file has " + std::to_string(m.images.size()) + ")");
    return image;
  }

  std::optional<Texture> decode(int index) {
    const tinygltf::Image& image = src_.model.images[static_cast<size_t>(index)];
    std::string label = "image " + std::to_string(index) + (image.uri.empty() ? "" : " '" + image.uri + "'");
    if (image.image.empty() || image.image.size() > static_cast<size_t>(INT32_MAX)) {
      src_.warn(label + " has no (usable) data, drawn untextured");
      return std::nullopt;
    }
    Texture t;
    t.name = image.name.empty() ? image.uri : image.name;
    if (image.as_is) {
      // stb converts any channel count (grey, grey+alpha, RGB, RGBA) and 16-bit data to RGBA8.
      int w = 0, h = 0, channels = 0;
      stbi_uc* pixels = stbi_load_from_memory(image.image.data(), static_cast<int>(image.image.size()), &w,
                                              &h, &channels, 4);
      if (pixels == nullptr) {
        src_.warn(label + " could not be decoded (" + stbi_failure_reason() + "), drawn untextured");
        return std::nullopt;
      }
      pack(t, pixels, w, h, 4, 8);
      stbi_image_free(pixels);
    } else {
      // Decoded by tinygltf (a caller that did not install storeEncodedImage): check its claims.
      int bytesPer = image.bits == 16 ? 2 : (image.bits == 8 ? 1 : 0);
      size_t need = static_cast<size_t>(std::max(image.width, 0)) *
                    static_cast<size_t>(std::max(image.height, 0)) *
                    static_cast<size_t>(std::max(image.component, 0)) * static_cast<size_t>(bytesPer);
      if (bytesPer == 0 || image.component < 1 || image.component > 4 || need == 0 ||
          image.image.size() < need) {
        src_.warn(label + " has an unsupported layout, drawn untextured");
        return std::nullopt;
      }
      pack(t, image.image.data(), image.width, image.height, image.component, image.bits);
    }
    return t;
  }

  // Packs `channels` x `bits` texels into RGBA8 with R in the low byte; grey expands to RGB.
  static void pack(Texture& t, const unsigned char* data, int w, int h, int channels, int bits) {
    t.width = static_cast<uint32_t>(w);
    t.height = static_cast<uint32_t>(h);
    t.rgba8.resize(static_cast<size_t>(w) * static_cast<size_t>(h));
    auto channel = [&](size_t texel, int c) -> uint32_t {
      size_t i = texel * static_cast<size_t>(channels) + static_cast<size_t>(c);
      if (bits == 8) return data[i];
      uint16_t v;
      std::memcpy(&v, data + 2 * i, sizeof v);
      return (static_cast<uint32_t>(v) * 255u + 32767u) / 65535u;
    };
    for (size_t p = 0; p < t.rgba8.size(); ++p) {
      uint32_t r = channel(p, 0);
      uint32_t g = channels >= 3 ? channel(p, 1) : r;
      uint32_t b = channels >= 3 ? channel(p, 2) : r;
      uint32_t a = channels == 4 ? channel(p, 3) : (channels == 2 ? channel(p, 1) : 255u);
      t.rgba8[p] = r | (g << 8) | (b << 16) | (a << 24);
    }
  }

  const Source& src_;
  Scene& scene_;
  std::map<int, int> cache_;
};

float finiteFactor(const Source& src, double value, const std::string& what) {
  if (!std::isfinite(value) || value < 0.0) src.fail(what + " is not a finite, non-negative number");
  return static_cast<float>(value);
}

}  // namespace

void convertMaterials(const Source& src, Scene& scene) {
  ImageDecoder images(src, scene);
  const tinygltf::Model& m = src.model;
  for (size_t i = 0; i < m.materials.size(); ++i) {
    const tinygltf::Material& in = m.materials[i];
    const tinygltf::PbrMetallicRoughness& pbr = in.pbrMetallicRoughness;
    std::string what = "material " + std::to_string(i) + (in.name.empty() ? "" : " '" + in.name + "'");
    Material out;
    out.name = in.name.empty() ? "material" + std::to_string(i) : in.name;
    if (pbr.baseColorFactor.size() < 3) src.fail(what + ": baseColorFactor needs 4 numbers");
    for (int c = 0; c < 3; ++c)
      out.baseColor[c] =
          finiteFactor(src, pbr.baseColorFactor[static_cast<size_t>(c)], what + ": baseColorFactor");
    out.metallic = std::min(finiteFactor(src, pbr.metallicFactor, what + ": metallicFactor"), 1.0f);
    out.roughness = std::min(finiteFactor(src, pbr.roughnessFactor, what + ": roughnessFactor"), 1.0f);
    if (pbr.baseColorTexture.index >= 0)
      out.baseColorTexture = images.texture(pbr.baseColorTexture.index, what + ": baseColorTexture");

    double strength = 1.0;
    auto ext = in.extensions.find("KHR_materials_emissive_strength");
    if (ext != in.extensions.end() && ext->second.Has("emissiveStrength"))
      strength = ext->second.Get("emissiveStrength").GetNumberAsDouble();
    float s = finiteFactor(src, strength, what + ": emissiveStrength");
    for (size_t c = 0; c < 3 && c < in.emissiveFactor.size(); ++c)
      out.emissive[static_cast<int>(c)] =
          s * finiteFactor(src, in.emissiveFactor[c], what + ": emissiveFactor");
    if (out.isEmissive() && in.emissiveTexture.index >= 0)
      out.emissive *= images.meanLinearColor(in.emissiveTexture.index, what + ": emissiveTexture");
    scene.materials.push_back(std::move(out));
  }
}

}  // namespace raylab::gltf

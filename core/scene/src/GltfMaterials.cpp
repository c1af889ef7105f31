#include "GltfMaterials.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "tofsim/util/Error.h"

namespace tofsim::scene::detail {

float srgbToLinear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

namespace {

// srgb: base colours are sRGB-encoded; metallic-roughness values are linear.
Texture decodeImage(const GltfDocument& doc, int index, bool srgb) {
  const ImageDesc& im = doc.images[index];
  const std::string key = "image[" + std::to_string(index) + "] '" + im.name + "'";
  const std::size_t bytes = im.bits == 16 ? 2 : 1;
  if ((im.bits != 8 && im.bits != 16) || im.components < 1 || im.components > 4 || im.width <= 0 ||
      im.height <= 0 ||
      im.pixels.size() != static_cast<std::size_t>(im.width) * im.height * im.components * bytes) {
    throw InputError(FileLoc{doc.file}, key, "image could not be decoded (unsupported format)");
  }
  // Table for 8 bit; direct formula for 16 bit.
  const auto decode = [srgb](float encoded) { return srgb ? srgbToLinear(encoded) : encoded; };
  float lut[256];
  for (int i = 0; i < 256; ++i) lut[i] = decode(i / 255.0f);
  Texture t;
  t.width = im.width;
  t.height = im.height;
  const std::size_t n = static_cast<std::size_t>(im.width) * im.height;
  t.rgb.resize(n * 3);
  for (std::size_t p = 0; p < n; ++p) {
    for (int c = 0; c < 3; ++c) {
      // Grey (and grey+alpha) images repeat their first channel.
      const int src = im.components >= 3 ? c : 0;
      const std::size_t at = (p * im.components + src) * bytes;
      t.rgb[p * 3 + c] = bytes == 1 ? lut[im.pixels[at]]
                                    : decode((im.pixels[at] | im.pixels[at + 1] << 8) / 65535.0f);
    }
  }
  return t;
}

// Decodes each (image, encoding) once and hands out its Scene::textures index.
class TextureTable {
 public:
  TextureTable(const GltfDocument& doc, Scene& scene) : doc_(doc), scene_(scene) {}
  /// -1 when `image` is absent or out of range.
  int32_t indexOf(int image, bool srgb) {
    if (image < 0 || image >= static_cast<int>(doc_.images.size())) return -1;
    const auto key = std::make_pair(image, srgb);
    auto it = index_.find(key);
    if (it == index_.end()) {
      scene_.textures.push_back(decodeImage(doc_, image, srgb));
      it = index_.emplace(key, static_cast<int32_t>(scene_.textures.size() - 1)).first;
    }
    return it->second;
  }

 private:
  const GltfDocument& doc_;
  Scene& scene_;
  std::map<std::pair<int, bool>, int32_t> index_;
};

float unitClamped(double v) { return static_cast<float>(std::min(1.0, std::max(0.0, v))); }

}  // namespace

void convertMaterials(const GltfDocument& doc, Scene& scene, LoadReport& report) {
  TextureTable textures(doc, scene);
  for (std::size_t i = 0; i < doc.materials.size(); ++i) {
    const MaterialDesc& m = doc.materials[i];
    Material out;
    out.name = m.name.empty() ? "material_" + std::to_string(i) : m.name;
    out.albedo = glm::vec3(m.baseColorFactor);
    out.albedoTexture = textures.indexOf(m.baseColorImage, true);
    if (out.albedoTexture >= 0 && m.baseColorTexCoord != 0) {
      report.warnings.push_back("material '" + out.name + "' uses TEXCOORD_" +
                                std::to_string(m.baseColorTexCoord) + " for its base colour");
    }
    out.metallic = unitClamped(m.metallicFactor);
    out.roughness = unitClamped(m.roughnessFactor);
    out.metallicRoughnessTexture = textures.indexOf(m.metallicRoughnessImage, false);
    if (out.metallicRoughnessTexture >= 0 && m.metallicRoughnessTexCoord != 0) {
      report.warnings.push_back("material '" + out.name + "' uses TEXCOORD_" +
                                std::to_string(m.metallicRoughnessTexCoord) +
                                " for its metallic-roughness");
    }
    report.metallicMaterials += m.metallic;
    report.emissiveMaterials += m.emissive;
    report.transmissiveMaterials += m.transmissive;
    report.ignoredMaterialParts.push_back(m.ignored);
    report.materialExtras.push_back(m.extras);
    scene.materials.push_back(std::move(out));
  }
}

Material defaultMaterial() {
  Material m;
  m.name = "default";
  m.albedo = glm::vec3(0.8f);
  return m;
}

}  // namespace tofsim::scene::detail

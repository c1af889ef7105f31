#include "GltfMaterials.h"

#include <cmath>
#include <map>
#include <string>

#include "tofsim/util/Error.h"

namespace tofsim::scene::detail {

float srgbToLinear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

namespace {

Texture decodeImage(const GltfDocument& doc, int index) {
  const ImageDesc& im = doc.images[index];
  const std::string key = "image[" + std::to_string(index) + "] '" + im.name + "'";
  const std::size_t bytes = im.bits == 16 ? 2 : 1;
  if ((im.bits != 8 && im.bits != 16) || im.components < 1 || im.components > 4 ||
      im.width <= 0 || im.height <= 0 ||
      im.pixels.size() != static_cast<std::size_t>(im.width) * im.height * im.components * bytes) {
    throw InputError(FileLoc{doc.file}, key, "image could not be decoded (unsupported format)");
  }
  // Table for 8 bit; direct formula for 16 bit.
  float lut[256];
  for (int i = 0; i < 256; ++i) lut[i] = srgbToLinear(i / 255.0f);
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
                                    : srgbToLinear((im.pixels[at] | im.pixels[at + 1] << 8) / 65535.0f);
    }
  }
  return t;
}

}  // namespace

void convertMaterials(const GltfDocument& doc, Scene& scene, LoadReport& report) {
  std::map<int, int32_t> textureOfImage;
  for (std::size_t i = 0; i < doc.materials.size(); ++i) {
    const MaterialDesc& m = doc.materials[i];
    Material out;
    out.name = m.name.empty() ? "material_" + std::to_string(i) : m.name;
    out.albedo = glm::vec3(m.baseColorFactor);
    if (m.baseColorImage >= 0 && m.baseColorImage < static_cast<int>(doc.images.size())) {
      auto it = textureOfImage.find(m.baseColorImage);
      if (it == textureOfImage.end()) {
        scene.textures.push_back(decodeImage(doc, m.baseColorImage));
        it = textureOfImage.emplace(m.baseColorImage, int32_t(scene.textures.size() - 1)).first;
      }
      out.albedoTexture = it->second;
      if (m.baseColorTexCoord != 0) {
        report.warnings.push_back("material '" + out.name + "' uses TEXCOORD_" +
                                  std::to_string(m.baseColorTexCoord) + " for its base colour");
      }
    }
    report.metallicMaterials += m.metallic;
    report.emissiveMaterials += m.emissive;
    report.transmissiveMaterials += m.transmissive;
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

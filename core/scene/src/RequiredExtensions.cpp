#include "RequiredExtensions.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string_view>

#include "tofsim/util/Error.h"

namespace tofsim::scene::detail {

namespace {

// Extensions whose data the loader reads correctly, or which change nothing a
// diffuse renderer uses.
constexpr std::array<std::string_view, 2> kSupported{
    "KHR_mesh_quantization",
    "KHR_materials_emissive_strength",
};

uint32_t le32(const std::string& s, std::size_t at) {
  uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = v << 8 | uint8_t(s[at + i]);
  return v;
}

/// The JSON text: the whole file, or a .glb's first chunk.
std::string jsonText(const std::string& bytes) {
  if (bytes.size() >= 20 && bytes.compare(0, 4, "glTF") == 0) {
    const uint32_t length = le32(bytes, 12);
    if (le32(bytes, 16) != 0x4E4F534Au || 20 + std::size_t{length} > bytes.size()) return {};
    return bytes.substr(20, length);
  }
  return bytes;
}

}  // namespace

std::vector<std::string> readRequiredExtensions(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const nlohmann::json doc = nlohmann::json::parse(jsonText(bytes), nullptr, false);
  std::vector<std::string> required;
  if (!doc.is_object() || !doc.contains("extensionsRequired")) return required;
  const nlohmann::json& list = doc["extensionsRequired"];
  if (!list.is_array()) return required;
  for (const nlohmann::json& e : list) {
    if (e.is_string()) required.push_back(e.get<std::string>());
  }
  return required;
}

void checkRequiredExtensions(const std::filesystem::path& path) {
  for (const std::string& ext : readRequiredExtensions(path)) {
    if (std::find(kSupported.begin(), kSupported.end(), ext) == kSupported.end()) {
      throw InputError(FileLoc{path.string()}, "",
                       "required extension " + ext + " is not supported");
    }
  }
}

}  // namespace tofsim::scene::detail

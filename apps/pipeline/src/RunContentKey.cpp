#include "tofsim/pipeline/RunContentKey.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "tofsim/config/EffectiveConfigParts.h"
#include "tofsim/pipeline/Version.h"
#include "tofsim/util/Error.h"
#include "tofsim/util/Hash.h"

namespace tofsim::pipeline {

namespace fs = std::filesystem;

namespace {

uint32_t littleEndian32(const char* bytes) {
  uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(bytes[i]);
  return v;
}

// The glTF JSON of a scene file: the whole .gltf, or the JSON chunk of a
// .glb (header: magic, version, length; then chunk length, chunk type
// "JSON", the text). A .glb's BIN chunk is inside the file, hashed with it,
// and is not read here.
std::string gltfJson(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read scene " + path.string());
  char header[20] = {};
  in.read(header, sizeof header);
  if (in.gcount() < 4 || std::memcmp(header, "glTF", 4) != 0) {
    in.clear();
    in.seekg(0);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  constexpr uint32_t kJsonChunk = 0x4E4F534A;  // "JSON", little endian
  if (in.gcount() < 20 || littleEndian32(header + 16) != kJsonChunk) {
    throw InputError("scene " + path.string() + ": not a valid glTF binary (.glb) file");
  }
  std::string json(littleEndian32(header + 12), '\0');
  in.read(json.data(), static_cast<std::streamsize>(json.size()));
  if (static_cast<std::size_t>(in.gcount()) != json.size()) {
    throw InputError("scene " + path.string() + ": truncated JSON chunk");
  }
  return json;
}

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// glTF URIs are RFC 3986 references: "my%20texture.png" names
// "my texture.png". A malformed escape is kept as written.
std::string percentDecoded(const std::string& uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size()) {
      const int hi = hexDigit(uri[i + 1]), lo = hexDigit(uri[i + 2]);
      if (hi >= 0 && lo >= 0) {
        out += static_cast<char>(hi * 16 + lo);
        i += 2;
        continue;
      }
    }
    out += uri[i];
  }
  return out;
}

void addExternalUris(const nlohmann::json& doc, const char* array, const fs::path& folder,
                     std::vector<fs::path>& files) {
  const auto it = doc.find(array);
  if (it == doc.end() || !it->is_array()) return;
  for (const nlohmann::json& entry : *it) {
    if (!entry.is_object() || !entry.contains("uri") || !entry["uri"].is_string()) continue;
    const std::string uri = entry["uri"].get<std::string>();
    if (uri.rfind("data:", 0) == 0) continue;  // embedded: part of the scene file's bytes
    files.push_back(folder / percentDecoded(uri));
  }
}

}  // namespace

std::vector<fs::path> sceneInputFiles(const fs::path& scene) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(gltfJson(scene));
  } catch (const nlohmann::json::exception& e) {
    throw InputError("scene " + scene.string() + ": " + e.what());
  }
  std::vector<fs::path> files = {scene};
  if (doc.is_object()) {
    addExternalUris(doc, "buffers", scene.parent_path(), files);
    addExternalUris(doc, "images", scene.parent_path(), files);
  }
  return files;
}

std::string sceneInputsDigest(const fs::path& scene) {
  // Each file's name (relative, as the document spells it) and digest, so
  // that renaming a texture is a change too.
  Fnv1a64 hash;
  for (const fs::path& file : sceneInputFiles(scene)) {
    hash.update(file.lexically_relative(scene.parent_path()).generic_string());
    hash.update("\0", 1);
    // A missing texture is the loader's to report (or tolerate); here it
    // is one more state of the inputs.
    std::error_code ec;
    hash.update(fs::is_regular_file(file, ec) ? hex64(fnv1a64File(file)) : "missing");
  }
  return hex64(hash.value());
}

RunContentKey runContentKey(const config::RunConfig& config, const std::string& sceneDigest) {
  RunContentKey key;
  Fnv1a64 configHash;
  configHash.update(config::effectiveConfigYaml(config));
  key.config = hex64(configHash.value());
  key.scene = sceneDigest.empty() ? sceneInputsDigest(config.scene_file) : sceneDigest;
  key.version = kVersion;
  const config::EffectiveConfigParts parts = config::effectiveConfigParts(config);
  Fnv1a64 renderHash;
  for (const std::string& part : {parts.render, key.scene, key.version}) {
    renderHash.update(part);
    renderHash.update("\0", 1);
  }
  key.render = hex64(renderHash.value());
  Fnv1a64 senseHash;
  senseHash.update(parts.sensors);
  key.sense = hex64(senseHash.value());
  return key;
}

}  // namespace tofsim::pipeline

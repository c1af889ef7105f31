#pragma once
// Tiny hand-written glTF files for loader tests: a buffer of floats/ints
// embedded as a base64 data URI and the JSON around it.

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace tofsim::test {

inline std::string base64(const std::vector<uint8_t>& bytes) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t v = uint32_t(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= uint32_t(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) v |= bytes[i + 2];
    out += k[v >> 18 & 63];
    out += k[v >> 12 & 63];
    out += i + 1 < bytes.size() ? k[v >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? k[v & 63] : '=';
  }
  return out;
}

template <typename T>
void appendBytes(std::vector<uint8_t>& out, const std::vector<T>& values) {
  const std::size_t at = out.size();
  out.resize(at + values.size() * sizeof(T));
  std::memcpy(out.data() + at, values.data(), values.size() * sizeof(T));
}

inline std::string dataUri(const std::vector<uint8_t>& bytes) {
  return "data:application/octet-stream;base64," + base64(bytes);
}

inline std::filesystem::path writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

/// One triangle (0,0,0) (1,0,0) (0,1,0) in mesh 0 (no normals, no material),
/// placed by the given "nodes" and "scenes" JSON.
inline std::string triangleGltf(const std::string& nodesAndScenes,
                                std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0}) {
  std::vector<uint8_t> bytes;
  appendBytes(bytes, positions);
  const std::string n = std::to_string(positions.size() / 3);
  return R"({"asset": {"version": "2.0"},)" + nodesAndScenes + R"(,
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "buffers": [{"byteLength": )" + std::to_string(bytes.size()) + R"(, "uri": ")" + dataUri(bytes) + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": )" + std::to_string(bytes.size()) + R"(}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" + n + R"(, "type": "VEC3"}]})";
}

}  // namespace tofsim::test

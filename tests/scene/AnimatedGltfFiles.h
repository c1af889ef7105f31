#pragma once
// Generated glTF files with animations for the animation tests: one buffer of
// float accessors (accessor 0: the triangle (0,0,0) (1,0,0) (0,1,0) of mesh 0)
// and the JSON around it.

#include <cstdint>
#include <string>
#include <vector>

#include "GltfTestFiles.h"

namespace tofsim::test {

class AnimatedGltf {
 public:
  AnimatedGltf() { addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3"); }

  /// A float accessor of `type` ("SCALAR", "VEC3", "VEC4"); returns its index.
  int addFloats(const std::vector<float>& values, const std::string& type) {
    const int components = type == "SCALAR" ? 1 : type == "VEC3" ? 3 : 4;
    const std::size_t offset = bytes_.size();
    appendBytes(bytes_, values);
    const int index = static_cast<int>(accessors_.size());
    views_.push_back(R"({"buffer": 0, "byteOffset": )" + std::to_string(offset) +
                     R"(, "byteLength": )" + std::to_string(values.size() * 4) + "}");
    accessors_.push_back(
        R"({"bufferView": )" + std::to_string(index) + R"(, "componentType": 5126, "count": )" +
        std::to_string(values.size() / components) + R"(, "type": ")" + type + R"("})");
    return index;
  }

  /// One sampler (input times, output accessor, interpolation) per channel:
  /// {"sampler": i, "target": {"node": n, "path": p}}.
  void addChannel(int node, const std::string& path, const std::vector<float>& times,
                  const std::vector<float>& values, const std::string& interpolation) {
    const std::string type = path == "rotation" ? "VEC4" : path == "weights" ? "SCALAR" : "VEC3";
    const int input = addFloats(times, "SCALAR");
    const int output = addFloats(values, type);
    addRawChannel(node, path, input, output, interpolation);
  }

  void addRawChannel(int node, const std::string& path, int input, int output,
                     const std::string& interpolation) {
    const std::string index = std::to_string(samplers_.size());
    channels_.push_back(R"({"sampler": )" + index + R"(, "target": {"node": )" +
                        std::to_string(node) + R"(, "path": ")" + path + R"("}})");
    samplers_.push_back(R"({"input": )" + std::to_string(input) + R"(, "output": )" +
                        std::to_string(output) + R"(, "interpolation": ")" + interpolation +
                        R"("})");
  }

  /// The file: `nodes` and `extra` (",\"cameras\": [...]" etc.) JSON, every
  /// node that is nobody's child in the scene given by `roots` ("[0, 1]").
  std::string json(const std::string& nodes, const std::string& roots,
                   const std::string& extra = "") const {
    std::string out = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": )" + roots +
                      R"(}], "nodes": )" + nodes + extra + R"(,
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "buffers": [{"byteLength": )" +
                      std::to_string(bytes_.size()) + R"(, "uri": ")" + dataUri(bytes_) + R"("}],
  "bufferViews": [)" + joined(views_) +
                      R"(],
  "accessors": [)" + joined(accessors_) +
                      "]";
    if (!channels_.empty()) {
      out += R"(, "animations": [{"name": "anim", "channels": [)" + joined(channels_) +
             R"(], "samplers": [)" + joined(samplers_) + "]}]";
    }
    return out + "}";
  }

 private:
  static std::string joined(const std::vector<std::string>& parts) {
    std::string out;
    for (const std::string& p : parts) out += (out.empty() ? "" : ", ") + p;
    return out;
  }

  std::vector<uint8_t> bytes_;
  std::vector<std::string> views_;
  std::vector<std::string> accessors_;
  std::vector<std::string> channels_;
  std::vector<std::string> samplers_;
};

}  // namespace tofsim::test

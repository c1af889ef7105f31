#pragma once
// The subset of a glTF document the loader uses, as plain structs. Only
// TinyGltfImport.cpp sees tinygltf; the rest of the loader reads this.
// Indices are glTF indices (-1 = absent).

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace tofsim::scene::detail {

// glTF componentType values.
inline constexpr int kByte = 5120;
inline constexpr int kUnsignedByte = 5121;
inline constexpr int kShort = 5122;
inline constexpr int kUnsignedShort = 5123;
inline constexpr int kUnsignedInt = 5125;
inline constexpr int kFloat = 5126;

// glTF primitive modes.
inline constexpr int kPoints = 0;
inline constexpr int kTriangles = 4;
inline constexpr int kTriangleStrip = 5;
inline constexpr int kTriangleFan = 6;

struct BufferView {
  int buffer = -1;
  std::size_t byteOffset = 0;
  std::size_t byteLength = 0;
  std::size_t byteStride = 0;  ///< 0 = tightly packed
};

struct Sparse {
  std::size_t count = 0;
  int indicesView = -1;
  std::size_t indicesOffset = 0;
  int indicesComponentType = 0;
  int valuesView = -1;
  std::size_t valuesOffset = 0;
};

struct Accessor {
  int bufferView = -1;  ///< -1: all zeros (before sparse substitution)
  std::size_t byteOffset = 0;
  int componentType = 0;
  int components = 0;  ///< 1 (SCALAR) .. 4 (VEC4), 4/9/16 for matrices
  bool normalized = false;
  std::size_t count = 0;
  std::optional<Sparse> sparse;
};

struct Primitive {
  int mode = kTriangles;
  int position = -1;
  int normal = -1;
  std::vector<int> texcoords;  ///< accessor of TEXCOORD_n at [n]
  int indices = -1;
  int material = -1;
};

struct MeshDesc {
  std::string name;
  std::vector<Primitive> primitives;
};

/// A node's local transform as the file gives it: a matrix, or the TRS
/// properties present (absent ones are identity). Animations replace T, R, S.
struct NodeTrs {
  std::optional<glm::dmat4> matrix;
  std::optional<glm::dvec3> translation;
  std::optional<glm::dquat> rotation;
  std::optional<glm::dvec3> scale;
};

struct Node {
  std::string name;
  int mesh = -1;
  int camera = -1;
  std::vector<int> children;
  NodeTrs trs;
  glm::dmat4 local{1.0};  ///< localMatrix(trs)
};

struct AnimationChannelDesc {
  int sampler = -1;
  int node = -1;     ///< -1: no target node (the channel is ignored)
  std::string path;  ///< "translation", "rotation", "scale", "weights" (or other)
};

struct AnimationSamplerDesc {
  int input = -1;
  int output = -1;
  std::string interpolation;  ///< "LINEAR" when the file leaves it out
};

struct AnimationDesc {
  std::string name;
  std::vector<AnimationChannelDesc> channels;
  std::vector<AnimationSamplerDesc> samplers;
};

struct MaterialDesc {
  std::string name;
  glm::dvec4 baseColorFactor{1.0};
  int baseColorImage = -1;  ///< glTF image index of baseColorTexture's source
  int baseColorTexCoord = 0;
  double metallicFactor = 1.0;      ///< glTF default
  double roughnessFactor = 1.0;     ///< glTF default
  int metallicRoughnessImage = -1;  ///< glTF image index of metallicRoughnessTexture's source
  int metallicRoughnessTexCoord = 0;
  bool metallic = false;
  bool emissive = false;
  bool transmissive = false;
  /// The parts of the material no renderer reads (for tofsim info), in order:
  /// emission, normal and occlusion textures, alpha, then every extension.
  std::vector<std::string> ignored;
  /// The material's `extras`, its scalars by their path ("a.b" for member b
  /// of object a, "a.0" for element 0 of array a; numbers as "%.17g" text,
  /// booleans as true/false): passed on in LoadReport::materialExtras, where
  /// the config layer reads the per-material parameters by name
  /// (scattering_delay).
  std::map<std::string, std::string> extras;
};

/// Decoded pixels as tinygltf delivers them (stb_image): 8 or 16 bits.
struct ImageDesc {
  std::string name;
  int width = 0;
  int height = 0;
  int components = 0;  ///< 1..4
  int bits = 8;        ///< 8 or 16
  std::vector<unsigned char> pixels;
};

struct CameraDesc {
  std::string name;
  bool perspective = true;
  double yfov_rad = 0.0;
  double aspectRatio = 0.0;  ///< 0 when absent
};

struct GltfDocument {
  std::string file;  ///< for error messages
  std::vector<std::vector<unsigned char>> buffers;
  std::vector<std::string> bufferNames;  ///< uri or "buffer[i]"
  std::vector<BufferView> bufferViews;
  std::vector<Accessor> accessors;
  std::vector<MeshDesc> meshes;
  std::vector<Node> nodes;
  std::vector<MaterialDesc> materials;
  std::vector<ImageDesc> images;
  std::vector<CameraDesc> cameras;
  std::vector<AnimationDesc> animations;
  std::size_t skins = 0;              ///< glTF skins (ignored)
  std::size_t morphTargetMeshes = 0;  ///< meshes with morph targets (ignored)
  std::vector<int> rootNodes;         ///< of the default scene
  std::vector<std::string> warnings;
};

}  // namespace tofsim::scene::detail

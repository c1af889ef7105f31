#pragma once
// A scene ready to render: triangle meshes in world space (node transforms
// already applied), diffuse materials and the cameras the file defined.
// Units are metres; the frame is glTF's (right-handed, +Y up).

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace tofsim::scene {

/// An RGB texture in linear radiometric units (sRGB decoded at load time).
/// Row 0 is the top row of the image file; glTF uv (0,0) is its top-left.
struct Texture {
  int32_t width = 0;
  int32_t height = 0;
  std::vector<float> rgb;  ///< width * height * 3 floats
};

/// Lambertian material. albedo = baseColorFactor.rgb x baseColorTexture.rgb.
struct Material {
  std::string name;
  glm::vec3 albedo{0.8f};
  int32_t albedoTexture = -1;  ///< index into Scene::textures, or -1
};

/// One triangle list with one material, in world space.
struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions_world;
  std::vector<glm::vec3> normals_world;  ///< unit length, one per position
  std::vector<glm::vec2> uvs;            ///< empty, or one per position
  std::vector<uint32_t> indices;         ///< 3 per triangle
  int32_t material = 0;                  ///< index into Scene::materials

  std::size_t triangleCount() const { return indices.size() / 3; }
};

/// A perspective camera defined in the scene file.
struct SceneCamera {
  std::string name;
  glm::vec3 position_world{0.0f};
  glm::vec3 forward_world{0.0f, 0.0f, -1.0f};  ///< unit
  glm::vec3 up_world{0.0f, 1.0f, 0.0f};        ///< unit, orthogonal to forward
  float fov_y_deg = 45.0f;
  float aspect = 0.0f;  ///< width / height, 0 when the file does not say
};

struct Bounds {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
};

struct Scene {
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<SceneCamera> cameras;

  std::size_t triangleCount() const;
  /// Axis-aligned box of all referenced vertices, metres; zero box when empty.
  Bounds bounds() const;
};

}  // namespace tofsim::scene

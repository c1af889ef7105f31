#pragma once
// A scene ready to render: triangle meshes in world space (node transforms
// already applied), materials and the cameras the file defined.
// Units are metres; the frame is glTF's (right-handed, +Y up).

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "tofsim/physics/TemporalResponse.h"

namespace tofsim::scene {

/// An RGB texture of linear values: radiometric for base colours (sRGB
/// decoded at load time), as stored for metallic-roughness (glTF: linear).
/// Row 0 is the top row of the image file; glTF uv (0,0) is its top-left.
struct Texture {
  int32_t width = 0;
  int32_t height = 0;
  std::vector<float> rgb;  ///< width * height * 3 floats
};

/// A glTF metallic-roughness material. albedo = baseColorFactor.rgb x
/// baseColorTexture.rgb; metallic = metallicFactor x texture.b, roughness =
/// roughnessFactor x texture.g. Renderers use albedo alone (Lambertian) unless
/// render.materials is `gltf` (shaders/gltf_brdf.glsl). The defaults are
/// those of a code-built diffuse surface (glTF's own are metallic 1,
/// roughness 1; the loader fills in the file's).
struct Material {
  std::string name;
  glm::vec3 albedo{0.8f};
  int32_t albedoTexture = -1;             ///< index into Scene::textures, or -1
  float metallic = 0.0f;                  ///< in [0, 1]
  float roughness = 1.0f;                 ///< perceptual roughness in [0, 1]; alpha = roughness^2
  int32_t metallicRoughnessTexture = -1;  ///< index into Scene::textures (B metal, G rough), or -1
  /// Its temporal response (issue 41's `scattering_delay`: the config's
  /// `materials:` entry, else the glTF material's extras); none: instant.
  std::optional<physics::ResponseKernel> scatteringDelay;
};

/// One triangle list with one material, in world space.
struct Mesh {
  std::string name;
  std::string node;  ///< the glTF node that placed it (its name; empty if unnamed)
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

/// The closed mesh a participating medium fills (`media:`, issue 42): taken
/// out of the surfaces by scene::takeRegionMesh, an interface that no
/// renderer draws, reflects at or is shadowed by (index matched: nothing
/// reflects or refracts there). World space, 3 vertices per triangle, wound
/// so that each triangle's normal (b - a) x (c - a) points out.
struct RegionMesh {
  std::string name;  ///< the `media:` entry's `region`: a glTF mesh or node name
  std::vector<glm::vec3> triangles_world;
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
  /// Node and mesh names of primitives dropped because none of their
  /// triangles has area: a name asked for later (a relay wall) is then
  /// "has no area", not "missing".
  std::vector<std::string> arealess;
  /// The media's regions (RegionMeshes.h), in `media:` order; empty without.
  std::vector<RegionMesh> regions;

  std::size_t triangleCount() const;
  /// Axis-aligned box of all referenced vertices, metres; zero box when empty.
  Bounds bounds() const;
};

}  // namespace tofsim::scene

#pragma once
// glTF 2.0 (.gltf with external or embedded buffers, and .glb) into a Scene.
//
// What is used: triangle primitives (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN;
// strips and fans become lists), POSITION, NORMAL, TEXCOORD_n, indices, the
// node hierarchy of the default scene (world transforms baked into positions
// and normals), perspective cameras, baseColorFactor.rgb x baseColorTexture
// as albedo, and metallicFactor, roughnessFactor, metallicRoughnessTexture
// (shaded with render.materials: gltf). Accessors may be strided, normalized integers
// (KHR_mesh_quantization) or sparse. Primitives without NORMAL get flat
// normals (the glTF rule), one face normal per triangle.
//
// What is not used (counted in LoadReport so callers can warn): points and
// lines, orthographic cameras, zero-area triangles, and the emissive and
// transmissive parts of materials (lights are point/spot lights configured
// separately): those materials render as their base colour. Per material,
// LoadReport::ignoredMaterialParts names what is not read: emission, normal
// and occlusion textures, alphaMode, and every material extension
// (KHR_materials_ior and KHR_materials_specular included: the dielectric F0
// stays the pinned 0.04). Metallic
// materials are counted too: they render as diffuse base colour under the
// default render.materials: lambertian. Morph targets and skins are ignored
// (counted in LoadReport; a skinned mesh is placed rigidly by its node).
// Animations: loadGltf gives the nodes' own transforms (the file's rest
// pose) and only counts them; AnimatedScene (AnimatedScene.h) reads, checks
// and plays their translation, rotation and scale channels.
//
// Units: glTF metres; frame: glTF's right-handed, +Y up.

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "tofsim/scene/Scene.h"

namespace tofsim::scene {

/// What the loader skipped or changed, for the caller to report.
struct LoadReport {
  std::size_t skippedPrimitives = 0;      ///< POINTS, LINES, LINE_LOOP, LINE_STRIP
  std::size_t degenerateTriangles = 0;    ///< zero-area triangles dropped
  std::size_t flatNormalPrimitives = 0;   ///< primitives without NORMAL (flat normals made)
  std::size_t metallicMaterials = 0;      ///< metallicFactor > 0 or a metallic texture
  std::size_t emissiveMaterials = 0;      ///< emissiveFactor != 0 or an emissive texture
  std::size_t transmissiveMaterials = 0;  ///< KHR_materials_transmission
  std::size_t orthographicCameras = 0;    ///< skipped
  std::size_t animations = 0;             ///< glTF animations (played by AnimatedScene only)
  std::size_t skins = 0;                  ///< glTF skins (ignored: meshes placed rigidly)
  std::size_t morphTargetMeshes = 0;      ///< meshes with morph targets (ignored)
  /// Per material of the file (Scene::materials order; the loader's default
  /// material, added after them, has none): the parts no renderer reads, e.g.
  /// "emission", "normalTexture", "KHR_materials_ior (dielectric F0 stays 0.04)".
  std::vector<std::vector<std::string>> ignoredMaterialParts;
  /// Per material of the file (Scene::materials order, the default material
  /// none): its glTF `extras`, the scalars by path ("a.b" for member b of
  /// object a, "a.0" for element 0 of array a; numbers as "%.17g" text), for
  /// the config layer to read its per-material parameters from
  /// (config::materialDelays: scattering_delay).
  std::vector<std::map<std::string, std::string>> materialExtras;
  std::vector<std::string> warnings;  ///< tinygltf's warnings and the loader's own
};

/// Loads a .gltf or .glb. Throws tofsim::InputError naming the file (and the
/// accessor, buffer or extension at fault) for missing or malformed input.
Scene loadGltf(const std::filesystem::path& path, LoadReport* report = nullptr);

}  // namespace tofsim::scene

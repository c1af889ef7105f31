#pragma once
// glTF materials and their base-colour and metallic-roughness images to
// Materials and linear Textures. Metallic-roughness is shaded only with
// render.materials: gltf; emissive and transmissive properties are never used
// for shading; all three are counted in the LoadReport.

#include "GltfDocument.h"
#include "tofsim/scene/GltfLoader.h"

namespace tofsim::scene::detail {

/// Fills scene.materials (one per glTF material, same index) and
/// scene.textures (one per image and encoding used: sRGB base colour, linear
/// metallic-roughness).
void convertMaterials(const GltfDocument& doc, Scene& scene, LoadReport& report);

/// The material of primitives that name none: "default", albedo 0.8.
Material defaultMaterial();

/// sRGB-encoded value in [0,1] to linear.
float srgbToLinear(float encoded);

}  // namespace tofsim::scene::detail

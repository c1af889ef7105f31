#pragma once
// glTF materials and base-colour images to Lambertian Materials and linear
// Textures. Metallic, emissive and transmissive properties are not used for
// shading (the renderer is diffuse); they are counted in the LoadReport.

#include "GltfDocument.h"
#include "tofsim/scene/GltfLoader.h"

namespace tofsim::scene::detail {

/// Fills scene.materials (one per glTF material, same index) and
/// scene.textures (one per base-colour image used).
void convertMaterials(const GltfDocument& doc, Scene& scene, LoadReport& report);

/// The material of primitives that name none: "default", albedo 0.8.
Material defaultMaterial();

/// sRGB-encoded value in [0,1] to linear.
float srgbToLinear(float encoded);

}  // namespace tofsim::scene::detail

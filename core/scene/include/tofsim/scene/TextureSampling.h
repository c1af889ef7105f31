#pragma once
// Albedo and metallic-roughness lookup shared by renderers that shade on the CPU. Matches the GL
// renderer's sampler state (GL_LINEAR, GL_REPEAT, texel centres at
// (i + 0.5) / size) so a CPU renderer sees the same values the G-buffer does.

#include <glm/glm.hpp>

#include "tofsim/scene/Scene.h"

namespace tofsim::scene {

/// Bilinear, wrapping lookup. uv (0, 0) is the top-left of the image (glTF);
/// the texture must be non-empty.
glm::vec3 sampleBilinear(const Texture& texture, const glm::vec2& uv);

/// albedo factor x texture(uv) when the material has a texture, else the factor.
glm::vec3 materialAlbedo(const Scene& scene, int32_t material, const glm::vec2& uv);

/// (metallic, roughness): the factors x the metallic-roughness texture's
/// (B, G) at uv when the material has one, else the factors.
glm::vec2 materialMetallicRoughness(const Scene& scene, int32_t material, const glm::vec2& uv);

}  // namespace tofsim::scene

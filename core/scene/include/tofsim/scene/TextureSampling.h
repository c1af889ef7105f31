#pragma once
// Base-colour and metallic-roughness texture lookup shared by renderers that shade on the CPU. Matches the GL
// renderer's sampler state (GL_LINEAR, GL_REPEAT, texel centres at
// (i + 0.5) / size) so a CPU renderer sees the same values the G-buffer does.

#include <glm/glm.hpp>

#include "tofsim/scene/Scene.h"

namespace tofsim::scene {

/// Bilinear, wrapping lookup. uv (0, 0) is the top-left of the image (glTF);
/// the texture must be non-empty.
glm::vec3 sampleBilinear(const Texture& texture, const glm::vec2& uv);

/// What the material's base-colour texture gives at uv (rgb), 1 where it
/// has none: its albedo factor's multiplier (physics::texturedVertex).
glm::vec3 baseColorTexel(const Scene& scene, int32_t material, const glm::vec2& uv);

/// What the material's metallic-roughness texture gives at uv: its (B, G),
/// 1 where it has none; the (metallic, roughness) factors' multipliers.
glm::vec2 metallicRoughnessTexel(const Scene& scene, int32_t material, const glm::vec2& uv);

}  // namespace tofsim::scene

#include "GpuScene.h"

#include "GpuContract.h"
#include "tofsim/gl/Check.h"
#include "tofsim/util/Error.h"

namespace tofsim::render {

namespace {
struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv;
};
}  // namespace

GpuScene::GpuScene(const scene::Scene& scene) : scene_(scene) {
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;
  for (const scene::Mesh& mesh : scene.meshes) {
    if (mesh.indices.empty()) continue;
    DrawRange range;
    range.indexCount = static_cast<GLsizei>(mesh.indices.size());
    range.indexOffsetBytes = indices.size() * sizeof(uint32_t);
    range.baseVertex = static_cast<GLint>(vertices.size());
    range.material = mesh.material;
    for (std::size_t i = 0; i < mesh.positions_world.size(); ++i) {
      vertices.push_back({mesh.positions_world[i], mesh.normals_world[i],
                          mesh.uvs.empty() ? glm::vec2(0.0f) : mesh.uvs[i]});
    }
    indices.insert(indices.end(), mesh.indices.begin(), mesh.indices.end());
    ranges_.push_back(range);
  }
  if (indices.empty()) throw InputError("the scene has no triangles to render");
  vertices_ = gl::Buffer(vertices.size() * sizeof(Vertex), vertices.data(), 0);
  indices_ = gl::Buffer(indices.size() * sizeof(uint32_t), indices.data(), 0);
  bytes_ = vertices_.size() + indices_.size();

  vertexArray_.setVertexBuffer(vertices_, sizeof(Vertex));
  vertexArray_.setElementBuffer(indices_);
  vertexArray_.setFloatAttribute(gpu::kPositionAttribute, 3, offsetof(Vertex, position));
  vertexArray_.setFloatAttribute(gpu::kNormalAttribute, 3, offsetof(Vertex, normal));
  vertexArray_.setFloatAttribute(gpu::kUvAttribute, 2, offsetof(Vertex, uv));
  for (const scene::Texture& texture : scene.textures) {
    gl::Texture t = gl::Texture::create2D(GL_RGB32F, texture.width, texture.height);
    t.upload2D(GL_RGB, GL_FLOAT, texture.rgb.data());
    t.setFilter(GL_LINEAR, GL_LINEAR);
    t.setWrap(GL_REPEAT);
    bytes_ += texture.rgb.size() * sizeof(float);
    textures_.push_back(std::move(t));
  }
  TOFSIM_GL_CHECK("GpuScene upload");
}

void GpuScene::draw(const gl::Program& program, Materials materials) const {
  vertexArray_.bind();
  for (const DrawRange& range : ranges_) {
    if (materials != Materials::Skip) {
      setMaterial(program, range.material, materials == Materials::SetGltf);
    }
    glDrawElementsBaseVertex(GL_TRIANGLES, range.indexCount, GL_UNSIGNED_INT,
                             reinterpret_cast<const void*>(range.indexOffsetBytes),
                             range.baseVertex);
  }
  TOFSIM_GL_CHECK("GpuScene::draw");
}

void GpuScene::setMaterial(const gl::Program& program, int32_t index, bool gltf) const {
  const scene::Material& material = scene_.materials.at(static_cast<std::size_t>(index));
  program.set("uMaterial", index);
  const bool textured = material.albedoTexture >= 0;
  program.set("uHasAlbedoTexture", textured ? 1 : 0);
  if (textured) {
    textures_.at(static_cast<std::size_t>(material.albedoTexture)).bindUnit(gpu::kAlbedoTexture);
  }
  if (!gltf) return;
  const bool mrTextured = material.metallicRoughnessTexture >= 0;
  program.set("uHasMetallicRoughnessTexture", mrTextured ? 1 : 0);
  if (mrTextured) {
    textures_.at(static_cast<std::size_t>(material.metallicRoughnessTexture))
        .bindUnit(gpu::kMetallicRoughnessTexture);
  }
}

}  // namespace tofsim::render

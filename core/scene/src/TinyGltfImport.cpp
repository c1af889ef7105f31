#include "TinyGltfImport.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <utility>

#include "NodeTransforms.h"
#include "tofsim/util/Error.h"

namespace tofsim::scene::detail {

namespace {

std::string trimmed(std::string s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  return s;
}

NodeTrs trsOf(const tinygltf::Node& n) {
  NodeTrs trs;
  if (n.matrix.size() == 16) {
    trs.matrix = glm::make_mat4(n.matrix.data());
    return trs;
  }
  if (n.translation.size() == 3) {
    trs.translation = glm::dvec3(n.translation[0], n.translation[1], n.translation[2]);
  }
  if (n.rotation.size() == 4) {
    // glTF stores (x, y, z, w); glm's constructor takes (w, x, y, z).
    trs.rotation = glm::dquat(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);
  }
  if (n.scale.size() == 3) trs.scale = glm::dvec3(n.scale[0], n.scale[1], n.scale[2]);
  return trs;
}

AnimationDesc convert(const tinygltf::Animation& a) {
  AnimationDesc out;
  out.name = a.name;
  for (const tinygltf::AnimationChannel& c : a.channels) {
    out.channels.push_back({c.sampler, c.target_node, c.target_path});
  }
  for (const tinygltf::AnimationSampler& s : a.samplers) {
    out.samplers.push_back({s.input, s.output, s.interpolation});
  }
  return out;
}

Accessor convert(const tinygltf::Accessor& a) {
  Accessor out;
  out.bufferView = a.bufferView;
  out.byteOffset = a.byteOffset;
  out.componentType = a.componentType;
  out.components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
  out.normalized = a.normalized;
  out.count = a.count;
  if (a.sparse.isSparse) {
    out.sparse = Sparse{static_cast<std::size_t>(std::max(a.sparse.count, 0)),
                        a.sparse.indices.bufferView,
                        static_cast<std::size_t>(std::max(a.sparse.indices.byteOffset, 0)),
                        a.sparse.indices.componentType,
                        a.sparse.values.bufferView,
                        static_cast<std::size_t>(std::max(a.sparse.values.byteOffset, 0))};
  }
  return out;
}

Primitive convert(const tinygltf::Primitive& p) {
  Primitive out;
  out.mode = p.mode < 0 ? kTriangles : p.mode;  // tinygltf uses -1 for "absent"
  out.indices = p.indices;
  out.material = p.material;
  for (const auto& [name, accessor] : p.attributes) {
    if (name == "POSITION") out.position = accessor;
    if (name == "NORMAL") out.normal = accessor;
    // TEXCOORD_<n>; anything else after the underscore is not a texture
    // coordinate set (std::stoul would throw on it: a crash found by fuzzing).
    const std::string suffix = name.rfind("TEXCOORD_", 0) == 0 ? name.substr(9) : "";
    if (!suffix.empty() && suffix.size() <= 2 &&
        std::all_of(suffix.begin(), suffix.end(),
                    [](unsigned char c) { return std::isdigit(c); })) {
      const std::size_t set = std::stoul(suffix);
      if (set < 16) {
        if (out.texcoords.size() <= set) out.texcoords.resize(set + 1, -1);
        out.texcoords[set] = accessor;
      }
    }
  }
  return out;
}

// What of a material no renderer reads: tofsim lights are point/spot lights,
// surfaces are opaque and two-sided, shading normals are the vertex normals,
// and the BRDF's dielectric F0 is the pinned 0.04 (shaders/gltf_brdf.glsl), so
// KHR_materials_ior and KHR_materials_specular do not change it.
// The scalars of `value` (an extras object) into `out` by their path below
// `prefix`, an array's elements by their index ("reemission.0.2": a matrix's
// row 0, column 2); nulls are left out.
void flattenExtras(const tinygltf::Value& value, const std::string& prefix,
                   std::map<std::string, std::string>& out) {
  if (value.IsObject()) {
    for (const std::string& key : value.Keys()) {
      flattenExtras(value.Get(key), prefix.empty() ? key : prefix + "." + key, out);
    }
  } else if (value.IsArray()) {
    for (std::size_t i = 0; i < value.ArrayLen(); ++i) {
      const std::string index = std::to_string(i);
      flattenExtras(value.Get(static_cast<int>(i)), prefix.empty() ? index : prefix + "." + index, out);
    }
  } else if (value.IsNumber()) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value.GetNumberAsDouble());
    out[prefix] = text;
  } else if (value.IsString()) {
    out[prefix] = value.Get<std::string>();
  } else if (value.IsBool()) {
    out[prefix] = value.Get<bool>() ? "true" : "false";
  }
}

std::vector<std::string> ignoredParts(const tinygltf::Material& m, bool emissive) {
  std::vector<std::string> out;
  if (emissive) out.push_back("emission");
  if (m.normalTexture.index >= 0) out.push_back("normalTexture");
  if (m.occlusionTexture.index >= 0) out.push_back("occlusionTexture");
  if (!m.alphaMode.empty() && m.alphaMode != "OPAQUE") {
    out.push_back("alphaMode " + m.alphaMode + " (rendered opaque)");
  }
  for (const auto& [name, value] : m.extensions) {
    (void)value;
    if (name == "KHR_materials_ior" || name == "KHR_materials_specular") {
      out.push_back(name + " (dielectric F0 stays 0.04)");
    } else if (name == "KHR_materials_transmission") {
      out.push_back(name + " (rendered opaque)");
    } else {
      out.push_back(name);
    }
  }
  return out;
}

MaterialDesc convert(const tinygltf::Model& model, const tinygltf::Material& m) {
  MaterialDesc out;
  out.name = m.name;
  const auto& pbr = m.pbrMetallicRoughness;
  if (pbr.baseColorFactor.size() == 4) {
    out.baseColorFactor = {pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2],
                           pbr.baseColorFactor[3]};
  }
  const int tex = pbr.baseColorTexture.index;
  if (tex >= 0 && tex < static_cast<int>(model.textures.size())) {
    out.baseColorImage = model.textures[tex].source;
    out.baseColorTexCoord = pbr.baseColorTexture.texCoord;
  }
  out.metallicFactor = pbr.metallicFactor;
  out.roughnessFactor = pbr.roughnessFactor;
  const int mr = pbr.metallicRoughnessTexture.index;
  if (mr >= 0 && mr < static_cast<int>(model.textures.size())) {
    out.metallicRoughnessImage = model.textures[mr].source;
    out.metallicRoughnessTexCoord = pbr.metallicRoughnessTexture.texCoord;
  }
  // The metallic texture is multiplied by the factor, so the factor decides.
  out.metallic = pbr.metallicFactor > 0.0;
  out.emissive =
      m.emissiveTexture.index >= 0 || std::any_of(m.emissiveFactor.begin(), m.emissiveFactor.end(),
                                                  [](double v) { return v != 0.0; });
  out.transmissive = m.extensions.count("KHR_materials_transmission") > 0;
  out.ignored = ignoredParts(m, out.emissive);
  if (m.extras.IsObject()) flattenExtras(m.extras, "", out.extras);
  return out;
}

}  // namespace

GltfDocument importGltf(const std::filesystem::path& path) {
  const std::string file = path.string();
  tinygltf::Model model;
  tinygltf::TinyGLTF parser;
  std::string err, warn;
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  const bool ok = ext == ".glb" ? parser.LoadBinaryFromFile(&model, &err, &warn, file)
                                : parser.LoadASCIIFromFile(&model, &err, &warn, file);
  if (!ok) throw InputError(FileLoc{file}, "", "cannot load glTF: " + trimmed(err));

  GltfDocument doc;
  doc.file = file;
  if (!trimmed(warn).empty()) doc.warnings.push_back(trimmed(warn));
  for (std::size_t i = 0; i < model.buffers.size(); ++i) {
    tinygltf::Buffer& b = model.buffers[i];
    doc.buffers.push_back(std::move(b.data));
    const bool dataUri = b.uri.rfind("data:", 0) == 0;
    doc.bufferNames.push_back(b.uri.empty() || dataUri
                                  ? "buffer[" + std::to_string(i) + "]"
                                  : "buffer[" + std::to_string(i) + "] '" + b.uri + "'");
  }
  for (const tinygltf::BufferView& v : model.bufferViews) {
    doc.bufferViews.push_back({v.buffer, v.byteOffset, v.byteLength, v.byteStride});
  }
  for (const tinygltf::Accessor& a : model.accessors) doc.accessors.push_back(convert(a));
  for (const tinygltf::Mesh& m : model.meshes) {
    MeshDesc mesh{m.name, {}};
    bool morphed = false;
    for (const tinygltf::Primitive& p : m.primitives) {
      mesh.primitives.push_back(convert(p));
      morphed = morphed || !p.targets.empty();
    }
    doc.morphTargetMeshes += morphed ? 1 : 0;
    doc.meshes.push_back(std::move(mesh));
  }
  for (const tinygltf::Node& n : model.nodes) {
    const NodeTrs trs = trsOf(n);
    doc.nodes.push_back({n.name, n.mesh, n.camera, n.children, trs, localMatrix(trs)});
  }
  for (const tinygltf::Animation& a : model.animations) doc.animations.push_back(convert(a));
  doc.skins = model.skins.size();
  for (const tinygltf::Material& m : model.materials) doc.materials.push_back(convert(model, m));
  for (tinygltf::Image& im : model.images) {
    doc.images.push_back({im.name.empty() ? im.uri : im.name, im.width, im.height, im.component,
                          im.bits, std::move(im.image)});
  }
  for (const tinygltf::Camera& c : model.cameras) {
    const bool persp = c.type == "perspective";
    doc.cameras.push_back(
        {c.name, persp, persp ? c.perspective.yfov : 0.0, persp ? c.perspective.aspectRatio : 0.0});
  }

  if (!model.scenes.empty()) {
    const int s = model.defaultScene >= 0 && model.defaultScene < int(model.scenes.size())
                      ? model.defaultScene
                      : 0;
    doc.rootNodes = model.scenes[s].nodes;
  } else {
    // No scene: every node that is nobody's child is a root.
    std::vector<bool> isChild(model.nodes.size(), false);
    for (const tinygltf::Node& n : model.nodes) {
      for (int c : n.children) {
        if (c >= 0 && c < int(isChild.size())) isChild[c] = true;
      }
    }
    for (std::size_t i = 0; i < isChild.size(); ++i) {
      if (!isChild[i]) doc.rootNodes.push_back(static_cast<int>(i));
    }
  }
  return doc;
}

}  // namespace tofsim::scene::detail

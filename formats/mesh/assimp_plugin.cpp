// The assimp plugin module (assimp_plugin_api.h): a scene in any format assimp imports,
// flattened into an AssimpScene -- every mesh of every node, the node's transform and its
// parents' applied, polygons triangulated (docs/fconv.md, "Scene formats through
// assimp"). Only this file sees assimp's headers; only this module maps libassimp.

#include <cstdio>
#include <cstring>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include <assimp/DefaultIOSystem.h>
#include <assimp/commonMetaData.h>
#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "formats/mesh/assimp_plugin_api.h"
#include "formats/mesh/assimp_scene.hpp"

namespace {

using fest::formats::AssimpScene;

void add_count(std::vector<std::pair<std::string, std::size_t>>& list, const std::string& what, std::size_t n) {
  if (n == 0) return;
  for (auto& item : list)
    if (item.first == what) {
      item.second += n;
      return;
    }
  list.emplace_back(what, n);
}

bool is_triangle_mesh(const aiMesh& m) { return (m.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) != 0; }

// Which per-vertex attributes every triangle mesh of the scene has: an attribute only some
// meshes have cannot be one per vertex of the flattened mesh, and is counted as lost.
struct Attributes {
  bool normals = true, colors = true, texcoords = true;
};

Attributes common_attributes(const aiScene& s, AssimpScene& out) {
  Attributes a;
  std::size_t meshes = 0, with_normals = 0, with_colors = 0, with_uv = 0;
  for (unsigned i = 0; i < s.mNumMeshes; ++i) {
    const aiMesh& m = *s.mMeshes[i];
    if (!is_triangle_mesh(m)) continue;
    ++meshes;
    with_normals += m.HasNormals();
    with_colors += m.HasVertexColors(0);
    with_uv += m.HasTextureCoords(0) && m.mNumUVComponents[0] == 2;
  }
  a.normals = meshes > 0 && with_normals == meshes;
  a.colors = meshes > 0 && with_colors == meshes;
  a.texcoords = meshes > 0 && with_uv == meshes;
  if (!a.normals) add_count(out.lost, "vertex normals of meshes beside meshes without them", with_normals);
  if (!a.colors) add_count(out.lost, "vertex colours of meshes beside meshes without them", with_colors);
  if (!a.texcoords) add_count(out.lost, "texture coordinates of meshes beside meshes without them", with_uv);
  return a;
}

// One instance of mesh `m` under the accumulated transform `t`.
void append_mesh(const aiMesh& m, const aiMatrix4x4& t, const Attributes& keep, AssimpScene& out) {
  const std::size_t first = out.positions.size() / 3;
  aiMatrix3x3 normal_matrix(t);
  normal_matrix.Inverse().Transpose();
  // A mirroring transform turns faces inside out: their corner order is reversed back.
  const bool mirrored = aiMatrix3x3(t).Determinant() < 0;
  for (unsigned v = 0; v < m.mNumVertices; ++v) {
    const aiVector3D p = t * m.mVertices[v];
    out.positions.insert(out.positions.end(), {double(p.x), double(p.y), double(p.z)});
    if (keep.normals) {
      aiVector3D n = normal_matrix * m.mNormals[v];
      if (n.Length() > 0) n.Normalize();
      out.normals.insert(out.normals.end(), {double(n.x), double(n.y), double(n.z)});
    }
    if (keep.colors) {
      const aiColor4D& c = m.mColors[0][v];
      out.colors.insert(out.colors.end(), {c.r, c.g, c.b, c.a});
    }
    if (keep.texcoords) out.texcoords.insert(out.texcoords.end(), {m.mTextureCoords[0][v].x, m.mTextureCoords[0][v].y});
  }
  for (unsigned f = 0; f < m.mNumFaces; ++f) {
    const aiFace& face = m.mFaces[f];
    if (face.mNumIndices != 3) continue;  // sorted out before: points and lines are counted
    const std::uint32_t a = first + face.mIndices[0], b = first + face.mIndices[1], c = first + face.mIndices[2];
    if (mirrored) out.triangles.insert(out.triangles.end(), {a, c, b});
    else out.triangles.insert(out.triangles.end(), {a, b, c});
  }
}

void walk(const aiScene& s, const aiNode& node, const aiMatrix4x4& parent, const Attributes& keep, AssimpScene& out) {
  const aiMatrix4x4 t = parent * node.mTransformation;
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    const aiMesh& m = *s.mMeshes[node.mMeshes[i]];
    if (is_triangle_mesh(m)) {
      append_mesh(m, t, keep, out);
    } else {
      // Points and lines (SortByPType put them in meshes of their own).
      if (m.mPrimitiveTypes & aiPrimitiveType_POINT) add_count(out.lost, "point primitives", m.mNumFaces);
      if (m.mPrimitiveTypes & aiPrimitiveType_LINE) add_count(out.lost, "line primitives", m.mNumFaces);
    }
  }
  for (unsigned i = 0; i < node.mNumChildren; ++i) walk(s, *node.mChildren[i], t, keep, out);
}

void count_losses(const aiScene& s, AssimpScene& out) {
  std::size_t bones = 0, morphs = 0, extra_uv = 0, extra_colors = 0, wide_uv = 0;
  for (unsigned i = 0; i < s.mNumMeshes; ++i) {
    const aiMesh& m = *s.mMeshes[i];
    bones += m.mNumBones;
    morphs += m.mNumAnimMeshes;
    extra_uv += m.GetNumUVChannels() > 1 ? m.GetNumUVChannels() - 1 : 0;
    extra_colors += m.GetNumColorChannels() > 1 ? m.GetNumColorChannels() - 1 : 0;
    wide_uv += m.HasTextureCoords(0) && m.mNumUVComponents[0] != 2;
  }
  add_count(out.lost, "bones", bones);
  add_count(out.lost, "morph targets", morphs);
  add_count(out.lost, "animations", s.mNumAnimations);
  add_count(out.lost, "texture coordinate sets beyond the first", extra_uv);
  add_count(out.lost, "colour sets beyond the first", extra_colors);
  add_count(out.lost, "texture coordinate sets of 1 or 3 components", wide_uv);
  // assimp adds a default material to scenes that have none: not the file's. Its glTF 2
  // importer appends one to every scene, after the file's (unnamed, so it is told by its
  // place: the importer marks its scenes with the asset's version, "2.0").
  std::size_t materials = 0;
  for (unsigned i = 0; i < s.mNumMaterials; ++i)
    if (s.mMaterials[i]->GetName() != aiString(AI_DEFAULT_MATERIAL_NAME)) ++materials;
  aiString version;
  if (materials > 0 && s.mMetaData != nullptr && s.mMetaData->Get(AI_METADATA_SOURCE_FORMAT_VERSION, version) &&
      version.C_Str()[0] == '2' && (out.format == "gltf" || out.format == "glb"))
    --materials;
  add_count(out.not_geometry, "materials", materials);
  add_count(out.not_geometry, "embedded textures", s.mNumTextures);
  add_count(out.not_geometry, "cameras", s.mNumCameras);
  add_count(out.not_geometry, "lights", s.mNumLights);
}

// "%XX" sequences replaced by their bytes (RFC 3986); anything else kept as it is.
std::string percent_decoded(const std::string& text) {
  auto hex = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 2 < text.size() && hex(text[i + 1]) >= 0 && hex(text[i + 2]) >= 0) {
      out += static_cast<char>(hex(text[i + 1]) * 16 + hex(text[i + 2]));
      i += 2;
    } else {
      out += text[i];
    }
  }
  return out;
}

// The files a scene refers to (a glTF's external buffers). assimp reads the scene itself
// from memory (ReadFileFromMemory) and asks this IO system for every other file, by the
// name the scene writes (relative to the scene: glTF URIs are), so it is looked for in
// the scene file's folder -- never in the working directory -- and, for a scene without a
// file (standard input), nowhere: the first name asked for is kept for the message.
class FilesBesideScene : public Assimp::DefaultIOSystem {
 public:
  explicit FilesBesideScene(const char* folder) {
    if (folder != nullptr) folder_ = folder;
  }
  bool Exists(const char* name) const override {
    return folder_ && DefaultIOSystem::Exists(resolve(name).c_str());
  }
  Assimp::IOStream* Open(const char* name, const char* mode) override {
    Assimp::IOStream* stream = nullptr;
    if (folder_ && std::strchr(mode, 'w') == nullptr && std::strchr(mode, 'a') == nullptr) {
      stream = DefaultIOSystem::Open(resolve(name).c_str(), mode);
      // glTF URIs are percent-encoded ("my%20mesh.bin" names "my mesh.bin"); assimp
      // 5.2 passes them on undecoded.
      const std::string decoded = percent_decoded(name);
      if (stream == nullptr && decoded != name) stream = DefaultIOSystem::Open(resolve(decoded.c_str()).c_str(), mode);
    }
    if (stream == nullptr) not_opened_.push_back(name);
    return stream;
  }
  bool has_folder() const { return folder_.has_value(); }
  // The file the importer's error names among those it asked for and did not get (an
  // importer may probe optional files); "" when the error is about something else.
  std::string missing(const std::string& error) const {
    for (const std::string& name : not_opened_)
      if (error.find(name) != std::string::npos) return folder_ ? resolve(name.c_str()) : name;
    return "";
  }

 private:
  std::string resolve(const char* name) const {
    if (name[0] == '/') return name;
    return *folder_ + "/" + name;
  }
  std::optional<std::string> folder_;
  std::vector<std::string> not_opened_;
};

int read_scene(const char* bytes, size_t size, const char* hint, const char* folder, void* scene, char* message,
               size_t message_size) {
  auto fail = [&](const std::string& what, int status = 3) {
    std::snprintf(message, message_size, "%s", what.c_str());
    return status;
  };
  try {
    AssimpScene& out = *static_cast<AssimpScene*>(scene);
    Assimp::Importer importer;
    auto* files = new FilesBesideScene(folder);  // the importer owns and deletes it
    importer.SetIOHandler(files);
    // Triangulate polygons, put points and lines into meshes of their own, and share
    // vertices that agree in every attribute (formats that store one vertex per corner,
    // 3DS and FBX, would otherwise arrive as a triangle soup).
    const aiScene* s = importer.ReadFileFromMemory(
        bytes, size, aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_JoinIdenticalVertices, hint);
    if (s == nullptr) {
      const std::string error = importer.GetErrorString();
      const std::string missing = files->missing(error);
      if (missing.empty()) return fail(error);
      if (!files->has_folder())
        return fail("the scene refers to the file \"" + missing +
                    "\", which cannot be found for a scene read from standard input (give the scene's path, or "
                    "embed the file: GLB or a data: URI)");
      return fail("cannot read \"" + missing + "\", which the scene refers to", 4);
    }
    if (s->mRootNode == nullptr || (s->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
      return fail("the scene is incomplete (no node hierarchy or no meshes)");
    out.format = hint;
    const Attributes keep = common_attributes(*s, out);
    walk(*s, *s->mRootNode, aiMatrix4x4(), keep, out);
    count_losses(*s, out);
    return 0;
  } catch (const std::exception& e) {
    return fail(e.what());
  }
}

}  // namespace

extern "C" __attribute__((visibility("default"))) const FestAssimpPluginTable* fest_assimp_plugin_table(void) {
  static const FestAssimpPluginTable table{FEST_ASSIMP_PLUGIN_ABI, sizeof(AssimpScene), read_scene};
  return &table;
}

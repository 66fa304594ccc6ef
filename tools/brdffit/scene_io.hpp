#pragma once
// brdffit's files <-> lib types: meshes (through formats/), cam.json, light.json, the rig
// JSON of fest-capture(5) (RIG), brdf.json and the materials file, HDR images and masks.

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "brdffit/lumitexel_builder.hpp"
#include "reflectance/view_json.hpp"
#include "brdffit/texture_atlas.hpp"
#include "reflectance/camera.hpp"
#include "reflectance/environment.hpp"
#include "reflectance/lafortune.hpp"
#include "reflectance/render.hpp"
#include "reflectance/triangle_mesh.hpp"

namespace fest::brdffit_tool {

// A mesh as brdffit uses it: polygons fanned into triangles, vertex normals from the file
// or angle-weighted ones. Throws bad_input for a mesh without faces.
struct LoadedMesh {
  reflectance::TriangleMesh mesh;
  std::string sha256;  // of the triangle geometry (see mesh_sha256)
  bool had_normals = false;
};
LoadedMesh load_mesh(const std::string& path);

// SHA-256 (hex) of the vertex positions (f64 little-endian x, y, z each) followed by the
// triangles (u32 little-endian indices): the same for every file format of one mesh.
std::string mesh_sha256(const reflectance::TriangleMesh& mesh);

// The refined normals of `brdffit normals` (normals.ply: one point per lumitexel, in the
// .ltx order); throws bad_input unless there are `lumitexels` points with usable normals.
std::vector<Eigen::Vector3d> load_refined_normals(const std::string& path, std::size_t lumitexels);

// The mesh of a texture atlas as PLY: three vertices per triangle (the atlas cuts the
// surface into charts) with normals and texture coordinates s, t (t up: s = x / width,
// t = 1 - y / height, the convention of PLY/OBJ viewers).
std::string encode_atlas_ply(const reflectance::TriangleMesh& mesh, const brdffit::TextureAtlas& atlas);

// Writes a PLY with vertex normals.
std::string encode_mesh_ply(const reflectance::TriangleMesh& mesh);

nlohmann::json load_json(const std::string& path);

// cam.json and light.json: lib/reflectance/view_json's codec.
using reflectance::camera_from_json;
using reflectance::camera_to_json;
using reflectance::light_from_json;
using reflectance::light_to_json;

reflectance::LafortuneBrdf brdf_from_json(const nlohmann::json& j, const std::string& where);

// The materials file (brdffit(1) MATERIALS): {"materials": [brdf.json ...],
// "triangle_material": [per triangle]} or {"materials": [...], "vertex_weights":
// [[per vertex, one weight per material] ...]}.
reflectance::SurfaceMaterials materials_from_json(const nlohmann::json& j, const reflectance::TriangleMesh& mesh,
                                                  const std::string& where);

// The rig: one entry per image, paths resolved against `root`.
struct RigImage {
  std::string file, mask;        // as written in the rig
  std::string file_path, mask_path;  // resolved
  int angle_index = 0;
  double angle_deg = 0;
  brdffit::ImageView view;
  std::string light_id;
};
struct Rig {
  nlohmann::json doc;  // as read (kept for rewriting)
  std::string frame;
  std::vector<RigImage> images;
};
// `root`: the folder relative paths are resolved against ("" = the rig file's folder, or
// the working directory when the rig comes from standard input).
Rig load_rig(const std::string& path, const std::string& root);

// Radiance as float RGB (grey is replicated; a 4th channel is split off as validity).
void load_radiance(const std::string& path, cv::Mat& rgb, cv::Mat& valid);
cv::Mat load_mask(const std::string& path);

std::string encode_exr(const cv::Mat& rgb);
std::string encode_png(const cv::Mat& mat);
// Tone-mapped 8-bit sRGB preview: x -> sRGB(clamp(exposure x)).
cv::Mat tonemap(const cv::Mat& rgb, double exposure);

// Binary products go to a terminal only by mistake: a usage error for "-" on a terminal,
// naming `advice` (what to do instead).
void refuse_binary_terminal(const std::string& path, const char* advice = "use -o FILE");

// Writes binary data to a path, refusing a terminal for "-" (usage error).
void write_binary(const std::string& path, const std::vector<std::uint8_t>& bytes);

// A --report JSON; nothing when `path` is empty.
void write_report(const std::string& path, const nlohmann::json& j);

// A lat-long HDR environment map (EXR/PFM); non-finite texels become 0.
reflectance::EnvironmentMap load_environment(const std::string& path);

}  // namespace fest::brdffit_tool

// brdffit export (docs/brdffit.md §6): glTF 2.0 (or .glb) with the materials as
// metallic-roughness textures baked into a texture atlas (lib/brdffit/texture_bake).

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "brdffit/image_metrics.hpp"
#include "brdffit/pbr_appearance.hpp"
#include "brdffit/texture_atlas.hpp"
#include "brdffit/texture_bake.hpp"
#include "commands.hpp"
#include "core/srgb.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/threads.hpp"
#include "fitted_inputs.hpp"
#include "gltf_export.hpp"
#include "scene_io.hpp"

namespace fest::brdffit_tool {
namespace {

// 8-bit PNGs of the baked maps: base colour sRGB-encoded (glTF's baseColorTexture is
// sRGB), metallic-roughness linear, normals as 0.5 n + 0.5.
PngTextures encode_maps(const brdffit::PbrMaps& m, bool normal_map) {
  auto to8 = [](const cv::Mat& f, auto map) {
    cv::Mat out(f.size(), CV_8UC3);
    for (int y = 0; y < f.rows; ++y)
      for (int x = 0; x < f.cols; ++x)
        for (int c = 0; c < 3; ++c)
          out.at<cv::Vec3b>(y, x)[c] =
              static_cast<std::uint8_t>(std::lround(255 * std::clamp(map(f.at<cv::Vec3f>(y, x)[c]), 0.0, 1.0)));
    return out;
  };
  PngTextures t;
  t.base_color = encode_png(to8(m.base_color, [](float v) { return linear_to_srgb(v); }));
  t.metallic_roughness = encode_png(to8(m.metallic_roughness, [](float v) { return static_cast<double>(v); }));
  if (normal_map) t.normal = encode_png(to8(m.normal, [](float v) { return 0.5 * v + 0.5; }));
  return t;
}

}  // namespace

int run_export(const ExportArgs& a) {
  if (a.materials.empty() == a.svbrdf.empty()) throw usage_error("export needs --materials or --svbrdf (not both)");
  if (!a.normals.empty() && a.svbrdf.empty()) throw usage_error("--normals needs --svbrdf and --ltx");
  const bool glb = a.out.size() > 4 && a.out.compare(a.out.size() - 4, 4, ".glb") == 0;
  if (a.flat && (glb || !a.normals.empty())) throw usage_error("--flat writes a .gltf without textures (no .glb, no --normals)");
  const LoadedMesh lm = load_mesh(a.mesh);
  std::optional<FittedInputs> fitted;
  reflectance::SurfaceMaterials mats;
  if (!a.materials.empty()) {
    mats = materials_from_json(load_json(a.materials), lm.mesh, a.materials);
  } else {
    fitted = load_fitted(lm, a.mesh, a.svbrdf, a.ltx);
    mats = fitted_materials(*fitted, lm, a.svbrdf + ", " + a.ltx);
  }
  if (a.flat) {
    write_output(a.out, encode_gltf(lm.mesh, mats));
    return 0;
  }
  std::vector<Eigen::Vector3d> refined;
  if (!a.normals.empty()) refined = load_refined_normals(a.normals, fitted->set.lumitexels.size());

  // The atlas: axis-projected charts at a texel size that makes its longer side about
  // --texture-size. The first guess ignores the gutters and the packing's waste, which
  // grow with the number of charts (a fragmented scan): coarsen the texels up to twice
  // more when the atlas came out more than 10 % too large.
  double texel = a.texel > 0 ? a.texel : brdffit::texel_size_for(lm.mesh, a.texture_size);
  brdffit::AtlasOptions ao;
  ao.gutter = a.gutter;
  constexpr double kMaxSide = 16384;
  brdffit::TextureAtlas atlas;
  for (int pass = 0; pass < 3; ++pass) {
    const brdffit::FlatTriangles flat = brdffit::axis_projection(lm.mesh, texel);
    if (brdffit::flat_texel_area(flat) > kMaxSide * kMaxSide)
      throw usage_error("--texel {}: the mesh alone would cover more than {}^2 texels", texel, kMaxSide);
    atlas = brdffit::build_atlas(lm.mesh, flat, ao);
    const double side = std::max(atlas.width, atlas.height);
    if (a.texel > 0 || side <= 1.1 * a.texture_size) break;
    texel *= side / a.texture_size;
  }
  if (atlas.width > 16384 || atlas.height > 16384)
    throw usage_error("the texture atlas would be {}x{} texels (at most 16384): raise --texel or lower --texture-size",
                      atlas.width, atlas.height);
  const brdffit::TexelSurface texels = brdffit::texel_surface(atlas);
  brdffit::PbrMaps maps;
  if (fitted) {
    const brdffit::LumitexelSurface surface(lm.mesh, fitted->set, fitted->projection, mats, std::move(refined));
    maps = brdffit::bake_pbr(lm.mesh, atlas, texels, std::cref(surface), resolve_threads(a.threads));
  } else {
    maps = brdffit::bake_pbr(lm.mesh, atlas, texels, brdffit::materials_surface(lm.mesh, mats), resolve_threads(a.threads));
  }
  const PngTextures pngs = encode_maps(maps, !a.normals.empty());

  // Images beside the .gltf (named after it), inside the .glb, or data URIs on stdout.
  const ImageStorage storage = is_stdio(a.out) ? ImageStorage::data_uri : glb ? ImageStorage::glb : ImageStorage::files;
  const std::filesystem::path out_path(a.out);
  const GltfFile g = encode_textured_gltf(lm.mesh, atlas, pngs, storage, out_path.stem().string());
  if (is_stdio(a.out)) {
    write_output(a.out, g.bytes);
    return 0;
  }
  // All files under temporary names first, renamed into place only when every one was
  // written: nothing partial when the folder is full or missing.
  std::vector<std::unique_ptr<AtomicFile>> files;
  auto stage = [&](const std::string& path, const std::string& bytes) {
    files.push_back(std::make_unique<AtomicFile>(path));
    write_output(files.back()->temp_path(), bytes);
  };
  for (const auto& [name, bytes] : g.images) stage((out_path.parent_path() / name).string(), bytes);
  stage(a.out, g.bytes);
  for (auto& f : files) f->commit();
  return 0;
}

}  // namespace fest::brdffit_tool

// brdffit lumitexels (docs/brdffit.md §4): the rig's HDR images resampled onto the mesh by
// lib/brdffit -> a .ltx file, and with --atlas the home images' pixels as a texture atlas.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "brdffit/home_atlas.hpp"
#include "brdffit/ltx_format.hpp"
#include "brdffit/lumitexel_builder.hpp"
#include "brdffit/texture_atlas.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "core/resources.hpp"
#include "core/stopwatch.hpp"
#include "core/threads.hpp"
#include "core/tool_main.hpp"
#include "option_checks.hpp"
#include "scene_io.hpp"

namespace fest::brdffit_tool {

int run_lumitexels(const LumitexelArgs& a) {
  const Stopwatch clock;
  brdffit::LumitexelOptions o = with_threads(a.o, a.threads);
  const LoadedMesh lm = load_mesh(a.mesh);
  const Rig rig = load_rig(a.rig, a.root);
  if (rig.frame != "mesh" && rig.frame != "turntable")
    throw bad_input("rig frame \"{}\": run brdffit register --rig first ({})", rig.frame, a.rig);
  std::vector<brdffit::ImageView> views;
  for (std::size_t k = 0; k < rig.images.size(); ++k) {
    if (!rig.doc["images"][k].contains("light"))
      throw bad_input("rig image {} has no light ({})", k, rig.images[k].file);
    views.push_back(rig.images[k].view);
  }
  o.depth_eps = a.depth_eps_rel * reflectance::bbox_diagonal(lm.mesh);
  auto load = [&](std::size_t k) {
    brdffit::ImagePixels px;
    const RigImage& ri = rig.images[k];
    try {
      load_radiance(ri.file_path, px.radiance, px.valid);
      if (!ri.mask_path.empty()) px.mask = load_mask(ri.mask_path);
      if (px.radiance.cols != ri.view.camera.width || px.radiance.rows != ri.view.camera.height)
        throw bad_input("image is {}x{} but its camera is {}x{}", px.radiance.cols, px.radiance.rows,
                        ri.view.camera.width, ri.view.camera.height);
      if (!px.mask.empty() && px.mask.size() != px.radiance.size())
        throw bad_input("mask {} is {}x{} but the image is {}x{}", ri.mask, px.mask.cols, px.mask.rows,
                        px.radiance.cols, px.radiance.rows);
    } catch (const Error& e) {
      if (e.status() != Status::bad_input) throw;
      throw Error(e.status(), with_location(e.what(), ri.file_path));
    }
    return px;
  };
  brdffit::LumitexelReport rep;
  Progress bar("brdffit lumitexels", 0, progress_wanted(a.progress));
  o.progress = bar.callback();
  brdffit::LumitexelSet set = brdffit::build_lumitexels(lm.mesh, views, load, o, &rep);
  bar.finish();
  set.mesh_sha256 = lm.sha256;
  for (const RigImage& ri : rig.images) set.images.push_back(ri.file);
  nlohmann::json header{{"generator", "brdffit lumitexels"}, {"rig_frame", rig.frame}};
  header["cameras"] = nlohmann::json::array();
  header["lights"] = nlohmann::json::array();
  for (const auto& v : views) {
    header["cameras"].push_back(camera_to_json(v.camera));
    header["lights"].push_back(light_to_json(v.light));
  }
  header["dropped_lumitexels"] = rep.dropped;
  header["min_samples"] = o.min_samples;
  const std::vector<std::uint8_t> bytes = brdffit::encode_ltx(set, header);
  // --atlas (docs/brdffit.md §4): the photographs' pixels of every triangle's home image, packed.
  std::string atlas_exr, atlas_ply;
  nlohmann::json atlas_report;
  if (!a.atlas.empty()) {
    const brdffit::HomeAssignment home = brdffit::assign_home_images(lm.mesh, views, o.threads);
    const brdffit::FlatTriangles flat = brdffit::home_image_projection(lm.mesh, views, home);
    const brdffit::TextureAtlas atlas = brdffit::build_atlas(lm.mesh, flat);
    if (atlas.width > 32768 || atlas.height > 32768)
      throw bad_input("the texture atlas would be {}x{} texels ({})", atlas.width, atlas.height, a.atlas);
    const brdffit::TexelSurface texels = brdffit::texel_surface(atlas);
    cv::Mat rgb(atlas.height, atlas.width, CV_32FC3, cv::Scalar(0, 0, 0));
    std::vector<char> is_home(views.size(), 0);
    for (std::int32_t k : home.image)
      if (k >= 0) is_home[static_cast<std::size_t>(k)] = 1;
    std::size_t home_images = 0, home_pixels = 0;
    for (std::size_t k = 0; k < views.size(); ++k) {
      if (!is_home[k]) continue;
      ++home_images;
      home_pixels += static_cast<std::size_t>(views[k].camera.width) * static_cast<std::size_t>(views[k].camera.height);
      brdffit::sample_home_image(lm.mesh, texels, home, k, views[k], load(k).radiance, rgb);
    }
    atlas_exr = encode_exr(rgb);
    atlas_ply = encode_atlas_ply(lm.mesh, atlas);
    atlas_report = {{"width", atlas.width}, {"height", atlas.height}, {"charts", atlas.charts.size()},
                    {"home_images", home_images}, {"home_image_pixels", home_pixels}};
  }
  const double seconds = clock.seconds();
  if (!a.report.empty()) {
    nlohmann::json r{{"stage", "lumitexels"},
                     {"lumitexels", set.lumitexels.size()},
                     {"samples", set.samples.size()},
                     {"mean_samples", static_cast<double>(set.samples.size()) / static_cast<double>(set.lumitexels.size())},
                     {"candidates", rep.candidates},
                     {"dropped", rep.dropped},
                     {"triangles_with_home", rep.triangles_with_home},
                     {"rejected", {{"occluded", rep.rejected_occluded}, {"shadowed", rep.rejected_shadowed},
                                   {"grazing", rep.rejected_grazing}, {"mask", rep.rejected_mask}}},
                     {"nonfinite_pixels", rep.nonfinite_pixels},
                     {"stage_seconds", rep.seconds},
                     {"seconds", seconds},
                     {"peak_rss_kb", peak_rss_kb()},
                     {"bytes", bytes.size()}};
    if (!a.atlas.empty()) r["atlas"] = atlas_report;
    write_report(a.report, r);
  }
  if (rep.nonfinite_pixels > 0)
    warn("brdffit", fmt::format("{} samples met NaN/Inf radiance and were left out", rep.nonfinite_pixels));
  if (!a.atlas.empty()) {
    // The .ltx goes last; refuse a terminal before any file is written.
    refuse_binary_terminal(a.out);
    write_output(a.atlas, atlas_exr);
    write_output(a.atlas_mesh.empty() ? std::filesystem::path(a.atlas).replace_extension(".ply").string() : a.atlas_mesh,
                 atlas_ply);
  }
  write_binary(a.out, bytes);
  return 0;
}

}  // namespace fest::brdffit_tool

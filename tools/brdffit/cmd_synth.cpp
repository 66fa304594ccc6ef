// brdffit synth (docs/brdffit.md §7): a synthetic ground truth -- a mesh with known
// materials on a turntable, rendered by lib/reflectance: HDR images, masks, rig.json, truth.json.

#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "brdffit/brdf_json.hpp"
#include "brdffit/synthetic_scene.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "core/threads.hpp"
#include "formats/table/table_io.hpp"
#include "reflectance/environment.hpp"
#include "reflectance/render.hpp"
#include "scene_io.hpp"

namespace fest::brdffit_tool {

int run_synth(const SynthArgs& a) {
  const int threads = resolve_threads(a.threads);
  reflectance::TriangleMesh mesh;
  if (!a.mesh.empty()) {
    mesh = load_mesh(a.mesh).mesh;
  } else {
    mesh = brdffit::icosphere(a.sphere_level, a.sphere_radius);
  }
  // Materials: a count (the built-in palette on patches) or a materials file.
  reflectance::SurfaceMaterials mats;
  if (a.materials_file.empty()) {
    const int k = a.material_count;
    if (k < 1 || k > 64) throw usage_error("--materials {}: 1..64 built-in materials", k);
    mats.brdfs = brdffit::palette(k);
    mats.triangle_material = brdffit::material_patches(mesh, k, a.seed);
  } else {
    const nlohmann::json j = load_json(a.materials_file);
    if (!j.contains("triangle_material") && !j.contains("vertex_weights") && j.contains("materials") &&
        j["materials"].is_array()) {
      nlohmann::json with = j;
      with["triangle_material"] = brdffit::material_patches(mesh, static_cast<int>(j["materials"].size()), a.seed);
      mats = materials_from_json(with, mesh, a.materials_file);
    } else {
      mats = materials_from_json(j, mesh, a.materials_file);
    }
  }
  const reflectance::TriangleMesh truth_mesh = mesh;  // rendered with the true normals
  reflectance::TriangleMesh given_mesh = mesh;
  if (a.perturb_deg > 0) brdffit::perturb_normals(given_mesh, a.perturb_deg, a.seed + 7);
  const std::vector<brdffit::TurntableImage> images = brdffit::turntable_images(mesh, a.setup);

  reflectance::EnvironmentMap env;
  reflectance::IrradianceSH sh;
  if (!a.env.empty()) {
    env = load_environment(a.env);
    sh = reflectance::project_irradiance(env);
  }
  reflectance::RenderOptions ro;
  ro.threads = threads;
  ro.shadow_resolution = a.shadow_res;
  if (!a.env.empty()) ro.background = &env;
  if (!a.env.empty() && a.env_light > 0) {
    ro.ambient = &sh;
    ro.ambient_scale = a.env_light;
  }

  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(fs::path(a.out) / "hdr", ec);
  if (ec) throw io_error("cannot create {}: {}", (fs::path(a.out) / "hdr").string(), ec.message());
  if (a.previews) {
    fs::create_directories(fs::path(a.out) / "preview", ec);
    if (ec) throw io_error("cannot create {}/preview: {}", a.out, ec.message());
  }
  nlohmann::json rig{{"version", 1}, {"frame", "mesh"}, {"session", "."}, {"images", nlohmann::json::array()}};
  std::mt19937_64 rng(a.seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  int last_angle = -1;
  Progress bar("brdffit synth", images.size(), progress_wanted(a.progress));
  for (std::size_t k = 0; k < images.size(); ++k) {
    const brdffit::TurntableImage& img = images[k];
    reflectance::Rendering r = reflectance::render(truth_mesh, mats, img.view.camera, img.view.light, ro);
    if (a.noise > 0)
      for (int y = 0; y < r.radiance.rows; ++y)
        for (int x = 0; x < r.radiance.cols; ++x) {
          cv::Vec3f& p = r.radiance.at<cv::Vec3f>(y, x);
          for (int c = 0; c < 3; ++c) p[c] = static_cast<float>(p[c] * (1 + a.noise * gauss(rng)));
        }
    const std::string file = fmt::format("hdr/a{:03}_L{}.exr", img.angle_index, img.light);
    const std::string mask = fmt::format("hdr/a{:03}_mask.png", img.angle_index);
    write_output((fs::path(a.out) / file).string(), encode_exr(r.radiance));
    if (img.angle_index != last_angle) write_output((fs::path(a.out) / mask).string(), encode_png(r.mask));
    if (a.previews)
      write_output((fs::path(a.out) / fmt::format("preview/a{:03}_L{}.png", img.angle_index, img.light)).string(),
                   encode_png(tonemap(r.radiance, 1.0)));
    last_angle = img.angle_index;
    bar.advance();
    rig["images"].push_back({{"file", file},
                             {"angle_index", img.angle_index},
                             {"angle_deg", img.angle_deg},
                             {"camera", camera_to_json(img.view.camera)},
                             {"light", light_to_json(img.view.light, fmt::format("L{}", img.light))},
                             {"mask", mask}});
  }
  nlohmann::json truth{{"generator", "brdffit synth"},
                       {"seed", a.seed},
                       {"mesh", "mesh.ply"},
                       {"mesh_sha256", mesh_sha256(given_mesh)},
                       {"materials", nlohmann::json::array()},
                       {"triangle_material", mats.triangle_material},
                       {"noise", a.noise},
                       {"normals_perturbed_deg", a.perturb_deg},
                       {"views", a.setup.views},
                       {"lights", a.setup.lights}};
  for (const auto& b : mats.brdfs) truth["materials"].push_back(brdffit::brdf_to_json(b));
  if (!mats.vertex_weights.empty()) {
    truth.erase("triangle_material");
    const std::size_t m = mats.brdfs.size();
    nlohmann::json w = nlohmann::json::array();
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
      w.push_back(std::vector<float>(mats.vertex_weights.begin() + static_cast<long>(v * m),
                                     mats.vertex_weights.begin() + static_cast<long>((v + 1) * m)));
    truth["vertex_weights"] = w;
  }
  if (!a.env.empty()) {
    truth["environment"] = a.env;
    truth["environment_light"] = a.env_light;
  }
  bar.finish();
  write_output((fs::path(a.out) / "mesh.ply").string(), encode_mesh_ply(given_mesh));
  if (a.perturb_deg > 0) {
    write_output((fs::path(a.out) / "mesh_true.ply").string(), encode_mesh_ply(truth_mesh));
    truth["true_normals_mesh"] = "mesh_true.ply";
  }
  write_output((fs::path(a.out) / "truth.json").string(), formats::write_json(truth));
  write_output((fs::path(a.out) / "rig.json").string(), formats::write_json(rig));  // last: the dataset is complete
  return 0;
}

}  // namespace fest::brdffit_tool

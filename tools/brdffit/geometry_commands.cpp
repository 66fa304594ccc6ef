// brdffit's geometry subcommands: flags -> scene_io (formats) -> lib/brdffit,
// lib/reflectance -> scene_io. Each subcommand runs from its CLI11 callback; errors are
// fest::Error and reach main's run_tool.

#include "geometry_commands.hpp"

#include <chrono>
#include <cmath>
#include <algorithm>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>

#include "brdffit/fitted_materials.hpp"
#include "brdffit/pbr_appearance.hpp"
#include "brdffit/texture_atlas.hpp"
#include "brdffit/texture_bake.hpp"
#include "brdffit/home_atlas.hpp"
#include "brdffit/image_metrics.hpp"
#include "brdffit/ltw_format.hpp"
#include "cli/cli.hpp"
#include "core/tool_main.hpp"
#include "brdffit/ltx_format.hpp"
#include "brdffit/lumitexel_builder.hpp"
#include "brdffit/registration.hpp"
#include "brdffit/synthetic_scene.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/resources.hpp"
#include "core/threads.hpp"
#include "formats/table/table_io.hpp"
#include "reflectance/environment.hpp"
#include "reflectance/render.hpp"
#include "gltf_export.hpp"
#include "scene_io.hpp"

namespace fest::brdffit_tool {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

void write_json_file(const std::string& path, const nlohmann::json& j) { write_output(path, formats::write_json(j)); }

reflectance::EnvironmentMap load_environment(const std::string& path) {
  cv::Mat rgb, valid;
  load_radiance(path, rgb, valid);
  reflectance::EnvironmentMap env;
  env.width = rgb.cols;
  env.height = rgb.rows;
  env.rgb.resize(static_cast<std::size_t>(rgb.cols) * rgb.rows * 3);
  for (int y = 0; y < rgb.rows; ++y)
    for (int x = 0; x < rgb.cols; ++x)
      for (int c = 0; c < 3; ++c) {
        const float v = rgb.at<cv::Vec3f>(y, x)[c];
        env.rgb[(static_cast<std::size_t>(y) * rgb.cols + x) * 3 + static_cast<std::size_t>(c)] = std::isfinite(v) ? v : 0.f;
      }
  return env;
}

// ---------------------------------------------------------------------------- synth

struct SynthArgs {
  std::string mesh;
  int sphere_level = 4;
  double sphere_radius = 50;
  std::string materials = "3";
  brdffit::TurntableSetup setup;
  double noise = 0;
  std::uint64_t seed = 1;
  std::string env;
  double env_light = 0;
  double perturb_deg = 0;
  int shadow_res = 2048;
  bool previews = false;
  std::string out;
  int threads = 0;
};

void run_synth(const SynthArgs& a) {
  const int threads = resolve_threads(a.threads);
  reflectance::TriangleMesh mesh;
  if (!a.mesh.empty()) {
    mesh = load_mesh(a.mesh).mesh;
  } else {
    mesh = brdffit::icosphere(a.sphere_level, a.sphere_radius);
  }
  // Materials: a count (the built-in palette on patches) or a materials file.
  reflectance::SurfaceMaterials mats;
  bool numeric = !a.materials.empty() && a.materials.find_first_not_of("0123456789") == std::string::npos;
  if (numeric) {
    const int k = std::stoi(a.materials);
    if (k < 1 || k > 64) throw usage_error("--materials {}: 1..64 built-in materials", k);
    mats.brdfs = brdffit::palette(k);
    mats.triangle_material = brdffit::material_patches(mesh, k, a.seed);
  } else {
    const nlohmann::json j = load_json(a.materials);
    if (!j.contains("triangle_material") && !j.contains("vertex_weights") && j.contains("materials") &&
        j["materials"].is_array()) {
      nlohmann::json with = j;
      with["triangle_material"] = brdffit::material_patches(mesh, static_cast<int>(j["materials"].size()), a.seed);
      mats = materials_from_json(with, mesh, a.materials);
    } else {
      mats = materials_from_json(j, mesh, a.materials);
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
  for (const auto& b : mats.brdfs) truth["materials"].push_back(brdf_to_json(b));
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
  write_output((fs::path(a.out) / "mesh.ply").string(), encode_mesh_ply(given_mesh));
  if (a.perturb_deg > 0) {
    write_output((fs::path(a.out) / "mesh_true.ply").string(), encode_mesh_ply(truth_mesh));
    truth["true_normals_mesh"] = "mesh_true.ply";
  }
  write_json_file((fs::path(a.out) / "truth.json").string(), truth);
  write_json_file((fs::path(a.out) / "rig.json").string(), rig);  // last: the dataset is complete
}

// ------------------------------------------------------------------------ lumitexels

struct LumitexelArgs {
  std::string mesh, rig, root, out = "-", report, atlas, atlas_mesh;
  brdffit::LumitexelOptions o;
  double depth_eps_rel = 0.002;
  int threads = 0;
};

void run_lumitexels(LumitexelArgs a) {
  const auto t0 = Clock::now();
  a.o.threads = resolve_threads(a.threads);
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
  a.o.depth_eps = a.depth_eps_rel * reflectance::bbox_diagonal(lm.mesh);
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
  brdffit::LumitexelSet set = brdffit::build_lumitexels(lm.mesh, views, load, a.o, &rep);
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
  header["min_samples"] = a.o.min_samples;
  const std::vector<std::uint8_t> bytes = brdffit::encode_ltx(set, header);
  // --atlas (spec §2.9): the photographs' pixels of every triangle's home image, packed.
  std::string atlas_exr, atlas_ply;
  nlohmann::json atlas_report;
  if (!a.atlas.empty()) {
    const brdffit::HomeAssignment home = brdffit::assign_home_images(lm.mesh, views, a.o.threads);
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
  const double seconds = seconds_since(t0);
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
    write_json_file(a.report, r);
  }
  if (rep.nonfinite_pixels > 0)
    warn("brdffit", fmt::format("{} samples met NaN/Inf radiance and were left out", rep.nonfinite_pixels));
  if (!a.atlas.empty()) {
    // The .ltx goes last; refuse a terminal before any file is written.
    if (is_stdio(a.out) && isatty(1)) throw usage_error("refusing to write binary to a terminal (use -o FILE)");
    write_output(a.atlas, atlas_exr);
    write_output(a.atlas_mesh.empty() ? std::filesystem::path(a.atlas).replace_extension(".ply").string() : a.atlas_mesh,
                 atlas_ply);
  }
  write_binary(a.out, bytes);
}

// -------------------------------------------------------------------------- register

struct RegisterArgs {
  std::string mesh, mask, camera, rig, root, out = "-", report;
  brdffit::RegistrationOptions o;
  double max_xor = 0.05;
  int threads = 0;
};

void run_register(RegisterArgs a) {
  const auto t0 = Clock::now();
  a.o.threads = resolve_threads(a.threads);
  const LoadedMesh lm = load_mesh(a.mesh);
  nlohmann::json report{{"stage", "register"}};
  if (!a.rig.empty()) {
    if (!a.mask.empty() || !a.camera.empty()) throw usage_error("--rig excludes --mask and --camera");
    const Rig rig = load_rig(a.rig, a.root);
    std::vector<cv::Mat> masks;
    std::vector<double> angles;
    std::vector<reflectance::PinholeCamera> cams;
    std::vector<int> seen;
    for (const RigImage& ri : rig.images) {
      if (std::find(seen.begin(), seen.end(), ri.angle_index) != seen.end()) continue;
      seen.push_back(ri.angle_index);
      if (ri.mask_path.empty()) throw bad_input("rig image {} has no mask ({})", ri.file, a.rig);
      cv::Mat m = load_mask(ri.mask_path);
      if (m.cols != ri.view.camera.width || m.rows != ri.view.camera.height)
        throw bad_input("mask is {}x{} but its camera is {}x{} ({})", m.cols, m.rows, ri.view.camera.width,
                        ri.view.camera.height, ri.mask_path);
      masks.push_back(m);
      angles.push_back(ri.angle_deg);
      cams.push_back(ri.view.camera);
    }
    // The initial axis is the one the rig's cameras imply (z through the origin for
    // hdrmerge's turntable frame); the mesh starts where the rig's frame puts it.
    Eigen::Vector3d axis_dir, axis_point;
    brdffit::estimate_turntable_axis(cams, angles, axis_dir, axis_point);
    const brdffit::TurntableFit fit = brdffit::register_turntable(lm.mesh, masks, angles, cams, axis_dir, axis_point, a.o);
    if (!(fit.xor_cost <= a.max_xor))
      throw runtime_failure("registration did not converge: XOR {:.4f} > --max-xor {} ({})", fit.xor_cost, a.max_xor,
                            a.rig);
    nlohmann::json out = rig.doc;
    out["frame"] = "mesh";
    out["registration"] = {{"xor", fit.xor_cost},
                           {"axis_direction", {fit.axis_direction.x(), fit.axis_direction.y(), fit.axis_direction.z()}},
                           {"axis_point", {fit.axis_point.x(), fit.axis_point.y(), fit.axis_point.z()}},
                           {"mesh_sha256", lm.sha256}};
    for (std::size_t k = 0; k < rig.images.size(); ++k) {
      const RigImage& ri = rig.images[k];
      const std::size_t m = static_cast<std::size_t>(std::find(seen.begin(), seen.end(), ri.angle_index) - seen.begin());
      const reflectance::PinholeCamera& c = fit.cameras[m];
      auto& e = out["images"][k];
      e["camera"] = camera_to_json(c);
      if (e.contains("light")) {
        // The light is fixed relative to the camera: carry it over through the camera frame.
        const Eigen::Vector3d q_cam = ri.view.camera.to_camera(ri.view.light.position);
        const Eigen::Vector3d q = c.R.transpose() * (q_cam - c.t);
        e["light"]["position"] = {q.x(), q.y(), q.z()};
      }
    }
    report["xor"] = fit.xor_cost;
    report["evaluations"] = fit.evaluations;
    report["seconds"] = seconds_since(t0);
    if (!a.report.empty()) write_json_file(a.report, report);
    write_output(a.out, formats::write_json(out));
    return;
  }
  if (a.mask.empty() || a.camera.empty()) throw usage_error("register needs --mask and --camera, or --rig");
  const reflectance::PinholeCamera init = camera_from_json(load_json(a.camera), a.camera);
  const cv::Mat mask = load_mask(a.mask);
  if (mask.cols != init.width || mask.rows != init.height)
    throw bad_input("the mask is {}x{} but the camera is {}x{} ({})", mask.cols, mask.rows, init.width, init.height,
                    a.mask);
  const brdffit::RegistrationResult r = brdffit::register_silhouette(lm.mesh, mask, init, a.o);
  if (!(r.xor_cost <= a.max_xor))
    throw runtime_failure("registration did not converge: XOR {:.4f} > --max-xor {} ({})", r.xor_cost, a.max_xor,
                          a.mask);
  report["xor"] = r.xor_cost;
  report["evaluations"] = r.evaluations;
  report["seconds"] = seconds_since(t0);
  if (!a.report.empty()) write_json_file(a.report, report);
  write_output(a.out, formats::write_json(camera_to_json(r.camera)));
}

// ---------------------------------------------------------------------------- render

struct RenderArgs {
  std::string mesh, materials, svbrdf, ltx, camera, light, rig, root, out, png, mask_out, env;
  int rig_image = -1;
  double exposure = 1, env_light = 0;
  int shadow_res = 2048;
  bool no_shadows = false;
  int threads = 0;
};

// The fitted result: the .ltw weights and the .ltx lumitexels they were made from, both
// checked against the mesh.
struct FittedInputs {
  brdffit::Projection projection;
  brdffit::LumitexelSet set;
};

FittedInputs load_fitted(const LoadedMesh& lm, const std::string& mesh_path, const std::string& svbrdf,
                         const std::string& ltx) {
  if (ltx.empty()) throw usage_error("--svbrdf needs --ltx, the lumitexel file the weights were made from");
  FittedInputs f;
  nlohmann::json wh;
  try {
    f.projection = brdffit::decode_ltw(read_input(svbrdf), &wh);
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw Error(e.status(), with_location(e.what(), svbrdf));
  }
  const std::string bytes = read_input(ltx);
  try {
    f.set = brdffit::decode_ltx(std::vector<std::uint8_t>(bytes.begin(), bytes.end()), nullptr);
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw Error(e.status(), with_location(e.what(), ltx));
  }
  if (f.set.mesh_sha256 != lm.sha256)
    throw bad_input("the mesh does not match the lumitexel file: SHA-256 {} vs {} ({}, {})", lm.sha256.substr(0, 16),
                    f.set.mesh_sha256.substr(0, 16), mesh_path, ltx);
  if (wh.contains("mesh_sha256") && wh["mesh_sha256"].is_string() && wh["mesh_sha256"] != lm.sha256)
    throw bad_input("the weights were made for another mesh (mesh_sha256 differs) ({})", svbrdf);
  return f;
}

// Every triangle takes the BRDF of its lumitexels' majority cluster; triangles without
// lumitexels take their neighbours' (materials_from_projection).
reflectance::SurfaceMaterials fitted_materials(const FittedInputs& f, const LoadedMesh& lm, const std::string& where) {
  try {
    return brdffit::materials_from_projection(f.projection, f.set, lm.mesh.triangles);
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw Error(e.status(), with_location(e.what(), where));
  }
}

// --materials JSON, or the fitted materials: --svbrdf (.ltw) with the --ltx it was made
// from, each triangle taking the BRDF of its lumitexels' majority cluster.
reflectance::SurfaceMaterials render_materials(const RenderArgs& a, const LoadedMesh& lm) {
  if (a.materials.empty() == a.svbrdf.empty()) throw usage_error("render needs --materials or --svbrdf (not both)");
  if (!a.materials.empty()) return materials_from_json(load_json(a.materials), lm.mesh, a.materials);
  return fitted_materials(load_fitted(lm, a.mesh, a.svbrdf, a.ltx), lm, a.svbrdf + ", " + a.ltx);
}

void run_render(const RenderArgs& a) {
  if (is_stdio(a.out) && isatty(1)) throw usage_error("refusing to write binary to a terminal (use -o FILE)");
  const LoadedMesh lm = load_mesh(a.mesh);
  const reflectance::SurfaceMaterials mats = render_materials(a, lm);
  brdffit::ImageView view;
  if (!a.rig.empty()) {
    if (a.rig_image < 0) throw usage_error("--rig needs --image K");
    const Rig rig = load_rig(a.rig, a.root);
    if (a.rig_image >= static_cast<int>(rig.images.size()))
      throw usage_error("--image {}: the rig has {} images", a.rig_image, rig.images.size());
    view = rig.images[static_cast<std::size_t>(a.rig_image)].view;
  } else {
    if (a.camera.empty() || a.light.empty()) throw usage_error("render needs --camera and --light, or --rig and --image");
    view.camera = camera_from_json(load_json(a.camera), a.camera);
    view.light = light_from_json(load_json(a.light), a.light);
  }
  if (!a.camera.empty() && !a.rig.empty()) view.camera = camera_from_json(load_json(a.camera), a.camera);
  if (!a.light.empty() && !a.rig.empty()) view.light = light_from_json(load_json(a.light), a.light);
  reflectance::RenderOptions ro;
  ro.threads = resolve_threads(a.threads);
  ro.shadows = !a.no_shadows;
  ro.shadow_resolution = a.shadow_res;
  reflectance::EnvironmentMap env;
  reflectance::IrradianceSH sh;
  if (!a.env.empty()) {
    env = load_environment(a.env);
    sh = reflectance::project_irradiance(env);
    ro.background = &env;
    if (a.env_light > 0) {
      ro.ambient = &sh;
      ro.ambient_scale = a.env_light;
    }
  }
  const reflectance::Rendering r = reflectance::render(lm.mesh, mats, view.camera, view.light, ro);
  const std::string exr = encode_exr(r.radiance);
  std::string png, mask;
  if (!a.png.empty()) png = encode_png(tonemap(r.radiance, a.exposure));
  if (!a.mask_out.empty()) mask = encode_png(r.mask);
  if (!a.png.empty()) write_output(a.png, png);
  if (!a.mask_out.empty()) write_output(a.mask_out, mask);
  write_output(a.out, exr);
}

// ------------------------------------------------------------------------------ eval

struct EvalArgs {
  std::string photo, render, mask, error, out = "-";
};

void run_eval(const EvalArgs& a) {
  cv::Mat p, r, pv, rv;
  load_radiance(a.photo, p, pv);
  load_radiance(a.render, r, rv);
  cv::Mat mask;
  if (!a.mask.empty()) mask = load_mask(a.mask);
  brdffit::RenderError e;
  try {
    e = brdffit::compare_renderings(p, r, mask);
  } catch (const Error& err) {
    throw Error(err.status(), with_location(err.what(), a.photo + ", " + a.render));
  }
  nlohmann::json j{{"photo", a.photo},
                   {"render", a.render},
                   {"pixels", e.pixels},
                   {"rmse", e.rmse},
                   {"relative_l2", e.relative_l2},
                   {"psnr_db", std::isfinite(e.psnr_db) ? nlohmann::json(e.psnr_db) : nlohmann::json("inf")},
                   {"exposure", e.exposure}};
  std::string err_bytes;
  if (!a.error.empty()) err_bytes = encode_exr(e.error);
  if (!a.error.empty()) write_output(a.error, err_bytes);
  write_output(a.out, formats::write_json(j));
}

// ---------------------------------------------------------------------------- export

struct ExportArgs {
  std::string mesh, materials, svbrdf, ltx, normals, out;
  bool flat = false;
  int texture_size = 1024, gutter = 2, threads = 0;
  double texel = 0;
};

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
  t.base_color = encode_png(to8(m.base_color, [](float v) { return brdffit::srgb_encode(v); }));
  t.metallic_roughness = encode_png(to8(m.metallic_roughness, [](float v) { return static_cast<double>(v); }));
  if (normal_map) t.normal = encode_png(to8(m.normal, [](float v) { return 0.5 * v + 0.5; }));
  return t;
}

void run_export(const ExportArgs& a) {
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
    return;
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
    return;
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
}

// ------------------------------------------------------------------------------ info

struct InfoArgs {
  std::string in = "-", mesh;
};

void run_info(const InfoArgs& a) {
  const std::string bytes = read_input(a.in);
  nlohmann::json header;
  brdffit::LumitexelSet set;
  try {
    set = brdffit::decode_ltx(std::vector<std::uint8_t>(bytes.begin(), bytes.end()), &header);
  } catch (const Error& e) {
    throw Error(e.status(), with_location(e.what(), a.in));
  }
  if (!a.mesh.empty()) {
    const LoadedMesh lm = load_mesh(a.mesh);
    if (lm.sha256 != set.mesh_sha256)
      throw bad_input("the mesh does not match the lumitexel file: SHA-256 {} vs {} ({}, {})", lm.sha256.substr(0, 16),
                      set.mesh_sha256.substr(0, 16), a.mesh, a.in);
  }
  std::size_t max_count = 0;
  for (const auto& l : set.lumitexels) max_count = std::max<std::size_t>(max_count, l.count);
  nlohmann::json j{{"lumitexels", set.lumitexels.size()},
                   {"samples", set.samples.size()},
                   {"mean_samples", set.lumitexels.empty() ? 0.0
                                                           : static_cast<double>(set.samples.size()) /
                                                                 static_cast<double>(set.lumitexels.size())},
                   {"max_samples", max_count},
                   {"images", set.images.size()},
                   {"mesh_sha256", set.mesh_sha256},
                   {"mesh_matches", a.mesh.empty() ? nlohmann::json(nullptr) : nlohmann::json(true)}};
  write_output("-", formats::write_json(j));
}

}  // namespace

void add_geometry_commands(CLI::App& app) {
  // The argument structs live as long as the app: CLI11 binds to them.
  static SynthArgs synth;
  auto* s = app.add_subcommand("synth", "Synthetic ground truth: a mesh with known materials on a turntable, HDR images, "
                                        "masks, rig.json, truth.json");
  s->add_option("--mesh", synth.mesh, "Mesh (PLY/OBJ/OFF/STL); default: an icosphere");
  s->add_option("--sphere", synth.sphere_level, "Icosphere subdivision level when no --mesh (20*4^L triangles)")
      ->check(CLI::Range(0, 9));
  s->add_option("--radius", synth.sphere_radius, "Icosphere radius")->check(CLI::PositiveNumber);
  s->add_option("--materials", synth.materials, "Number of built-in materials on surface patches, or a materials JSON");
  s->add_option("--views", synth.setup.views, "Turntable angles")->check(CLI::Range(1, 4096));
  s->add_option("--lights", synth.setup.lights, "Point lights (one image per view and light)")->check(CLI::Range(1, 64));
  s->add_option("--width", synth.setup.width, "Image width")->check(CLI::Range(8, 65536));
  s->add_option("--height", synth.setup.height, "Image height")->check(CLI::Range(8, 65536));
  s->add_option("--elevation", synth.setup.elevation_deg, "Camera elevation above the table, degrees")
      ->check(CLI::Range(-89.0, 89.0));
  s->add_option("--distance", synth.setup.distance, "Camera distance in bounding-sphere radii")
      ->check(CLI::Range(1.1, 1000.0));
  s->add_option("--fill", synth.setup.fill, "Fraction of the shorter image side the bounding sphere spans")
      ->check(CLI::Range(0.01, 1.0));
  s->add_option("--noise", synth.noise, "Multiplicative Gaussian noise, relative standard deviation")
      ->check(CLI::Range(0.0, 1.0));
  s->add_option("--seed", synth.seed, "Seed of every random choice (patches, noise, normal perturbation)");
  s->add_option("--env", synth.env, "Lat-long HDR environment map (EXR) seen as the background");
  s->add_option("--env-light", synth.env_light, "Also light the object diffusely by the environment, scaled")
      ->check(CLI::NonNegativeNumber);
  s->add_option("--perturb-normals", synth.perturb_deg, "Tilt the written mesh's normals by up to DEG (truth kept)")
      ->check(CLI::Range(0.0, 60.0));
  s->add_option("--shadow-res", synth.shadow_res, "Shadow map size")->check(CLI::Range(16, 16384));
  s->add_flag("--previews", synth.previews, "Also write tone-mapped PNGs into DIR/preview/");
  s->add_option("-o,--output", synth.out, "Dataset folder (created)")->required();
  cli::add_threads(*s, synth.threads);
  s->callback([] { run_synth(synth); });

  static LumitexelArgs ltx;
  auto* l = app.add_subcommand("lumitexels", "Resample the rig's HDR images onto the mesh: .ltx lumitexels");
  l->add_option("--mesh", ltx.mesh, "The mesh the rig is registered to")->required();
  l->add_option("--rig", ltx.rig, "Rig JSON (frame mesh or turntable)")->required();
  l->add_option("--root", ltx.root, "Folder the rig's image paths are relative to (default: the rig's session folder)");
  l->add_option("-o,--output", ltx.out, "Lumitexel file, - = standard output");
  l->add_option("--min-samples", ltx.o.min_samples, "Drop lumitexels with fewer samples")->check(CLI::Range(1, 65535));
  l->add_option("--min-cos", ltx.o.min_cos, "Smallest cosine of light and view to the normal")->check(CLI::Range(0.0, 1.0));
  l->add_option("--depth-eps", ltx.depth_eps_rel, "Depth and shadow tolerance, fraction of the bbox diagonal")
      ->check(CLI::Range(0.0, 1.0));
  l->add_option("--shadow-res", ltx.o.shadow_resolution, "Shadow map size (0: the largest image side, 512..8192)")
      ->check(CLI::Range(0, 16384));
  l->add_option("--atlas", ltx.atlas, "Also write the texture atlas of the home images' pixels (EXR; spec §2.9)");
  l->add_option("--atlas-mesh", ltx.atlas_mesh, "The mesh with the atlas' texture coordinates (PLY; default: the "
                                                "--atlas path with .ply)");
  l->add_option("--report", ltx.report, "Counts and timings as JSON");
  cli::add_threads(*l, ltx.threads);
  l->callback([] { run_lumitexels(ltx); });

  static RegisterArgs reg;
  auto* r = app.add_subcommand("register", "Silhouette registration of a photograph (or a turntable rig) to the mesh");
  r->add_option("--mesh", reg.mesh, "The mesh")->required();
  r->add_option("--mask", reg.mask, "Silhouette of the photograph (nonzero = object)");
  r->add_option("--camera", reg.camera, "cam.json: intrinsics and the initial pose");
  r->add_option("--rig", reg.rig, "Turntable mode: fit one camera and the table axis to all masks of the rig");
  r->add_option("--root", reg.root, "Folder the rig's paths are relative to (default: the rig's session folder)");
  r->add_flag("--auto", reg.o.automatic, "Ignore the initial pose: search orientations on SO(3)");
  r->add_flag("--fix-focal", reg.o.fix_focal, "Keep the camera's focal length (calibrated): fit the pose only");
  r->add_option("--orient-samples", reg.o.orient_samples, "Orientations tried by --auto")->check(CLI::Range(1, 100000));
  r->add_option("--coarse-iters", reg.o.coarse_iters, "Simplex steps per orientation at 1/8 resolution")
      ->check(CLI::Range(1, 10000));
  r->add_option("--keep", reg.o.keep, "Best orientations of --auto refined at every level")->check(CLI::Range(1, 1000));
  r->add_option("--iters", reg.o.iters_per_level, "Simplex steps per pyramid level")->check(CLI::Range(1, 100000));
  r->add_option("--max-xor", reg.max_xor, "Fail (exit 1) above this XOR fraction")->check(CLI::Range(0.0, 10.0));
  r->add_option("--seed", reg.o.seed, "Seed of the orientation samples");
  r->add_option("-o,--output", reg.out, "Fitted cam.json (or rig), - = standard output");
  r->add_option("--report", reg.report, "XOR, evaluations, time as JSON");
  cli::add_threads(*r, reg.threads);
  r->callback([] { run_register(reg); });

  static RenderArgs ren;
  auto* d = app.add_subcommand("render", "Render the mesh with Lafortune materials under a point light (linear EXR)");
  d->add_option("--mesh", ren.mesh, "The mesh")->required();
  d->add_option("--materials", ren.materials, "Materials JSON (truth.json of synth, or brdffit(1) MATERIALS)");
  d->add_option("--svbrdf", ren.svbrdf, "Fitted materials instead: .ltw of brdffit project (with --ltx); every "
                                         "triangle takes its lumitexels' majority cluster BRDF");
  d->add_option("--ltx", ren.ltx, "The lumitexel file the --svbrdf weights were made from");
  d->add_option("--camera", ren.camera, "cam.json");
  d->add_option("--light", ren.light, "light.json");
  d->add_option("--rig", ren.rig, "Take camera and light from a rig image (with --image)");
  d->add_option("--root", ren.root, "Folder the rig's paths are relative to");
  d->add_option("--image", ren.rig_image, "Index of the rig image")->check(CLI::NonNegativeNumber);
  d->add_option("-o,--output", ren.out, "Radiance EXR, - = standard output")->required();
  d->add_option("--png", ren.png, "Also write a tone-mapped PNG");
  d->add_option("--exposure", ren.exposure, "Scale before tone mapping for --png")->check(CLI::PositiveNumber);
  d->add_option("--mask-out", ren.mask_out, "Also write the object mask (PNG)");
  d->add_option("--env", ren.env, "Lat-long HDR environment map as background");
  d->add_option("--env-light", ren.env_light, "Diffuse environment light scale")->check(CLI::NonNegativeNumber);
  d->add_option("--shadow-res", ren.shadow_res, "Shadow map size")->check(CLI::Range(16, 16384));
  d->add_flag("--no-shadows", ren.no_shadows, "Skip the shadow test");
  cli::add_threads(*d, ren.threads);
  d->callback([] { run_render(ren); });

  static EvalArgs ev;
  auto* e = app.add_subcommand("eval", "Compare a rendering with a photograph: RMSE, relative L2, PSNR as JSON");
  e->add_option("--photo", ev.photo, "Photograph (EXR/PFM radiance)")->required();
  e->add_option("--render", ev.render, "Rendering from the same camera and light")->required();
  e->add_option("--mask", ev.mask, "Compare inside this mask only");
  e->add_option("--error", ev.error, "Also write |photo - render| (EXR)");
  e->add_option("-o,--output", ev.out, "Metrics JSON, - = standard output");
  e->callback([] { run_eval(ev); });

  static ExportArgs ex;
  auto* x = app.add_subcommand("export", "glTF 2.0 (or .glb) with the materials as metallic-roughness textures in a "
                                         "texture atlas (spec §2.9, §2.10)");
  x->add_option("--mesh", ex.mesh, "The mesh")->required();
  x->add_option("--materials", ex.materials, "Materials JSON (truth.json of synth, or brdffit(1) MATERIALS)");
  x->add_option("--svbrdf", ex.svbrdf, "Fitted materials instead: .ltw of brdffit project (with --ltx); each texel "
                                       "takes the nearest lumitexel's blend of basis BRDFs");
  x->add_option("--ltx", ex.ltx, "The lumitexel file the --svbrdf weights were made from");
  x->add_option("--normals", ex.normals, "Refined normals (normals.ply of brdffit normals): also a normal map");
  x->add_option("--gltf", ex.out, "Output .gltf (PNG textures beside it), .glb (all in one), - = standard output "
                                  "(textures as data URIs)")->required();
  x->add_option("--texture-size", ex.texture_size, "About the atlas' longer side in texels")->check(CLI::Range(16, 16384));
  x->add_option("--texel", ex.texel, "World units per texel instead of --texture-size")->check(CLI::PositiveNumber);
  x->add_option("--gutter", ex.gutter, "Texels around each atlas chart")->check(CLI::Range(0, 64));
  x->add_flag("--flat", ex.flat, "No textures: one constant material per BRDF, triangles by majority material");
  cli::add_threads(*x, ex.threads);
  x->callback([] { run_export(ex); });

  static InfoArgs info;
  auto* i = app.add_subcommand("info", "Describe a .ltx file as JSON; with --mesh, check that it belongs to that mesh");
  i->add_option("input", info.in, "Lumitexel file, - = standard input");
  i->add_option("--mesh", info.mesh, "Fail (exit 3) unless the file's mesh SHA-256 is this mesh's");
  i->callback([] { run_info(info); });
}

}  // namespace fest::brdffit_tool

// brdffit render (docs/brdffit.md §6): the mesh with known or fitted Lafortune materials
// under a point light (lib/reflectance) -> a linear radiance EXR.

#include <string>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/threads.hpp"
#include "fitted_inputs.hpp"
#include "reflectance/environment.hpp"
#include "reflectance/render.hpp"
#include "scene_io.hpp"

namespace fest::brdffit_tool {
namespace {

// --materials JSON, or the fitted materials: --svbrdf (.ltw) with the --ltx it was made
// from, each triangle taking the BRDF of its lumitexels' majority cluster.
reflectance::SurfaceMaterials render_materials(const RenderArgs& a, const LoadedMesh& lm) {
  if (a.materials.empty() == a.svbrdf.empty()) throw usage_error("render needs --materials or --svbrdf (not both)");
  if (!a.materials.empty()) return materials_from_json(load_json(a.materials), lm.mesh, a.materials);
  return fitted_materials(load_fitted(lm, a.mesh, a.svbrdf, a.ltx), lm, a.svbrdf + ", " + a.ltx);
}

}  // namespace

int run_render(const RenderArgs& a) {
  refuse_binary_terminal(a.out);
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
  return 0;
}

}  // namespace fest::brdffit_tool

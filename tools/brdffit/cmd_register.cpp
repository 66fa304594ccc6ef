// brdffit register (docs/brdffit.md §6): silhouette registration of one photograph, or of
// a turntable rig's masks, to the mesh (lib/brdffit/registration) -> cam.json or the rig.

#include <algorithm>
#include <string>
#include <vector>

#include "brdffit/registration.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "core/stopwatch.hpp"
#include "core/threads.hpp"
#include "formats/table/table_io.hpp"
#include "option_checks.hpp"
#include "scene_io.hpp"

namespace fest::brdffit_tool {

int run_register(const RegisterArgs& a) {
  const Stopwatch clock;
  brdffit::RegistrationOptions o = with_threads(a.o, a.threads);
  Progress bar("brdffit register", 0, progress_wanted(a.progress));
  o.progress = bar.callback();
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
    const brdffit::TurntableFit fit = brdffit::register_turntable(lm.mesh, masks, angles, cams, axis_dir, axis_point, o);
    bar.finish();
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
    report["seconds"] = clock.seconds();
    write_report(a.report, report);
    write_output(a.out, formats::write_json(out));
    return 0;
  }
  if (a.mask.empty() || a.camera.empty()) throw usage_error("register needs --mask and --camera, or --rig");
  const reflectance::PinholeCamera init = camera_from_json(load_json(a.camera), a.camera);
  const cv::Mat mask = load_mask(a.mask);
  if (mask.cols != init.width || mask.rows != init.height)
    throw bad_input("the mask is {}x{} but the camera is {}x{} ({})", mask.cols, mask.rows, init.width, init.height,
                    a.mask);
  const brdffit::RegistrationResult r = brdffit::register_silhouette(lm.mesh, mask, init, o);
  bar.finish();
  if (!(r.xor_cost <= a.max_xor))
    throw runtime_failure("registration did not converge: XOR {:.4f} > --max-xor {} ({})", r.xor_cost, a.max_xor,
                          a.mask);
  report["xor"] = r.xor_cost;
  report["evaluations"] = r.evaluations;
  report["seconds"] = clock.seconds();
  write_report(a.report, report);
  write_output(a.out, formats::write_json(camera_to_json(r.camera)));
  return 0;
}

}  // namespace fest::brdffit_tool

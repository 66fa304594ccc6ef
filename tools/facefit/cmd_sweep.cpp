// facefit sweep: the chapter's experiment, the error against eta over a set of faces.

#include <sys/stat.h>

#include <cmath>
#include <map>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "commands.hpp"
#include "face_files.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/image.hpp"
#include "facefit/camera.hpp"
#include "facefit/evaluate.hpp"
#include "facefit/render.hpp"
#include "facefit/synth.hpp"
#include "formats/facemodel/landmarks_io.hpp"
#include "formats/facemodel/mmb.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"

namespace fest::facefit_tool {

using namespace fest;

int run_sweep(const SweepArgs& a) {
  const facefit::Model model = load_model(a.model);
  if (a.faces.empty() || a.vertices.empty()) throw usage_error("sweep needs --faces LIST and --vertices SET.tsv");
  std::vector<Eigen::VectorXd> faces;
  for (const auto& p : read_list(a.faces)) faces.push_back(read_shape(p));
  const auto vertices = read_vertex_indices(a.vertices);
  const auto& etas = a.etas;
  for (double e : etas)
    if (e < 0) throw usage_error("--etas: η must be >= 0");
  std::vector<double> comps = a.components.empty() ? std::vector<double>{static_cast<double>(model.components)}
                                                   : a.components;
  const auto& noises = a.noise;
  const auto& yaws = a.yaw;
  std::vector<facefit::SweepSetting> settings;
  for (double k : comps) {
    if (k < 1 || k > static_cast<double>(model.components) || k != std::floor(k))
      throw usage_error("--components {} outside 1..{}", k, model.components);
    for (double s : noises) {
      if (s < 0) throw usage_error("--noise-sigma must be >= 0");
      for (double y : yaws) settings.push_back({static_cast<std::size_t>(k), s, y});
    }
  }
  const std::vector<std::uint32_t> mask = a.mask.empty() ? model.eval_mask : read_vertex_indices(a.mask);
  const auto rows = facefit::sweep(model, faces, vertices, etas, settings, mask, a.seed);
  std::string text;
  if (!a.summary) {
    text = "face\tcomponents\tf\teta\tsigma_N\tyaw_deg\tE_r\tE_r_rms\tnorm_c\tE_full\n";
    for (const auto& r : rows)
      text += fmt::format("{}\t{}\t{}\t{:.9g}\t{:.9g}\t{:.9g}\t{:.9g}\t{:.9g}\t{:.9g}\t{:.9g}\n", r.face, r.setting.components, r.f,
                          r.eta, r.setting.sigma_noise, r.setting.yaw_deg, r.E_r, r.E_r_rms, r.norm_c, r.E_full);
  } else {
    // Means over faces per (setting, η): the paper's curves. Row order: settings, then η.
    struct Acc { double E_r = 0, E_r_rms = 0, norm_c = 0, E_full = 0; std::size_t n = 0; };
    std::vector<Acc> acc(settings.size() * etas.size());
    std::size_t i = 0;
    for (const auto& r : rows) {
      auto& s = acc[i++ % acc.size()];
      s.E_r += r.E_r; s.E_r_rms += r.E_r_rms; s.norm_c += r.norm_c; s.E_full += r.E_full; ++s.n;
    }
    text = "components\tf\teta\tsigma_N\tyaw_deg\tE_r\tE_r_rms\tnorm_c\tE_full\n";
    for (std::size_t si = 0; si < settings.size(); ++si)
      for (std::size_t ei = 0; ei < etas.size(); ++ei) {
        const auto& s = acc[si * etas.size() + ei];
        const double n = static_cast<double>(s.n);
        text += fmt::format("{}\t{}\t{:.9g}\t{:.9g}\t{:.9g}\t{:.9g}\t{:.9g}\t{:.9g}\t{:.9g}\n", settings[si].components, vertices.size(),
                            etas[ei], settings[si].sigma_noise, settings[si].yaw_deg, s.E_r / n, s.E_r_rms / n, s.norm_c / n, s.E_full / n);
      }
  }
  write_output("-", text);
  return 0;
}

}  // namespace fest::facefit_tool

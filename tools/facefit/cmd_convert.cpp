// facefit convert: a model imported from eos .bin, NumPy .npz, a mesh list or .mmb, written as .mmb.

#include <sys/stat.h>

#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "face_files.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "facefit/pca_build.hpp"
#include "facefit/rng.hpp"
#include "formats/facemodel/import.hpp"
#include "formats/facemodel/mmb.hpp"
#include "formats/table/table_io.hpp"
#include "model_assembly.hpp"

namespace fest::facefit_tool {

using namespace fest;

int run_convert(const ConvertArgs& a) {
  if (!(a.scale > 0) || !std::isfinite(a.scale)) throw usage_error("--scale must be positive");
  facefit::Model m;
  std::string warnings;
  if (a.from == ModelSource::eos) {
    m = formats::read_eos_model(read_input(a.input), a.input);
  } else if (a.from == ModelSource::npz) {
    m = formats::read_npz_model(a.input, &warnings);
  } else if (a.from == ModelSource::mmb) {
    formats::MmbReadOptions o;
    o.fix_basis = a.fix_basis;
    m = formats::read_mmb(a.input, o, &warnings);
  } else {
    BuildArgs b;
    m = build_from_meshes(read_list(a.input), b);
  }
  if (!warnings.empty()) warn(warnings);
  if (a.scale != 1) {
    for (auto& v : m.mean) v *= a.scale;
    for (auto& s : m.sigma) s *= a.scale;
  }
  const auto fixed = check_model_naming_flags(m, a.fix_basis);
  if (fixed.reordered) warn("sigma was not descending: components reordered");
  if (fixed.renormalised) warn("basis columns renormalised (--fix-basis)");
  attach_landmarks(m, a.landmarks, a.mask);
  // µm-sized models (BFM 2009) show as a bounding box over 1000 units.
  double lo = 1e300, hi = -1e300;
  for (double v : m.mean) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (hi - lo > 1000) warn(fmt::format("model extent is {:.4g} units: if it is in µm use --scale 0.001 for mm", hi - lo));
  write_output(a.output, formats::write_mmb(m));
  return 0;
}

}  // namespace fest::facefit_tool

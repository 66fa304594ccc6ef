// brdffit normals (docs/brdffit.md §6): .ltx and .ltw -> lib/brdffit's normal refinement
// against the projected BRDFs -> normals.ply.

#include <cstdio>
#include <string>

#include "brdffit/ltw_format.hpp"
#include "brdffit/normals.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "core/stopwatch.hpp"
#include "core/threads.hpp"
#include "fitted_inputs.hpp"
#include "option_checks.hpp"

namespace fest::brdffit_tool {
namespace {

// normals.ply (docs/brdffit.md §6): a point cloud with x y z nx ny nz (refined) and nx0
// ny0 nz0 (mesh). fest's mesh writer keeps only the standard vertex attributes, so this
// small fixed-layout PLY is written here.
std::string normals_ply(const brdffit::LumitexelSet& set, const brdffit::NormalResult& r, bool ascii) {
  std::string out = "ply\nformat ";
  out += ascii ? "ascii" : "binary_little_endian";
  out += " 1.0\ncomment brdffit normals: refined (nx ny nz) and mesh (nx0 ny0 nz0) normals\n";
  out += "element vertex " + std::to_string(set.lumitexels.size()) + "\n";
  for (const char* n : {"x", "y", "z", "nx", "ny", "nz", "nx0", "ny0", "nz0"}) out += std::string("property float ") + n + "\n";
  out += "property uchar refined\nend_header\n";
  for (std::size_t i = 0; i < set.lumitexels.size(); ++i) {
    const brdffit::Lumitexel& l = set.lumitexels[i];
    const float v[9] = {l.p.x(), l.p.y(), l.p.z(), r.normals[i].x(), r.normals[i].y(), r.normals[i].z(),
                        l.n.x(), l.n.y(), l.n.z()};
    if (ascii) {
      char line[256];
      int len = 0;
      for (float f : v) len += std::snprintf(line + len, sizeof(line) - static_cast<std::size_t>(len), "%.9g ", static_cast<double>(f));
      out.append(line, static_cast<std::size_t>(len));
      out += std::to_string(r.refined[i]) + "\n";
    } else {
      out.append(reinterpret_cast<const char*>(v), sizeof(v));
      out.push_back(static_cast<char>(r.refined[i]));
    }
  }
  return out;
}

}  // namespace

int run_normals(const NormalsArgs& a) {
  const Stopwatch clock;
  if (!a.ascii) refuse_binary_terminal(a.output, "use -o or a pipe");
  brdffit::NormalOptions o = with_threads(a.n, a.threads);
  nlohmann::json wh;
  const brdffit::Projection p = decoded_from(a.svbrdf, [&] { return brdffit::decode_ltw(read_input(a.svbrdf), &wh); });
  nlohmann::json header;
  const brdffit::LumitexelSet set = load_lumitexels(a.input, &header);
  if (wh.contains("mesh_sha256") && wh["mesh_sha256"].is_string() && wh["mesh_sha256"] != set.mesh_sha256)
    throw bad_input("the weights were made for another mesh (mesh_sha256 differs) ({})", a.svbrdf);
  if (p.cluster.size() != set.lumitexels.size())
    throw bad_input("{} has weights for {} lumitexels, the lumitexel file has {}", a.svbrdf, p.cluster.size(), set.lumitexels.size());
  check_normal_options(o);
  Progress bar("brdffit normals", 0, progress_wanted(a.progress));
  o.progress = bar.callback();
  const brdffit::NormalResult r = brdffit::refine_normals(set, p, o);
  bar.finish();
  write_output(a.output, normals_ply(set, r, a.ascii));
  write_report(a.report, {{"command", "normals"}, {"lumitexels", set.lumitexels.size()}, {"refined", r.refined_count},
                          {"residual_before", r.residual_before}, {"residual_after", r.residual_after},
                          {"seconds", clock.seconds()}});
  return 0;
}

}  // namespace fest::brdffit_tool

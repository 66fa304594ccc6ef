// facefit synth: the synthetic face population G2 (docs/facefit.md §4), its training and test
// lists, landmark sets and evaluation mask.

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

int run_synth(const SynthArgs& a) {
  if (a.output.empty()) throw usage_error("synth needs -o DIR");
  if (a.faces < 2 || a.train < 2 || a.train > a.faces) throw usage_error("need 2 <= --train <= --faces");
  if (a.resolution < 16 || a.resolution > 2048) throw usage_error("--resolution must be in 16..2048");
  if (!(a.detail >= 0)) throw usage_error("--detail-mm must be >= 0");
  if (::mkdir(a.output.c_str(), 0777) != 0 && errno != EEXIST) throw io_error("cannot create folder '{}'", a.output);
  facefit::Rng rng(a.seed);
  const auto tris = facefit::grid_triangles(a.resolution);
  std::string train, test;
  for (int i = 0; i < a.faces; ++i) {
    const auto face = facefit::draw_face(rng, a.detail);
    const std::string name = fmt::format("face{:03d}.ply", i + 1);
    write_mesh_to(shape_to_mesh(facefit::face_shape(face, a.resolution), 3, tris), a.output + "/" + name, std::nullopt);
    (i < a.train ? train : test) += name + "\n";
  }
  write_output(a.output + "/train.txt", train);
  write_output(a.output + "/test.txt", test);
  const auto sets = facefit::synth_landmarks(a.resolution, a.seed);
  write_output(a.output + "/set17.tsv", formats::write_vertex_set(sets.set17));
  write_output(a.output + "/set50.tsv", formats::write_vertex_set(sets.set50));
  write_output(a.output + "/set1000.tsv", formats::write_vertex_set(sets.set1000));
  write_output(a.output + "/landmarks.tsv", formats::write_vertex_set(sets.set50));
  std::vector<facefit::NamedVertex> mask;
  for (auto v : sets.eval_mask) mask.push_back({std::to_string(v), v});
  write_output(a.output + "/evalmask.tsv", formats::write_vertex_set(mask));
  return 0;
}

}  // namespace fest::facefit_tool

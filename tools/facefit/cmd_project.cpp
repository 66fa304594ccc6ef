// facefit project: a face's landmarks under a scaled orthographic camera, with noise.

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

int run_project(const ProjectArgs& a) {
  if (a.vertices.empty()) throw usage_error("project needs --vertices SET.tsv");
  if (a.noise_sigma < 0) throw usage_error("--noise-sigma must be >= 0");
  Eigen::VectorXd shape;
  if (!a.mesh.empty()) {
    shape = read_shape(a.mesh);
  } else {
    const facefit::Model m = load_model(a.model);
    if (m.dims != 3) throw bad_input("project needs a 3-D model");
    shape = Eigen::Map<const Eigen::VectorXd>(m.mean.data(), static_cast<Eigen::Index>(m.mean.size()));
  }
  const auto set = formats::read_vertex_set(read_text(a.vertices), a.vertices);
  const auto& c = a.center;
  const auto P = facefit::orthographic_camera(a.scale, {c[0], c[1]}, a.yaw, a.pitch);
  facefit::Rng rng(a.seed);
  std::vector<facefit::LandmarkEntry> out;
  for (const auto& nv : set) {
    if (3 * static_cast<Eigen::Index>(nv.vertex) + 2 >= shape.size())
      throw bad_input("vertex {} of '{}' is out of range ({} vertices)", nv.vertex, nv.name, shape.size() / 3);
    const Eigen::Vector3d x = shape.segment<3>(3 * static_cast<Eigen::Index>(nv.vertex));
    Eigen::Vector2d uv = P.leftCols<3>() * x + P.col(3);
    if (a.noise_sigma > 0) {
      uv.x() += a.noise_sigma * rng.normal();
      uv.y() += a.noise_sigma * rng.normal();
    }
    facefit::LandmarkEntry e;
    e.id = nv.name;
    e.by_vertex = a.by_vertex;
    e.vertex = nv.vertex;
    e.u = uv.x();
    e.v = uv.y();
    out.push_back(e);
  }
  write_output("-", formats::write_landmarks(out));
  return 0;
}

}  // namespace fest::facefit_tool

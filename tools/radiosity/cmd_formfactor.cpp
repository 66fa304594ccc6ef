// radiosity formfactor: F_AB and F_BA of two polygons, each a one-face mesh file.

#include <fmt/format.h>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/threads.hpp"
#include "formats/detect.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "radiosity/form_factors.hpp"

namespace fest::radiosity_tool {
namespace {

// One planar polygon of 3 or 4 corners from a mesh file.
radiosity::Polygon read_polygon(const std::string& path) {
  const Mesh mesh = formats::parse(formats::load_input(path), formats::read_mesh);
  if (mesh.n_faces() != 1) throw bad_input("expected one polygon, found {} faces ({})", mesh.n_faces(), path);
  radiosity::Polygon p;
  for (auto vh : mesh.fv_range(*mesh.faces().begin())) {
    if (p.n == 4) throw bad_input("the polygon has more than 4 corners ({})", path);
    const auto& q = mesh.point(vh);
    p.p[p.n++] = Eigen::Vector3d(q[0], q[1], q[2]);
  }
  if (!(p.area() > 0)) throw bad_input("the polygon has zero area ({})", path);
  return p;
}

}  // namespace

int run_formfactor(const FormFactorArgs& args) {
  radiosity::FormFactorOptions o;
  o.engine = args.ff;
  if (o.engine == radiosity::Engine::hemicube && (args.hemicube_res < 2 || args.hemicube_res % 2 != 0))
    throw usage_error("--hemicube-res must be even and at least 2");
  o.hemicube_res = args.hemicube_res;
  o.samples = args.samples;
  o.threads = resolve_threads(args.threads);
  const radiosity::Polygon a = read_polygon(args.a), b = read_polygon(args.b);
  const double fab = radiosity::polygon_form_factor(a, b, o, args.cells);
  const double fba = radiosity::polygon_form_factor(b, a, o, args.cells);
  write_output("-", fmt::format("{{\"F_AB\": {:.9g}, \"F_BA\": {:.9g}, \"area_A\": {:.9g}, \"area_B\": {:.9g}}}\n", fab,
                                fba, a.area(), b.area()));
  return 0;
}

}  // namespace fest::radiosity_tool

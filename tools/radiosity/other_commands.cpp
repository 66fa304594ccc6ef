// radiosity cornell, formfactor and render.

#include <cmath>

#include <fmt/format.h>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/threads.hpp"
#include "formats/detect.hpp"
#include "formats/image/image_io.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "radiosity/cornell.hpp"
#include "radiosity/form_factors.hpp"
#include "radiosity/scene_json.hpp"
#include "view.hpp"

namespace fest::radiosity_tool {
namespace {

// One planar polygon of 3 or 4 corners from a mesh file.
radiosity::Polygon read_polygon(const std::string& path) {
  const std::string bytes = read_input(path);
  Mesh mesh;
  try {
    mesh = formats::read_mesh(bytes, formats::detect_format(bytes, path));
  } catch (const Error& e) {
    throw Error(e.status(), with_location(e.what(), path));
  }
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

int run_cornell(const CornellArgs& args) {
  write_output(args.output, radiosity::encode_scene_json(radiosity::cornell_box(!args.no_blocks)));
  return 0;
}

int run_formfactor(const FormFactorArgs& args) {
  radiosity::FormFactorOptions o;
  if (args.ff == "hemicube") o.engine = radiosity::Engine::hemicube;
  else if (args.ff == "raycast") o.engine = radiosity::Engine::raycast;
  else if (args.ff == "analytic") o.engine = radiosity::Engine::analytic;
  else if (args.ff == "hybrid") o.engine = radiosity::Engine::hybrid;
  else throw usage_error("--ff must be hemicube, hybrid, raycast or analytic, not '{}'", args.ff);
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

int run_render(const RenderArgs& args) {
  const std::string bytes = read_input(args.input);
  const std::string where = is_stdio(args.input) ? "standard input" : args.input;
  Mesh mesh;
  try {
    const formats::Format f = formats::detect_format(bytes, where);
    if (formats::kind_of(f) != formats::Kind::mesh) throw bad_input("not a mesh");
    mesh = formats::read_mesh(bytes, f);
  } catch (const Error& e) {
    throw Error(e.status(), with_location(e.what(), where));
  }
  if (!mesh.has_vertex_colors()) throw bad_input("the mesh has no vertex colours to show ({})", where);
  ViewMesh vm;
  for (auto vh : mesh.vertices()) {
    const auto& p = mesh.point(vh);
    const auto& c = mesh.color(vh);
    vm.positions.emplace_back(p[0], p[1], p[2]);
    vm.values.emplace_back(c[0] / 255.0, c[1] / 255.0, c[2] / 255.0);
  }
  for (auto fh : mesh.faces()) {
    std::vector<std::uint32_t> f;
    for (auto vh : mesh.fv_range(fh)) f.push_back(static_cast<std::uint32_t>(vh.idx()));
    for (std::size_t j = 1; j + 1 < f.size(); ++j) vm.triangles.push_back({f[0], f[j], f[j + 1]});
  }
  const Image img = to_display(render_values(vm, args.camera, resolve_threads(args.threads)), 1.0, 1.0);
  write_output(args.output, formats::write_image(img, formats::Format::png));
  return 0;
}

}  // namespace fest::radiosity_tool

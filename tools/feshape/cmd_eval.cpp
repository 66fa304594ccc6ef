// feshape eval: distances of data points to a mesh (the statistics of seed Tables 1-2).
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/threads.hpp"
#include "feshape/assignment.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "points_input.hpp"

namespace fest::feshape_tool {

int run_eval(const EvalArgs& a) {
  if (a.points.empty()) throw usage_error("eval needs --points");
  const std::vector<Eigen::Vector3d> points = read_points(a.points, a.in_format);
  const formats::Input in = formats::load_input(a.input);
  if (formats::kind_of(in.format) != formats::Kind::mesh)
    throw bad_input("{}", with_location(fmt::format("{} is not a mesh", formats::format_name(in.format)), in.name));
  const Mesh mesh = formats::parse(in, formats::read_mesh);
  std::vector<Eigen::Vector3d> x;
  for (const auto v : mesh.vertices()) x.emplace_back(mesh.point(v)[0], mesh.point(v)[1], mesh.point(v)[2]);
  std::vector<std::array<int, 3>> tris;
  for (const auto f : mesh.faces()) {
    std::vector<int> c;
    for (const auto v : mesh.fv_range(f)) c.push_back(v.idx());
    for (std::size_t i = 1; i + 1 < c.size(); ++i) tris.push_back({c[0], c[i], c[i + 1]});
  }
  if (tris.empty()) throw bad_input("{}", with_location("the mesh has no faces to measure against", in.name));
  const feshape::ErrorStats s = feshape::error_stats(feshape::assign_points(points, x, tris, resolve_threads(a.threads)));
  nlohmann::json r;
  r["count"] = s.count;
  r["nodes"] = x.size();
  r["elements"] = tris.size();
  r["mean"] = s.mean;
  r["max"] = s.max;
  r["std"] = s.std;
  r["var"] = s.var;
  write_output(a.output, r.dump(2) + "\n");
  return 0;
}

}  // namespace fest::feshape_tool

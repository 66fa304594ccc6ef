// fcompare on meshes: counts, topology, vertex-by-vertex and surface distances.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "compare/mesh_compare.hpp"
#include "core/threads.hpp"
#include "core/tool_main.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "measure.hpp"

namespace fest::fcompare_tool {

using namespace fest::formats;
using fest::compare::Metrics;

namespace {

nlohmann::json topology_json(const compare::MeshTopology& t) {
  return {{"vertices", t.vertices},       {"faces", t.faces},
          {"edges", t.edges},             {"isolated_vertices", t.isolated_vertices},
          {"boundary_edges", t.boundary_edges}, {"boundary_loops", t.boundary_loops},
          {"components", t.components},   {"nonmanifold_vertices", t.nonmanifold_vertices},
          {"euler", t.euler},             {"genus", t.genus},
          {"faces_beside_halfedges", t.faces_beside}};
}

// A mesh file as it is: the halfedge mesh, and the faces it could not hold beside it.
Mesh read_mesh_file(const Input& in) {
  Mesh mesh = parse(in, read_mesh);
  for (const std::string& w : read_warnings(mesh)) warn("fcompare", w + " (" + in.name + ")");
  return mesh;
}

}  // namespace

void compare_meshes(const Input& ia, const Input& ib, const CompareOptions& opt, Metrics& m) {
  const Mesh a = read_mesh_file(ia);
  const Mesh b = read_mesh_file(ib);
  const compare::FaceList beside_a = faces_beside(a), beside_b = faces_beside(b);
  const auto ta = compare::mesh_topology(a, beside_a), tb = compare::mesh_topology(b, beside_b);
  m.details["topology_a"] = topology_json(ta);
  m.details["topology_b"] = topology_json(tb);
  // Line and point elements count like faces: a file that lost them differs.
  m.set("line_count_diff",
        std::abs(static_cast<double>(line_segments(a)) - static_cast<double>(line_segments(b))));
  m.set("point_count_diff", std::abs(static_cast<double>(point_count(a)) - static_cast<double>(point_count(b))));
  m.set("vertex_count_diff", std::abs(static_cast<double>(ta.vertices) - static_cast<double>(tb.vertices)));
  m.set("face_count_diff", std::abs(static_cast<double>(ta.faces) - static_cast<double>(tb.faces)));
  m.set("genus_diff", std::abs(static_cast<double>(ta.genus - tb.genus)));
  m.set("boundary_loops_diff",
        std::abs(static_cast<double>(ta.boundary_loops) - static_cast<double>(tb.boundary_loops)));
  m.set("components_diff", std::abs(static_cast<double>(ta.components) - static_cast<double>(tb.components)));
  m.set("nonmanifold_vertices_diff",
        std::abs(static_cast<double>(ta.nonmanifold_vertices) - static_cast<double>(tb.nonmanifold_vertices)));
  // Vertex by vertex only when asked (--ordered): the exact check for round trips that
  // keep vertex order, and meaningless for coders that reorder vertices (Edgebreaker),
  // whose output the surface distances below judge whatever the order.
  if (opt.ordered && a.n_vertices() != b.n_vertices())
    warn("fcompare", "--ordered: the vertex counts differ (" + std::to_string(a.n_vertices()) + " and " +
                         std::to_string(b.n_vertices()) + "), so vertices are not compared by index");
  if (opt.ordered && a.n_vertices() == b.n_vertices()) {
    double worst = 0;
    for (std::size_t i = 0; i < a.n_vertices(); ++i) {
      const auto d = a.point(Mesh::VertexHandle(static_cast<int>(i))) - b.point(Mesh::VertexHandle(static_cast<int>(i)));
      worst = std::max({worst, std::abs(d[0]), std::abs(d[1]), std::abs(d[2])});
    }
    m.set("vertex_max_abs", worst);
  }
  const auto d = compare::surface_distance(a, beside_a, b, beside_b, opt.samples, 1, resolve_threads(opt.threads));
  m.set("hausdorff", d.hausdorff);
  m.set("rms", d.rms);
  m.set("mean", d.mean);
  m.set("max_a_to_b", d.max_a_to_b);
  m.set("max_b_to_a", d.max_b_to_a);
  m.details["samples"] = {d.samples_a, d.samples_b};

  m.family({"hausdorff", "rms", "mean", "max_a_to_b", "max_b_to_a", "vertex_max_abs"});
  require_main(m, "hausdorff", opt);
  if (!opt.ignore_counts) {
    m.require("vertex_count_diff", "<=", 0);
    m.require("face_count_diff", "<=", 0);
    m.require("line_count_diff", "<=", 0);
    m.require("point_count_diff", "<=", 0);
  }
  if (!opt.ignore_topology) {
    for (const char* k : {"genus_diff", "boundary_loops_diff", "components_diff", "nonmanifold_vertices_diff"})
      m.require(k, "<=", 0);
  }
}

}  // namespace fest::fcompare_tool

// lemtrace probes: stream ribbons, tubes and glyphs at the seeds as one mesh (PLY or VTP).

#include "commands.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/threads.hpp"
#include "core/tool_main.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "formats/input.hpp"
#include "formats/mesh/indexed_ply.hpp"
#include "lemtrace/probes.hpp"
#include "trace_inputs.hpp"

namespace fest::lemtrace_tool {
namespace {

// Values of a point array at x: barycentric interpolation in the tet containing x. The
// mesh's vertices must be the dataset's points (no split that adds points).
struct PointArray {
  std::vector<double> values;
  bool ok(const FieldGrid& grid) const { return values.size() == grid.mesh().points.size(); }
  double at(const FieldGrid& grid, const Vec3& x) const {
    const int32_t cell = grid.locator().locate(x);
    if (cell < 0) return std::nan("");
    const TetGeometry g = tet_geometry(grid.mesh(), cell);
    const Eigen::Vector4d b = g.bary(x);
    const Tet& t = grid.mesh().tets[static_cast<std::size_t>(cell)];
    double v = 0;
    for (int k = 0; k < 4; ++k) v += b[k] * values[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
    return v;
  }
};

PointArray point_array(const std::string& path, const std::string& name) {
  const formats::Input in = formats::load_input(path);
  const Dataset ds = formats::parse(in, formats::read_dataset);
  // vtkFieldData::GetArray(name): the first array of that name, when it is numeric.
  const DataArray* arr = nullptr;
  for (const DataArray& candidate : ds.point_data)
    if (candidate.name == name) {
      if (candidate.numeric()) arr = &candidate;
      break;
    }
  if (!arr) throw bad_input("{}", with_location(fmt::format("no point array '{}' to colour by", name), in.name));
  if (arr->components != 1)
    throw bad_input("{}", with_location(fmt::format("point array '{}' has {} components; colour by a scalar", name,
                                                    arr->components), in.name));
  PointArray out;
  out.values.resize(arr->tuples());
  for (std::size_t i = 0; i < arr->tuples(); ++i) out.values[i] = arr->component(i, 0);
  return out;
}

Dataset probe_dataset(const ProbeMesh& mesh) {
  Dataset poly;
  poly.kind = DatasetKind::polydata;
  poly.has_points = true;
  std::vector<float> xyz;
  xyz.reserve(3 * mesh.points.size());
  for (const auto& p : mesh.points)
    for (int k = 0; k < 3; ++k) xyz.push_back(static_cast<float>(p[k]));
  poly.points = DataArray::from_floats("Points", 3, xyz);
  for (const auto& t : mesh.triangles) {
    const int64_t ids[3] = {t[0], t[1], t[2]};
    poly.polys.push_back(ids, 3);
  }
  for (std::size_t k = 0; k < mesh.scalars.size(); ++k) {
    std::vector<float> values;
    values.reserve(mesh.points.size());
    for (std::size_t i = 0; i < mesh.points.size(); ++i) values.push_back(static_cast<float>(mesh.scalars[k][i]));
    poly.point_data.push_back(DataArray::from_floats(mesh.scalar_names[k], 1, values));
  }
  return poly;
}

}  // namespace

int run_probes(const ProbesArgs& a) {
  // PLY (the default) or VTP; --to offers the line formats, of which probes take vtp.
  bool ply = true;
  if (a.trace.to == LineFormat::unset && !is_stdio(a.trace.output)) {
    const auto dot = a.trace.output.find_last_of('.');
    const std::string ext = dot == std::string::npos ? "" : a.trace.output.substr(dot);
    if (ext == ".vtp") ply = false;
    else if (ext != ".ply") throw usage_error("cannot tell the output format from '{}'; use --to ply|vtp", a.trace.output);
  } else if (a.trace.to == LineFormat::vtp) {
    ply = false;
  } else if (a.trace.to != LineFormat::unset) {
    throw usage_error("probes write ply or vtp, not {}", line_format_name(a.trace.to));
  }
  if (!(a.ribbon_width > 0) && !(a.tube_radius > 0) && !a.glyphs)
    throw usage_error("nothing to draw: give --ribbon WIDTH, --tube RADIUS and/or --glyphs");
  if (a.ribbon_width < 0 || a.tube_radius < 0 || a.glyph_scale < 0)
    throw usage_error("--ribbon, --tube and --glyph-scale must not be negative");

  const Seeds seeds = load_seeds(a.trace);
  Loaded loaded = load_grid(a.trace.grid, false);
  const FieldGrid& grid = *loaded.grid;
  TraceOptions o = trace_options(a.trace);
  if (o.method == Method::lem && o.samples_per_cell == 0) o.samples_per_cell = 4;  // smooth ribbons
  const int threads = resolve_threads(a.trace.grid.threads);
  grid.locator();

  PointArray colour;
  const bool by_speed = a.color == "speed";
  if (!by_speed) {
    colour = point_array(a.trace.grid.grid, a.color);
    if (!colour.ok(grid))
      throw bad_input("point array '{}' has {} values for {} mesh points (a split added points); colour by speed",
                      a.color, colour.values.size(), grid.mesh().points.size());
  }
  auto value_at = [&](const Vec3& x) {
    if (!by_speed) return colour.at(grid, x);
    const int32_t cell = grid.locator().locate(x);
    return cell < 0 ? 0.0 : velocity_at(grid, cell, x).norm();
  };

  // Size of the grid, for default glyph and tube sizes.
  Vec3 lo = grid.mesh().points.front(), hi = lo;
  for (const Vec3& p : grid.mesh().points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double extent = (hi - lo).norm();

  ProbeMesh mesh;
  std::size_t ribbons = 0, tubes = 0, glyphs = 0, outside = 0;
  std::vector<Polyline> lines;
  if (a.ribbon_width > 0 || a.tube_radius > 0) lines = trace_all(grid, seeds.x, seeds.t0, o, threads);
  if (a.ribbon_width > 0) {
    std::vector<Vec3> side(seeds.x.size());
    for (std::size_t s = 0; s < seeds.x.size(); ++s) {
      const int32_t cell = grid.locator().locate(seeds.x[s]);
      const Vec3 v = cell < 0 ? Vec3::UnitX() : velocity_at(grid, cell, seeds.x[s]);
      side[s] = seeds.x[s] + a.ribbon_width * perpendicular(v);
    }
    const std::vector<Polyline> neighbours = trace_all(grid, side, seeds.t0, o, threads);
    for (std::size_t s = 0; s < lines.size(); ++s) {
      const auto edges = ribbon_edges(lines[s], neighbours[s]);
      // Half the streamwise vorticity on the main line: the rate the twist should have.
      std::vector<double> rate;
      for (const auto& e : edges) {
        const int32_t cell = grid.locator().locate(e.a);
        double r = 0;
        if (cell >= 0) {
          const TetGeometry g = tet_geometry(grid.mesh(), cell);
          Mat3 A;
          Vec3 b;
          linear_field(g, A, b);
          r = 0.5 * streamwise_vorticity(A, A * e.a + b);
        }
        rate.push_back(r);
      }
      if (edges.size() >= 2) ++ribbons;
      append_ribbon(mesh, edges, "half_streamwise_vorticity", rate);
    }
  }
  if (a.tube_radius > 0) {
    for (const Polyline& l : lines) {
      std::vector<double> values;
      for (const Vec3& x : l.x) values.push_back(value_at(x));
      if (l.x.size() >= 2) ++tubes;
      append_tube(mesh, l, a.tube_radius, a.sides, a.color, values);
    }
  }
  if (a.glyphs) {
    const double scale = a.glyph_scale > 0 ? a.glyph_scale : 0.1 * extent / std::max(grid.max_speed(), 1e-300);
    for (const Vec3& x : seeds.x) {
      const int32_t cell = grid.locator().locate(x);
      if (cell < 0) {
        ++outside;
        continue;
      }
      const Vec3 v = velocity_at(grid, cell, x);
      const double len = scale * v.norm();
      if (!(len > 0)) {
        ++outside;
        continue;
      }
      append_arrow(mesh, x, v, len, 0.06 * len, a.sides, a.color, value_at(x));
      ++glyphs;
    }
  }
  for (auto& s : mesh.scalars) s.resize(mesh.points.size(), 0.0);

  std::string bytes;
  if (ply) {
    std::vector<float> xyz;
    xyz.reserve(3 * mesh.points.size());
    for (const Vec3& p : mesh.points)
      for (int k = 0; k < 3; ++k) xyz.push_back(static_cast<float>(p[k]));
    std::vector<std::vector<float>> sc;
    for (const auto& s : mesh.scalars) sc.emplace_back(s.begin(), s.end());
    bytes = formats::write_indexed_ply(xyz, mesh.triangles, mesh.scalar_names, sc);
  } else {
    bytes = formats::write_dataset(probe_dataset(mesh), formats::Format::vtp);
  }
  write_output(a.trace.output, bytes);
  if (outside > 0) warn("lemtrace", fmt::format("{} seeds outside the grid or at rest got no glyph", outside));
  if (!a.trace.report.empty()) {
    nlohmann::json r = {{"seeds", seeds.x.size()}, {"ribbons", ribbons}, {"tubes", tubes}, {"glyphs", glyphs},
                        {"seeds_without_glyph", outside}, {"vertices", mesh.points.size()},
                        {"triangles", mesh.triangles.size()}, {"scalars", mesh.scalar_names}};
    write_output(a.trace.report, r.dump(2) + "\n");
  }
  return 0;
}

}  // namespace fest::lemtrace_tool

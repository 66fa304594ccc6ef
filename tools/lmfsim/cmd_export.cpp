// lmfsim export: per-frame meshes of a trajectory (every body's shape placed by its
// pose), as VTK PolyData with a ParaView .pvd time series, or one OBJ/PLY per frame.
#include <cmath>
#include <filesystem>
#include <map>

#include <fmt/format.h>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"
#include "core/mesh.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "trajectory_csv.hpp"

namespace fest::lmfsim_tool {

using namespace fest::lmfsim;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Tess {
  std::vector<Vec3> v;
  std::vector<std::array<int, 3>> t;
};

// Cylinder of radius r and length l along local z (closed with two fans).
Tess cylinder(double r, double l, int seg = 16) {
  Tess m;
  for (int i = 0; i < seg; ++i) {
    const double a = 2 * kPi * i / seg;
    m.v.emplace_back(r * std::cos(a), r * std::sin(a), -l / 2);
    m.v.emplace_back(r * std::cos(a), r * std::sin(a), l / 2);
  }
  const int c0 = static_cast<int>(m.v.size());
  m.v.emplace_back(0, 0, -l / 2);
  m.v.emplace_back(0, 0, l / 2);
  for (int i = 0; i < seg; ++i) {
    const int j = (i + 1) % seg;
    m.t.push_back({2 * i, 2 * j, 2 * j + 1});
    m.t.push_back({2 * i, 2 * j + 1, 2 * i + 1});
    m.t.push_back({c0, 2 * j, 2 * i});
    m.t.push_back({c0 + 1, 2 * i + 1, 2 * j + 1});
  }
  return m;
}

Tess sphere(double r, int nu = 16, int nv = 8) {
  Tess m;
  m.v.emplace_back(0, 0, r);
  for (int j = 1; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double th = kPi * j / nv, ph = 2 * kPi * i / nu;
      m.v.emplace_back(r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph), r * std::cos(th));
    }
  m.v.emplace_back(0, 0, -r);
  const int south = static_cast<int>(m.v.size()) - 1;
  auto id = [&](int j, int i) { return 1 + (j - 1) * nu + (i % nu); };
  for (int i = 0; i < nu; ++i) {
    m.t.push_back({0, id(1, i), id(1, i + 1)});
    m.t.push_back({south, id(nv - 1, i + 1), id(nv - 1, i)});
    for (int j = 1; j + 1 < nv; ++j) {
      m.t.push_back({id(j, i), id(j + 1, i), id(j + 1, i + 1)});
      m.t.push_back({id(j, i), id(j + 1, i + 1), id(j, i + 1)});
    }
  }
  return m;
}

Tess box(const Vec3& s) {
  Tess m;
  for (int k = 0; k < 8; ++k)
    m.v.emplace_back((k & 1 ? 0.5 : -0.5) * s.x(), (k & 2 ? 0.5 : -0.5) * s.y(), (k & 4 ? 0.5 : -0.5) * s.z());
  const int f[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : f) {
    m.t.push_back({q[0], q[1], q[2]});
    m.t.push_back({q[0], q[2], q[3]});
  }
  return m;
}

Tess tessellate(const Body& b) {
  switch (b.shape.kind) {
    case Shape::Kind::box: return box(b.shape.dims);
    case Shape::Kind::sphere: return sphere(b.shape.dims.x());
    case Shape::Kind::cylinder: return cylinder(b.shape.dims.x(), b.shape.dims.y());
    case Shape::Kind::rod: {
      Tess m = cylinder(0.01 * b.shape.dims.x(), b.shape.dims.x());
      for (Vec3& v : m.v) v = Vec3(v.z(), v.y(), -v.x());  // local z -> local x
      for (auto& t : m.t) std::swap(t[1], t[2]);          // keep outward orientation
      return m;
    }
    case Shape::Kind::mesh: return {b.shape.vertices, b.shape.triangles};
    case Shape::Kind::none: break;
  }
  return sphere(0.02);  // particles and shapeless bodies: a small marker
}

}  // namespace

int cmd_export(const ExportOptions& opt) {
  const int outputs = !opt.vtk.empty() + !opt.obj.empty() + !opt.ply.empty();
  if (outputs != 1) throw fest::usage_error("export: give exactly one of --vtk, --obj, --ply");
  if (opt.scene.empty()) throw fest::usage_error("export: --scene is required");
  const Scene sc = load_scene(fest::read_input(opt.scene));
  const auto rows = parse_trajectory(fest::read_input(opt.trajectory), fest::input_name(opt.trajectory));
  std::map<std::string, int> index;
  std::vector<Tess> shapes;
  for (std::size_t i = 0; i < sc.bodies.size(); ++i) {
    index[sc.bodies[i].name] = static_cast<int>(i);
    shapes.push_back(tessellate(sc.bodies[i]));
  }
  // Group rows by frame (rows of one frame are contiguous).
  std::vector<std::pair<double, std::vector<const TrajectoryRow*>>> frames;
  for (const TrajectoryRow& r : rows) {
    if (!index.count(r.body)) throw fest::bad_input("trajectory names body '{}' that the scene lacks", r.body);
    if (frames.empty() || static_cast<long>(frames.size()) - 1 != r.frame) {
      if (r.frame != static_cast<long>(frames.size())) throw fest::bad_input("trajectory frames out of order at frame {}", r.frame);
      frames.push_back({r.t, {}});
    }
    frames.back().second.push_back(&r);
  }
  const std::string dir = !opt.vtk.empty() ? opt.vtk : (!opt.obj.empty() ? opt.obj : opt.ply);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw fest::io_error("cannot create folder '{}': {}", dir, ec.message());
  std::string pvd = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (std::size_t f = 0; f < frames.size(); ++f) {
    std::vector<Vec3> verts;
    std::vector<std::array<int, 3>> tris;
    std::vector<int> tri_body;
    for (const TrajectoryRow* r : frames[f].second) {
      const int b = index[r->body];
      const Tess& s = shapes[static_cast<std::size_t>(b)];
      const int base = static_cast<int>(verts.size());
      const Mat3 R = r->q.normalized().toRotationMatrix();
      for (const Vec3& v : s.v) verts.push_back(r->p + R * v);
      for (const auto& t : s.t) {
        tris.push_back({base + t[0], base + t[1], base + t[2]});
        tri_body.push_back(b);
      }
    }
    const std::string stem = fmt::format("frame_{:06d}", f);
    if (!opt.vtk.empty()) {
      fest::Dataset poly;
      poly.kind = fest::DatasetKind::polydata;
      poly.has_points = true;
      std::vector<double> xyz;
      xyz.reserve(3 * verts.size());
      for (const Vec3& v : verts) xyz.insert(xyz.end(), {v.x(), v.y(), v.z()});
      poly.points = fest::DataArray::from_doubles("Points", 3, xyz);
      for (const auto& t : tris) {
        const int64_t ids[3] = {t[0], t[1], t[2]};
        poly.polys.push_back(ids, 3);
      }
      poly.cell_data.push_back(fest::DataArray::from_ints("body", 1, std::vector<int64_t>(tri_body.begin(), tri_body.end()),
                                                          fest::vtk_type::int_));
      fest::write_output(dir + "/" + stem + ".vtp", fest::formats::write_dataset(poly, fest::formats::Format::vtp));
      pvd += fmt::format("    <DataSet timestep=\"{:.9g}\" part=\"0\" file=\"{}.vtp\"/>\n", frames[f].first, stem);
    } else {
      fest::Mesh mesh;
      for (const Vec3& v : verts) mesh.add_vertex(fest::Mesh::Point(v.x(), v.y(), v.z()));
      for (const auto& t : tris)
        mesh.add_face(fest::Mesh::VertexHandle(t[0]), fest::Mesh::VertexHandle(t[1]), fest::Mesh::VertexHandle(t[2]));
      const bool obj = !opt.obj.empty();
      fest::write_output(dir + "/" + stem + (obj ? ".obj" : ".ply"),
                         fest::formats::write_mesh(mesh, obj ? fest::formats::Format::obj : fest::formats::Format::ply));
    }
  }
  if (!opt.vtk.empty()) {
    pvd += "  </Collection>\n</VTKFile>\n";
    fest::write_output(dir + "/scene.pvd", pvd);
  }
  return 0;
}

}  // namespace fest::lmfsim_tool

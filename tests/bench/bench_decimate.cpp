// decimate against the anchors of its issue, in the same run: meshoptimizer's
// meshopt_simplify, OpenMesh's Decimater (ModQuadric) and CGAL's edge_collapse with
// Garland-Heckbert plane policies. Every result is measured by fcompare's metric
// (fest::compare::surface_distance: symmetric Hausdorff and RMS over the vertices and
// 100k area-weighted samples of each surface), never by a simplifier's own estimate.
//
//   bench_decimate MESH... [--ratios 0.1,0.02] [--threads N]
// One JSON line per (mesh, ratio, method).

#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/mesh_compare.hpp"
#include "core/tool_main.hpp"
#include "decimate/simplify.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"

#ifdef FEST_HAVE_MESHOPT
#include <meshoptimizer.h>
#endif
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#ifdef FEST_HAVE_CGAL
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#endif

namespace {

using namespace fest;
using Clock = std::chrono::steady_clock;

// CPU time of this thread: every method here is single-threaded, and on a shared, loaded
// machine wall time measures the neighbours more than the method.
double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return 1e3 * static_cast<double>(ts.tv_sec) + 1e-6 * static_cast<double>(ts.tv_nsec);
}

struct Soup {
  std::vector<double> xyz;
  std::vector<unsigned> tri;
};

Soup to_soup(const Mesh& m) {
  Soup s;
  for (const auto v : m.vertices())
    for (int i = 0; i < 3; ++i) s.xyz.push_back(m.point(v)[i]);
  for (const auto f : m.faces()) {
    std::vector<unsigned> c;
    for (const auto v : m.fv_range(f)) c.push_back(static_cast<unsigned>(v.idx()));
    for (std::size_t i = 1; i + 1 < c.size(); ++i) s.tri.insert(s.tri.end(), {c[0], c[i], c[i + 1]});
  }
  return s;
}

// Only the vertices the triangles use (the metric samples every vertex).
Mesh from_soup(const std::vector<double>& xyz, const std::vector<unsigned>& tri) {
  Mesh m;
  std::vector<int> map(xyz.size() / 3, -1);
  std::vector<Mesh::VertexHandle> vh;
  for (std::size_t t = 0; t + 2 < tri.size(); t += 3) {
    Mesh::VertexHandle c[3];
    for (int k = 0; k < 3; ++k) {
      const unsigned v = tri[t + static_cast<std::size_t>(k)];
      if (map[v] < 0) {
        map[v] = static_cast<int>(vh.size());
        vh.push_back(m.add_vertex(OpenMesh::Vec3d(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2])));
      }
      c[k] = vh[static_cast<std::size_t>(map[v])];
    }
    m.add_face(c[0], c[1], c[2]);  // a face OpenMesh refuses is dropped (counted below)
  }
  return m;
}

struct Result {
  Mesh mesh;
  double ms = 0;      // wall time of the simplification call(s) alone
  double cpu_ms = 0;  // this thread's CPU time over the same span
  std::size_t faces = 0;
};

Result run_fest(const Mesh& in, std::size_t target, decimate::Weighting weighting) {
  decimate::SimplifyOptions o;
  o.target_faces = target;
  o.weighting = weighting;
  o.use_normals = o.use_colors = o.use_texcoords = false;
  const auto t0 = Clock::now();
  const double c0 = thread_cpu_ms();
  Result r;
  r.mesh = decimate::simplify(in, o);
  r.ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  r.cpu_ms = thread_cpu_ms() - c0;
  r.faces = r.mesh.n_faces();
  return r;
}

#ifdef FEST_HAVE_MESHOPT
Result run_meshopt(const Soup& s, std::size_t target) {
  std::vector<float> pos(s.xyz.begin(), s.xyz.end());
  std::vector<unsigned> out(s.tri.size());
  const auto t0 = Clock::now();
  const double c0 = thread_cpu_ms();
  float err = 0;
  const std::size_t n = meshopt_simplify(out.data(), s.tri.data(), s.tri.size(), pos.data(), pos.size() / 3,
                                         3 * sizeof(float), 3 * target, 1.0f, 0, &err);
  Result r;
  r.ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  r.cpu_ms = thread_cpu_ms() - c0;
  out.resize(n);
  r.faces = n / 3;
  r.mesh = from_soup(s.xyz, out);
  return r;
}
#endif

Result run_openmesh(const Mesh& in, std::size_t target) {
  TriMesh m;
  for (const auto v : in.vertices()) m.add_vertex(in.point(v));
  for (const auto f : in.faces()) {
    std::vector<TriMesh::VertexHandle> c;
    for (const auto v : in.fv_range(f)) c.push_back(TriMesh::VertexHandle(v.idx()));
    m.add_face(c);
  }
  const auto t0 = Clock::now();
  const double c0 = thread_cpu_ms();
  OpenMesh::Decimater::DecimaterT<TriMesh> dec(m);
  OpenMesh::Decimater::ModQuadricT<TriMesh>::Handle hq;
  dec.add(hq);
  dec.initialize();
  dec.decimate_to_faces(0, target);
  m.garbage_collection();
  Result r;
  r.ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  r.cpu_ms = thread_cpu_ms() - c0;
  for (const auto v : m.vertices()) r.mesh.add_vertex(m.point(v));
  for (const auto f : m.faces()) {
    std::vector<Mesh::VertexHandle> c;
    for (const auto v : m.fv_range(f)) c.push_back(Mesh::VertexHandle(v.idx()));
    r.mesh.add_face(c);
  }
  r.faces = r.mesh.n_faces();
  return r;
}

#ifdef FEST_HAVE_CGAL
Result run_cgal(const Soup& s, std::size_t target) {
  using K = CGAL::Simple_cartesian<double>;
  using SM = CGAL::Surface_mesh<K::Point_3>;
  namespace SMS = CGAL::Surface_mesh_simplification;
  SM sm;
  std::vector<SM::Vertex_index> vi;
  for (std::size_t i = 0; i < s.xyz.size(); i += 3) vi.push_back(sm.add_vertex(K::Point_3(s.xyz[i], s.xyz[i + 1], s.xyz[i + 2])));
  for (std::size_t t = 0; t < s.tri.size(); t += 3) sm.add_face(vi[s.tri[t]], vi[s.tri[t + 1]], vi[s.tri[t + 2]]);
  const auto t0 = Clock::now();
  const double c0 = thread_cpu_ms();
  SMS::Count_stop_predicate<SM> stop(target * 3 / 2);  // edges of a closed mesh with `target` faces
  SMS::GarlandHeckbert_plane_policies<SM, K> gh(sm);
  SMS::edge_collapse(sm, stop, CGAL::parameters::get_cost(gh.get_cost()).get_placement(gh.get_placement()));
  sm.collect_garbage();
  Result r;
  r.ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  r.cpu_ms = thread_cpu_ms() - c0;
  std::vector<double> xyz;
  std::vector<unsigned> tri;
  for (const auto v : sm.vertices()) {
    const auto& p = sm.point(v);
    xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  }
  for (const auto f : sm.faces())
    for (const auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) tri.push_back(static_cast<unsigned>(v.idx()));
  r.mesh = from_soup(xyz, tri);
  r.faces = tri.size() / 3;
  return r;
}
#endif

}  // namespace

int main(int argc, char** argv) {
  return run_tool("bench_decimate", [&] {
    std::vector<std::string> meshes;
    std::vector<double> ratios = {0.1, 0.02};
    int threads = 2;
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--ratios" && i + 1 < argc) {
        ratios.clear();
        std::stringstream ss(argv[++i]);
        std::string x;
        while (std::getline(ss, x, ',')) ratios.push_back(std::stod(x));
      } else if (a == "--threads" && i + 1 < argc) {
        threads = std::atoi(argv[++i]);
      } else {
        meshes.push_back(a);
      }
    }
    for (const std::string& path : meshes) {
      const formats::Input in = formats::load_input(path);
      const Mesh mesh = formats::parse(in, formats::read_mesh);
      const Soup soup = to_soup(mesh);
      OpenMesh::Vec3d lo(1e300), hi(-1e300);
      for (const auto v : mesh.vertices()) { lo.minimize(mesh.point(v)); hi.maximize(mesh.point(v)); }
      const double diag = (hi - lo).norm();
      for (const double ratio : ratios) {
        const std::size_t target = static_cast<std::size_t>(ratio * static_cast<double>(mesh.n_faces()));
        std::vector<std::pair<std::string, std::function<Result()>>> methods;
        methods.push_back({"fest", [&] { return run_fest(mesh, target, decimate::Weighting::sqrt_area); }});
        methods.push_back({"fest-area", [&] { return run_fest(mesh, target, decimate::Weighting::area); }});
#ifdef FEST_HAVE_MESHOPT
        methods.push_back({"meshoptimizer", [&] { return run_meshopt(soup, target); }});
#endif
        methods.push_back({"openmesh", [&] { return run_openmesh(mesh, target); }});
#ifdef FEST_HAVE_CGAL
        methods.push_back({"cgal", [&] { return run_cgal(soup, target); }});
#endif
        for (auto& [name, fn] : methods) {
          const Result r = fn();
          const compare::SurfaceDistance d = compare::surface_distance(mesh, r.mesh, 100000, 1, threads);
          nlohmann::json j;
          j["mesh"] = path.substr(path.find_last_of('/') + 1);
          j["input_faces"] = mesh.n_faces();
          j["ratio"] = ratio;
          j["target_faces"] = target;
          j["method"] = name;
          j["faces"] = r.faces;
          j["faces_kept"] = r.mesh.n_faces();
          j["hausdorff"] = d.hausdorff;
          j["rms"] = d.rms;
          j["hausdorff_rel"] = d.hausdorff / diag;
          j["rms_rel"] = d.rms / diag;
          j["ms"] = r.ms;
          j["cpu_ms"] = r.cpu_ms;
          std::printf("%s\n", j.dump().c_str());
          std::fflush(stdout);
        }
      }
    }
    return 0;
  });
}

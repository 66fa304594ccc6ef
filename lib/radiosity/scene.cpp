#include "radiosity/scene.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "core/error.hpp"

namespace fest::radiosity {
namespace {

bool finite(const Rgb& c) { return std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]); }

double face_area(const SceneObject& o, const std::vector<std::uint32_t>& f) {
  Eigen::Vector3d s = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < f.size(); ++k) s += o.vertices[f[k]].cross(o.vertices[f[(k + 1) % f.size()]]);
  return 0.5 * s.norm();
}

// The corners of one input face as polygons of 3 or 4 corners: planar convex quads stay
// quads, everything else becomes a triangle fan.
std::vector<Polygon> face_polygons(const SceneObject& o, const std::vector<std::uint32_t>& f) {
  std::vector<Polygon> out;
  if (f.size() == 4) {
    Polygon q;
    q.n = 4;
    for (int k = 0; k < 4; ++k) q.p[k] = o.vertices[f[k]];
    const Eigen::Vector3d n = q.normal();
    bool convex = n.squaredNorm() > 0;
    for (int k = 0; k < 4 && convex; ++k) {
      const Eigen::Vector3d c = (q.p[(k + 1) % 4] - q.p[k]).cross(q.p[(k + 2) % 4] - q.p[(k + 1) % 4]);
      if (c.dot(n) <= 0) convex = false;
    }
    double off = 0;
    const Eigen::Vector3d c = q.centroid();
    for (int k = 0; k < 4; ++k) off = std::max(off, std::abs((q.p[k] - c).dot(n)));
    // Slightly warped quads (the Cornell box walls are off by millimetres) stay quads.
    if (convex && off <= 1e-2 * q.longest_edge()) {
      out.push_back(q);
      return out;
    }
  }
  for (std::size_t k = 1; k + 1 < f.size(); ++k) {
    Polygon t;
    t.n = 3;
    t.p[0] = o.vertices[f[0]];
    t.p[1] = o.vertices[f[k]];
    t.p[2] = o.vertices[f[k + 1]];
    if (t.area() > 0) out.push_back(t);
  }
  return out;
}

}  // namespace

SceneCheck check_scene(const Scene& scene) {
  SceneCheck check;
  if (scene.objects.empty()) throw bad_input("scene has no objects");
  bool emitter = false;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  std::size_t zero_area = 0;
  std::string zero_area_object;
  std::map<std::tuple<double, double, double, double, double, double>, int> edges;
  for (const SceneObject& o : scene.objects) {
    if (!finite(o.reflectance)) throw bad_input("object '{}': reflectance is not a finite number", o.name);
    if (!finite(o.emission)) throw bad_input("object '{}': emission is not a finite number", o.name);
    if ((o.reflectance < 0).any() || (o.reflectance > 0.999).any())
      throw bad_input("object '{}': reflectance ({}, {}, {}) outside [0, 0.999] (rho >= 1 never converges)", o.name,
                      o.reflectance[0], o.reflectance[1], o.reflectance[2]);
    if ((o.emission < 0).any())
      throw bad_input("object '{}': negative emission ({}, {}, {})", o.name, o.emission[0], o.emission[1],
                      o.emission[2]);
    for (std::size_t v = 0; v < o.vertices.size(); ++v) {
      if (!o.vertices[v].allFinite()) throw bad_input("object '{}': vertex {} is not finite", o.name, v);
      lo = lo.cwiseMin(o.vertices[v]);
      hi = hi.cwiseMax(o.vertices[v]);
    }
    for (std::size_t f = 0; f < o.faces.size(); ++f) {
      const auto& face = o.faces[f];
      if (face.size() < 3) throw bad_input("object '{}': face {} has {} corners (at least 3)", o.name, f, face.size());
      for (std::uint32_t i : face)
        if (i >= o.vertices.size())
          throw bad_input("object '{}': face {} names vertex {} of {}", o.name, f, i, o.vertices.size());
      if (!(face_area(o, face) > 0)) {
        if (zero_area++ == 0) zero_area_object = o.name;
        continue;
      }
      ++check.faces;
      for (std::size_t k = 0; k < face.size(); ++k) {
        const Eigen::Vector3d& a = o.vertices[face[k]];
        const Eigen::Vector3d& b = o.vertices[face[(k + 1) % face.size()]];
        auto key = std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3)
                       ? std::make_tuple(a.x(), a.y(), a.z(), b.x(), b.y(), b.z())
                       : std::make_tuple(b.x(), b.y(), b.z(), a.x(), a.y(), a.z());
        ++edges[key];
      }
    }
    if ((o.emission > 0).any() && !o.faces.empty()) emitter = true;
  }
  if (zero_area > 0)
    throw bad_input("{} zero-area face{} (the first in object '{}'); remove them", zero_area,
                    zero_area == 1 ? "" : "s", zero_area_object);
  if (check.faces == 0) throw bad_input("scene has no faces");
  if (!emitter) throw bad_input("scene has no emitter (every emission is zero): all radiosity would be 0");
  for (const auto& [key, count] : edges)
    if (count == 1) ++check.open_edges;
  check.diagonal = (hi - lo).norm();
  return check;
}

std::vector<Polygon> split_in_four(const Polygon& q) {
  std::vector<Polygon> out(4);
  if (q.n == 4) {
    const Eigen::Vector3d m01 = 0.5 * (q.p[0] + q.p[1]), m12 = 0.5 * (q.p[1] + q.p[2]);
    const Eigen::Vector3d m23 = 0.5 * (q.p[2] + q.p[3]), m30 = 0.5 * (q.p[3] + q.p[0]);
    const Eigen::Vector3d c = 0.25 * (q.p[0] + q.p[1] + q.p[2] + q.p[3]);
    const Eigen::Vector3d corners[4][4] = {
        {q.p[0], m01, c, m30}, {m01, q.p[1], m12, c}, {c, m12, q.p[2], m23}, {m30, c, m23, q.p[3]}};
    for (int k = 0; k < 4; ++k) {
      out[k].n = 4;
      for (int j = 0; j < 4; ++j) out[k].p[j] = corners[k][j];
    }
    return out;
  }
  const Eigen::Vector3d m01 = 0.5 * (q.p[0] + q.p[1]), m12 = 0.5 * (q.p[1] + q.p[2]), m20 = 0.5 * (q.p[2] + q.p[0]);
  const Eigen::Vector3d corners[4][3] = {{q.p[0], m01, m20}, {m01, q.p[1], m12}, {m20, m12, q.p[2]}, {m01, m12, m20}};
  for (int k = 0; k < 4; ++k) {
    out[k].n = 3;
    for (int j = 0; j < 3; ++j) out[k].p[j] = corners[k][j];
  }
  return out;
}

std::vector<Polygon> split_polygon(const Polygon& poly, double size) {
  std::vector<Polygon> out;
  if (!(size > 0) || poly.longest_edge() <= size) return {poly};
  if (poly.n == 4) {
    const double lu = std::max((poly.p[1] - poly.p[0]).norm(), (poly.p[2] - poly.p[3]).norm());
    const double lv = std::max((poly.p[3] - poly.p[0]).norm(), (poly.p[2] - poly.p[1]).norm());
    const int nu = std::max(1, static_cast<int>(std::ceil(lu / size - 1e-9)));
    const int nv = std::max(1, static_cast<int>(std::ceil(lv / size - 1e-9)));
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i) {
        Polygon q;
        q.n = 4;
        const double s0 = double(i) / nu, s1 = double(i + 1) / nu, t0 = double(j) / nv, t1 = double(j + 1) / nv;
        q.p[0] = poly.sample(s0, t0);
        q.p[1] = poly.sample(s1, t0);
        q.p[2] = poly.sample(s1, t1);
        q.p[3] = poly.sample(s0, t1);
        out.push_back(q);
      }
    return out;
  }
  std::vector<Polygon> level{poly};
  while (level.front().longest_edge() > size) {
    std::vector<Polygon> next;
    for (const Polygon& t : level)
      for (const Polygon& c : split_in_four(t)) next.push_back(c);
    level.swap(next);
  }
  return level;
}

Model build_model(const Scene& scene, const MeshingOptions& options) {
  const SceneCheck check = check_scene(scene);
  Model m;
  m.diagonal = check.diagonal > 0 ? check.diagonal : 1;
  double patch = options.patch_size > 0 ? options.patch_size : scene.patch_size > 0 ? scene.patch_size : m.diagonal / 12;
  double element = options.element_size > 0   ? options.element_size
                   : scene.element_size > 0 && options.patch_size <= 0 ? scene.element_size
                                                                       : patch / 4;
  if (element > patch) element = patch;
  const double emission_scale = options.emission_is_radiance ? M_PI : 1.0;
  if (!options.no_mesh) {
    // Refuse absurd sizes before allocating: an upper bound of the element count.
    double estimate = 0;
    for (const SceneObject& o : scene.objects)
      for (const auto& f : o.faces)
        for (const Polygon& face : face_polygons(o, f)) {
          const double np = std::ceil(face.longest_edge() / patch) + 1, ne = std::ceil(patch / element) + 1;
          estimate += 4 * np * np * ne * ne;
        }
    if (estimate > 5e7)
      throw bad_input("meshing would make about {:.3g} elements (patch size {:.4g}, element size {:.4g}); use larger sizes",
                      estimate, patch, element);
  }
  for (std::size_t oi = 0; oi < scene.objects.size(); ++oi) {
    const SceneObject& o = scene.objects[oi];
    m.objects.push_back({o.name, o.reflectance, o.emission * emission_scale});
    for (std::size_t f = 0; f < o.faces.size(); ++f) {
      for (const Polygon& face : face_polygons(o, o.faces[f])) {
        m.occluders.push_back(face);
        const std::vector<Polygon> patches = options.no_mesh ? std::vector<Polygon>{face} : split_polygon(face, patch);
        for (const Polygon& pp : patches) {
          Patch pt;
          set_polygon(pt, pp);
          pt.object = static_cast<int>(oi);
          pt.face = static_cast<int>(f);
          pt.rho = o.reflectance;
          pt.E = o.emission * emission_scale;
          const int pid = static_cast<int>(m.patches.size());
          const std::vector<Polygon> elems = options.no_mesh ? std::vector<Polygon>{pp} : split_polygon(pp, element);
          for (const Polygon& ep : elems) {
            Element e;
            set_polygon(e, ep);
            e.patch = pid;
            pt.elements.push_back(static_cast<int>(m.elements.size()));
            m.elements.push_back(e);
          }
          m.patches.push_back(std::move(pt));
        }
      }
    }
  }
  m.reset_solution();
  return m;
}

}  // namespace fest::radiosity

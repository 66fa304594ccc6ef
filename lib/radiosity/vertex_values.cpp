#include "radiosity/vertex_values.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace fest::radiosity {

VertexValues vertex_values(const Model& model, double crease_degrees) {
  VertexValues vv;
  const double q = 1e-7 * model.diagonal;
  const double cos_crease = std::cos(crease_degrees * M_PI / 180.0);
  std::map<std::tuple<int, long long, long long, long long>, std::vector<int>> at;
  std::vector<Rgb> sb, sh;
  std::vector<double> sa;
  std::vector<Eigen::Vector3d> sn;
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Element& el = model.elements[e];
    if (!el.active) continue;
    const int obj = model.patches[el.patch].object;
    std::array<int, 4> corners{-1, -1, -1, -1};
    for (int c = 0; c < el.poly.n; ++c) {
      const Eigen::Vector3d& p = el.poly.p[c];
      auto key = std::make_tuple(obj, std::llround(p.x() / q), std::llround(p.y() / q), std::llround(p.z() / q));
      std::vector<int>& list = at[key];
      int v = -1;
      for (int cand : list)
        if (vv.normal[cand].dot(el.normal) >= cos_crease) {
          v = cand;
          break;
        }
      if (v < 0) {
        v = static_cast<int>(vv.position.size());
        vv.position.push_back(p);
        vv.normal.push_back(el.normal);  // the first element's normal represents the cluster
        vv.object.push_back(obj);
        sb.push_back(Rgb::Zero());
        sh.push_back(Rgb::Zero());
        sa.push_back(0);
        sn.push_back(Eigen::Vector3d::Zero());
        list.push_back(v);
      }
      sb[v] += el.area * el.B;
      sh[v] += el.area * el.H;
      sa[v] += el.area;
      sn[v] += el.area * el.normal;
      corners[c] = v;
    }
    vv.elements.push_back(static_cast<int>(e));
    vv.element_corners.push_back(corners);
  }
  vv.B.resize(sb.size());
  vv.H.resize(sb.size());
  for (std::size_t v = 0; v < sb.size(); ++v) {
    vv.B[v] = sb[v] / sa[v];
    vv.H[v] = sh[v] / sa[v];
    if (sn[v].norm() > 0) vv.normal[v] = sn[v].normalized();
  }
  return vv;
}

std::vector<std::uint8_t> reflector_vertices(const Model& model, const VertexValues& vv) {
  std::vector<std::uint8_t> r(vv.object.size());
  for (std::size_t v = 0; v < r.size(); ++v) r[v] = (model.objects[vv.object[v]].emission == 0).all() ? 1 : 0;
  return r;
}

std::vector<std::array<std::uint8_t, 3>> display_colours(const std::vector<Rgb>& B, double exposure, double* used,
                                                         const std::vector<std::uint8_t>& reflector) {
  double k = exposure;
  if (!(k > 0)) {
    std::vector<double> y;
    for (std::size_t v = 0; v < B.size(); ++v)
      if (reflector.empty() || reflector[v]) y.push_back(luminance(B[v]) / M_PI);
    if (y.empty())
      for (const Rgb& b : B) y.push_back(luminance(b) / M_PI);
    double p99 = 0;
    if (!y.empty()) {
      const std::size_t idx = std::min(y.size() - 1, static_cast<std::size_t>(std::floor(0.99 * (y.size() - 1))));
      std::nth_element(y.begin(), y.begin() + static_cast<long>(idx), y.end());
      p99 = y[idx];
    }
    k = p99 > 0 ? 1.0 / p99 : 1.0;
  }
  if (used) *used = k;
  std::vector<std::array<std::uint8_t, 3>> out(B.size());
  for (std::size_t v = 0; v < B.size(); ++v)
    for (int c = 0; c < 3; ++c) {
      const double l = std::clamp(k * B[v][c] / M_PI, 0.0, 1.0);
      out[v][c] = static_cast<std::uint8_t>(std::lround(255.0 * std::pow(l, 1.0 / 2.2)));
    }
  return out;
}

RadiosityRange radiosity_range(const Model& model) {
  RadiosityRange r;
  r.min = Rgb::Constant(INFINITY);
  r.max = Rgb::Constant(-INFINITY);
  double area = 0;
  for (const Element& el : model.elements) {
    if (!el.active) continue;
    r.min = r.min.min(el.B);
    r.max = r.max.max(el.B);
    r.mean += el.area * el.B;
    area += el.area;
  }
  if (area > 0) r.mean /= area;
  else r.min = r.max = Rgb::Zero();
  return r;
}

}  // namespace fest::radiosity

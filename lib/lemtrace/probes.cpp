#include "lemtrace/probes.hpp"

#include <algorithm>
#include <cmath>

namespace fest::lemtrace {

std::size_t ProbeMesh::scalar(const std::string& name) {
  for (std::size_t i = 0; i < scalar_names.size(); ++i)
    if (scalar_names[i] == name) {
      scalars[i].resize(points.size(), 0.0);
      return i;
    }
  scalar_names.push_back(name);
  scalars.emplace_back(points.size(), 0.0);
  return scalars.size() - 1;
}

bool position_at(const Polyline& line, double t, Vec3& out) {
  const auto& ts = line.t;
  if (ts.empty()) return false;
  const bool forward = ts.back() >= ts.front();
  const double lo = forward ? ts.front() : ts.back(), hi = forward ? ts.back() : ts.front();
  const double eps = 1e-12 * std::max(1.0, std::fabs(hi));
  if (t < lo - eps || t > hi + eps) return false;
  for (std::size_t i = 1; i < ts.size(); ++i) {
    const double t0 = ts[i - 1], t1 = ts[i];
    if ((forward && t <= t1 + eps) || (!forward && t >= t1 - eps)) {
      const double f = t1 == t0 ? 0.0 : std::clamp((t - t0) / (t1 - t0), 0.0, 1.0);
      out = line.x[i - 1] + f * (line.x[i] - line.x[i - 1]);
      return true;
    }
  }
  out = line.x.back();
  return true;
}

Vec3 perpendicular(const Vec3& v) {
  const Vec3 a = v.cwiseAbs();
  Vec3 e = Vec3::UnitX();
  if (a[1] <= a[0] && a[1] <= a[2]) e = Vec3::UnitY();
  if (a[2] < a[0] && a[2] < a[1]) e = Vec3::UnitZ();
  if (a[0] <= a[1] && a[0] <= a[2]) e = Vec3::UnitX();
  const Vec3 p = v.cross(e);
  const double n = p.norm();
  return n > 0 ? Vec3(p / n) : Vec3::UnitX();
}

namespace {

// Tangent of a polyline at point i (central where possible).
Vec3 tangent(const std::vector<Vec3>& x, std::size_t i) {
  const std::size_t a = i > 0 ? i - 1 : i, b = i + 1 < x.size() ? i + 1 : i;
  Vec3 t = x[b] - x[a];
  const double n = t.norm();
  return n > 0 ? Vec3(t / n) : Vec3::UnitZ();
}

// Moves a frame vector from tangent t0 to t1 by the rotation taking t0 to t1 (discrete
// parallel transport, the rotation-minimising frame).
Vec3 transport(const Vec3& n, const Vec3& t0, const Vec3& t1) {
  const Vec3 axis = t0.cross(t1);
  const double s = axis.norm(), c = t0.dot(t1);
  if (s < 1e-15) return n;
  const Vec3 k = axis / s;
  const double angle = std::atan2(s, c);
  return n * std::cos(angle) + k.cross(n) * std::sin(angle) + k * k.dot(n) * (1 - std::cos(angle));
}

}  // namespace

std::vector<RibbonEdge> ribbon_edges(const Polyline& main, const Polyline& neighbour) {
  std::vector<RibbonEdge> out;
  Vec3 frame = Vec3::Zero(), prev_t = Vec3::Zero();
  double twist = 0, prev_angle = 0;
  for (std::size_t i = 0; i < main.x.size(); ++i) {
    Vec3 b;
    if (!position_at(neighbour, main.t[i], b)) break;
    RibbonEdge e;
    e.a = main.x[i];
    e.b = b;
    e.t = main.t[i];
    const Vec3 r = b - e.a;
    e.width = r.norm();
    const Vec3 t = tangent(main.x, i);
    if (out.empty()) {
      frame = r - t * t.dot(r);
      if (frame.norm() < 1e-300) frame = perpendicular(t);
      frame.normalize();
      prev_angle = 0;
    } else {
      frame = transport(frame, prev_t, t);
      frame = (frame - t * t.dot(frame)).normalized();
    }
    // Angle of r about t against the frame, unwrapped into a cumulative twist.
    const double angle = std::atan2(frame.cross(r).dot(t), frame.dot(r));
    double d = angle - prev_angle;
    while (d > M_PI) d -= 2 * M_PI;
    while (d < -M_PI) d += 2 * M_PI;
    if (!out.empty()) twist += d;
    else twist = angle;
    prev_angle = angle;
    prev_t = t;
    e.twist = twist;
    out.push_back(e);
  }
  return out;
}

void append_ribbon(ProbeMesh& mesh, const std::vector<RibbonEdge>& edges, const std::string& extra_name,
                   const std::vector<double>& extra) {
  if (edges.size() < 2) return;
  const auto base = static_cast<uint32_t>(mesh.points.size());
  for (const auto& e : edges) {
    mesh.points.push_back(e.a);
    mesh.points.push_back(e.b);
  }
  const std::size_t w = mesh.scalar("width"), tw = mesh.scalar("twist"), tm = mesh.scalar("time");
  const std::size_t ex = extra_name.empty() ? 0 : mesh.scalar(extra_name);
  for (auto& other : mesh.scalars) other.resize(mesh.points.size(), 0.0);
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (int k = 0; k < 2; ++k) {
      const std::size_t v = base + 2 * i + static_cast<std::size_t>(k);
      mesh.scalars[w][v] = edges[i].width;
      mesh.scalars[tw][v] = edges[i].twist;
      mesh.scalars[tm][v] = edges[i].t;
      if (!extra_name.empty() && i < extra.size()) mesh.scalars[ex][v] = extra[i];
    }
  for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
    const uint32_t a0 = base + static_cast<uint32_t>(2 * i), b0 = a0 + 1, a1 = a0 + 2, b1 = a0 + 3;
    mesh.triangles.push_back({a0, a1, b0});
    mesh.triangles.push_back({b0, a1, b1});
  }
}

void append_tube(ProbeMesh& mesh, const Polyline& line, double radius, int sides, const std::string& name,
                 const std::vector<double>& values) {
  if (line.x.size() < 2 || sides < 3) return;
  const auto base = static_cast<uint32_t>(mesh.points.size());
  Vec3 t = tangent(line.x, 0);
  Vec3 n = perpendicular(t);
  const std::size_t s = mesh.scalar(name);
  for (std::size_t i = 0; i < line.x.size(); ++i) {
    const Vec3 ti = tangent(line.x, i);
    if (i > 0) n = (transport(n, t, ti) - ti * ti.dot(transport(n, t, ti))).normalized();
    t = ti;
    const Vec3 bn = t.cross(n);
    for (int k = 0; k < sides; ++k) {
      const double phi = 2 * M_PI * k / sides;
      mesh.points.push_back(line.x[i] + radius * (std::cos(phi) * n + std::sin(phi) * bn));
    }
  }
  mesh.scalars[s].resize(mesh.points.size(), 0.0);
  for (auto& other : mesh.scalars) other.resize(mesh.points.size(), 0.0);
  for (std::size_t i = 0; i < line.x.size(); ++i)
    for (int k = 0; k < sides; ++k)
      mesh.scalars[s][base + i * static_cast<std::size_t>(sides) + static_cast<std::size_t>(k)] =
          i < values.size() ? values[i] : 0.0;
  const auto S = static_cast<uint32_t>(sides);
  for (uint32_t i = 0; i + 1 < line.x.size(); ++i)
    for (uint32_t k = 0; k < S; ++k) {
      const uint32_t a = base + i * S + k, b = base + i * S + (k + 1) % S;
      const uint32_t c = a + S, d = b + S;
      mesh.triangles.push_back({a, b, c});
      mesh.triangles.push_back({b, d, c});
    }
}

void append_arrow(ProbeMesh& mesh, const Vec3& p, const Vec3& dir, double length, double radius, int sides,
                  const std::string& name, double value) {
  const double n = dir.norm();
  if (!(n > 0) || sides < 3) return;
  const Vec3 t = dir / n;
  const Vec3 u = perpendicular(t), w = t.cross(u);
  const auto base = static_cast<uint32_t>(mesh.points.size());
  const double shaft = 0.65 * length;
  auto ring = [&](const Vec3& c, double r) {
    for (int k = 0; k < sides; ++k) {
      const double phi = 2 * M_PI * k / sides;
      mesh.points.push_back(c + r * (std::cos(phi) * u + std::sin(phi) * w));
    }
  };
  ring(p, radius);                        // shaft bottom   base + k
  ring(p + shaft * t, radius);            // shaft top      base + S + k
  ring(p + shaft * t, 2.2 * radius);      // cone base      base + 2S + k
  mesh.points.push_back(p + length * t);  // tip            base + 3S
  mesh.points.push_back(p);               // bottom centre  base + 3S + 1
  const auto S = static_cast<uint32_t>(sides);
  for (uint32_t k = 0; k < S; ++k) {
    const uint32_t k1 = (k + 1) % S;
    mesh.triangles.push_back({base + k, base + k1, base + S + k});
    mesh.triangles.push_back({base + k1, base + S + k1, base + S + k});
    mesh.triangles.push_back({base + 2 * S + k, base + 2 * S + k1, base + 3 * S});
    mesh.triangles.push_back({base + S + k, base + S + k1, base + 2 * S + k});
    mesh.triangles.push_back({base + S + k1, base + 2 * S + k1, base + 2 * S + k});
    mesh.triangles.push_back({base + k1, base + k, base + 3 * S + 1});
  }
  const std::size_t s = mesh.scalar(name);
  for (auto& other : mesh.scalars) other.resize(mesh.points.size(), 0.0);
  for (std::size_t v = base; v < mesh.points.size(); ++v) mesh.scalars[s][v] = value;
}

double streamwise_vorticity(const Eigen::Matrix3d& g, const Vec3& v) {
  const Vec3 omega(g(2, 1) - g(1, 2), g(0, 2) - g(2, 0), g(1, 0) - g(0, 1));
  const double n = v.norm();
  return n > 0 ? omega.dot(v) / n : 0.0;
}

}  // namespace fest::lemtrace

#include "softobj/palate.hpp"
#include "core/quote.hpp"

#include <cmath>
#include <optional>

#include <nlohmann/json.hpp>

#include "core/error.hpp"

namespace fest::softobj {

namespace {

using Vec = Eigen::Vector3d;
using json = nlohmann::json;

double num(const json& j, const char* where) {
  if (!j.is_number() || !std::isfinite(j.get<double>())) throw bad_input("palate: {} is not a number", where);
  return j.get<double>();
}

double plane_norm(const Palate& pl) { return std::hypot(pl.plane[0], pl.plane[1]); }
// Signed distance to the strip's plane, > 0 on the forbidden side; nullopt outside the strip.
std::optional<double> strip_distance(const Palate& pl, const Vec& v) {
  if (v.y() < pl.y_range[0] || v.y() > pl.y_range[1] || std::abs(v.z()) > pl.width / 2) return std::nullopt;
  return (pl.plane[0] * v.x() + pl.plane[1] * v.y() + pl.plane[2]) / plane_norm(pl);
}

// The parameters that place point i: its length index, angle index, pivot point and the
// plane of rotation (e1, e2 in-plane axes; the direction is cos/sin in them).
struct Joint {
  int length, angle, pivot;
};
Joint joint_of(int i) {
  switch (i) {
    case 1: return {3, 12, 0};
    case 2: return {4, 13, 1};
    case 3: return {5, 14, 2};
    default: break;
  }
  const int row = (i - 4) / 2;  // 4,5 -> vl1; 6,7 -> vl2; 8,9 -> vl3
  return {i + 2, 15 + (i - 4), row + 1};
}

// Sets the angle (and for vl0 the origin) so that point i lies at q, keeping its length.
void set_direction(TongueParams& p, int i, const Vec& pivot, const Vec& q) {
  const Vec u = (q - pivot).normalized();
  const double d = 180 / M_PI;
  if (i == 0) {  // vl0 moves about vl1: vl1 = vl0 + l1 (sin a1, -cos a1, 0)
    const Vec w = (pivot - q).normalized();
    p[12] = std::atan2(w.x(), -w.y()) * d;
    p[0] = q.x(), p[1] = q.y(), p[2] = q.z();
    return;
  }
  const Joint j = joint_of(i);
  if (i == 1 || i == 3) p[j.angle] = std::atan2(u.x(), -u.y()) * d;
  else if (i == 2) p[j.angle] = std::atan2(-u.x(), u.y()) * d;
  else if ((i - 4) % 2 == 0) p[j.angle] = std::atan2(u.x(), -u.z()) * d;  // left, -z
  else p[j.angle] = std::atan2(u.x(), u.z()) * d;                          // right, +z
}

// Circle (pivot, l) in the point's plane of rotation meets the sphere (o, r): the point
// of the intersection nearest to `current`, if any.
std::optional<Vec> on_sphere(const Vec& pivot, double l, const Vec& current, bool median, const Vec& o, double r) {
  // In-plane axes: median points rotate in z = const (x, y); lateral ones in y = const (x, z).
  const Vec e1(1, 0, 0), e2 = median ? Vec(0, 1, 0) : Vec(0, 0, 1), n = median ? Vec(0, 0, 1) : Vec(0, 1, 0);
  const double h = (o - pivot).dot(n);
  const double r2 = r * r - h * h;
  if (r2 <= 0) return std::nullopt;
  const double rc = std::sqrt(r2);
  const Eigen::Vector2d c((o - pivot).dot(e1), (o - pivot).dot(e2));  // circle centre, pivot at 0
  const double dist = c.norm();
  if (dist < 1e-12 || dist > l + rc || dist < std::abs(l - rc)) return std::nullopt;
  const double a = (l * l - rc * rc + dist * dist) / (2 * dist);
  const double hh = std::sqrt(std::max(0.0, l * l - a * a));
  const Eigen::Vector2d base = c * (a / dist), perp(-c.y() / dist, c.x() / dist);
  std::optional<Vec> best;
  for (double s : {1.0, -1.0}) {
    const Eigen::Vector2d q2 = base + s * hh * perp;
    const Vec q = pivot + q2.x() * e1 + q2.y() * e2;
    if (!best || (q - current).norm() < (*best - current).norm()) best = q;
  }
  return best;
}

}  // namespace

Palate decode_palate(std::string_view text) {
  json doc;
  try {
    doc = json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    throw bad_input("palate: {}", json_failure_words(e.what(), e.byte, text));
  } catch (const json::exception& e) {  // a number beyond double's range: out_of_range, not parse_error
    throw bad_input("palate: {}", json_failure_words(e.what(), 0, text));
  }
  if (!doc.is_object() || !doc.contains("sphere") || !doc.contains("strip"))
    throw bad_input("palate: needs \"sphere\" and \"strip\" objects");
  Palate p;
  const json& s = doc["sphere"];
  if (!s.is_object() || !s.contains("center") || !s["center"].is_array() || s["center"].size() != 3)
    throw bad_input("palate: sphere.center is not [x, y, z]");
  p.centre = {num(s["center"][0], "sphere.center"), num(s["center"][1], "sphere.center"), num(s["center"][2], "sphere.center")};
  p.radius = num(s.value("radius", json()), "sphere.radius");
  const json& t = doc["strip"];
  if (!t.is_object() || !t.contains("plane") || !t["plane"].is_array() || t["plane"].size() != 3 || !t.contains("y_range") ||
      !t["y_range"].is_array() || t["y_range"].size() != 2)
    throw bad_input("palate: strip needs plane [p0,p1,p2] and y_range [ya,yb]");
  for (int i = 0; i < 3; ++i) p.plane[i] = num(t["plane"][static_cast<std::size_t>(i)], "strip.plane");
  for (int i = 0; i < 2; ++i) p.y_range[i] = num(t["y_range"][static_cast<std::size_t>(i)], "strip.y_range");
  p.width = num(t.value("width", json()), "strip.width");
  if (doc.contains("step")) {
    if (!doc["step"].is_number_integer() || doc["step"].get<int>() < 1 || doc["step"].get<int>() > 1000)
      throw bad_input("palate: step is not an integer in 1..1000");
    p.step = doc["step"].get<int>();
  }
  if (!(p.radius > 0) || !(p.width > 0) || plane_norm(p) == 0 || !(p.y_range[1] >= p.y_range[0]))
    throw bad_input("palate: radius and width must be positive, the plane's (p0, p1) nonzero, y_range ordered");
  return p;
}

PalateFix palate_pass1(TongueParams& p, const Palate& pl, double rho) {
  PalateFix fix;
  const double rv = pl.radius - rho;  // the virtual palate
  for (int i = 0; i < 10; ++i) {  // chain order vl0..vl3, then the lateral points
    auto vl = tongue_points(p);
    const Vec v = vl[static_cast<std::size_t>(i)];
    const int pivot = i == 0 ? 1 : joint_of(i).pivot;
    const Vec P = vl[static_cast<std::size_t>(pivot)];
    const double l = (v - P).norm();
    const bool median = i <= 3;
    // Sphere: rotate the incident segment onto the virtual sphere, length kept.
    if (v.x() > pl.centre.x() && (v - pl.centre).norm() > rv) {
      if (auto q = on_sphere(P, l, v, median, pl.centre, rv)) {
        set_direction(p, i, P, *q);
        ++fix.sphere;
        continue;
      }
    }
    // Plane strip: step off the virtual plane along its normal, then re-derive the
    // segment (length changes) and scale the row's coronal lengths by 1 + ratio.
    if (auto sd = strip_distance(pl, v); sd && *sd + rho > 0) {
      const Vec n = Vec(pl.plane[0], pl.plane[1], 0) / plane_norm(pl);
      Vec q = v;
      const double total = *sd + rho;
      for (int s = 0; s < pl.step; ++s) q -= (total / pl.step) * n;
      const double l_new = (q - P).norm();
      if (i <= 3) {
        const int li = i == 0 ? 3 : joint_of(i).length;
        const double l_old = p[li];
        p[li] = l_new;
        set_direction(p, i, P, q);
        const double ratio = (l_old - l_new) / l_old;
        const int row = i == 0 ? 1 : i;  // the row at vl_row: coronal lengths l(2 row + 2), l(2 row + 3)
        p[2 * row + 4] *= 1 + ratio;
        p[2 * row + 5] *= 1 + ratio;
      } else {
        p[joint_of(i).length] = l_new;
        set_direction(p, i, P, q);
      }
      ++fix.plane;
    }
  }
  return fix;
}

std::size_t palate_pass2(TriMesh& m, const Palate& pl) {
  std::size_t moved = 0;
  for (auto v : m.vertices()) {
    const auto& pt = m.point(v);
    Vec q(pt[0], pt[1], pt[2]);
    bool changed = false;
    if (q.x() > pl.centre.x() && (q - pl.centre).norm() > pl.radius) {
      q = pl.centre + pl.radius * (q - pl.centre).normalized();
      changed = true;
    }
    if (auto sd = strip_distance(pl, q); sd && *sd > 0) {
      q -= *sd * Vec(pl.plane[0], pl.plane[1], 0) / plane_norm(pl);
      changed = true;
    }
    if (changed) {
      m.set_point(v, TriMesh::Point(q.x(), q.y(), q.z()));
      ++moved;
    }
  }
  if (moved && m.has_vertex_normals()) {
    if (!m.has_face_normals()) m.request_face_normals();
    m.update_face_normals();
    for (auto v : m.vertices()) {
      const auto& pt = m.point(v);
      const Vec q(pt[0], pt[1], pt[2]);
      if ((q.x() > pl.centre.x() && std::abs((q - pl.centre).norm() - pl.radius) < 1e-9) ||
          (strip_distance(pl, q) && std::abs(*strip_distance(pl, q)) < 1e-9))
        m.set_normal(v, m.calc_vertex_normal(v));
    }
  }
  return moved;
}

}  // namespace fest::softobj

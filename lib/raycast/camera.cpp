#include "raycast/camera.hpp"

#include <stdexcept>

namespace fest::raycast {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Point-in-convex-polygon test in the polygon's plane (same side of every edge).
bool inside_polygon(const std::vector<Vec3>& poly, const Vec3& n, const Vec3& p) {
  int sign = 0;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const Vec3& a = poly[k];
    const Vec3& b = poly[(k + 1) % poly.size()];
    const double s = dot(cross(b - a, p - a), n);
    const int sg = s > 0 ? 1 : s < 0 ? -1 : 0;
    if (sg == 0) continue;
    if (sign == 0) sign = sg;
    else if (sg != sign) return false;
  }
  return true;
}

}  // namespace

Ray Camera::ray(double x, double y) const {
  Ray r;
  const double u = x / width, v = (height - y) / height;  // 0..1 from the lower left
  switch (kind) {
    case Kind::perspective: {
      const double aspect = static_cast<double>(width) / height;
      r.origin = eye;
      r.dir = forward + ((2 * u - 1) * tan_half_fov * aspect) * right + ((2 * v - 1) * tan_half_fov) * up;
      break;
    }
    case Kind::orthographic: {
      const double aspect = static_cast<double>(width) / height;
      r.origin = eye + ((2 * u - 1) * half_height * aspect) * right + ((2 * v - 1) * half_height) * up;
      r.dir = forward;
      break;
    }
    case Kind::off_axis: {
      // p_ij = p_a + (i + 1/2)/W (p_b - p_a) + (H - j - 1/2)/H (p_c - p_a)
      const Vec3 p = pa + u * (pb - pa) + v * (pc - pa);
      r.origin = eye;
      r.dir = (mirror ? mirror->reflect(p) : p) - eye;
      break;
    }
  }
  if (near > 0) r.t_min = near / norm(r.dir);
  if (mirror) {
    // Content starts where the line of sight crosses the mirror (what lies in front of
    // the mirror cannot be shown); a line of sight that misses the mirror shows background.
    const double nd = dot(mirror->n, r.dir);
    if (std::abs(nd) < 1e-15) {
      r.valid = false;
      return r;
    }
    const double t = (mirror->delta - dot(mirror->n, r.origin)) / nd;
    if (t <= 0) {
      r.valid = false;
      return r;
    }
    r.t_min = std::max(r.t_min, t);
    if (!mirror->outline.empty() && !inside_polygon(mirror->outline, mirror->n, r.origin + t * r.dir)) r.valid = false;
  }
  return r;
}

Camera Camera::moved_eye(const Vec3& offset) const {
  Camera c = *this;
  c.eye = eye + offset;
  return c;
}

Camera orbit_camera(const Vec3& centre, double radius, double az_deg, double el_deg, double roll_deg, double fov_deg,
                    double zoom, int width, int height) {
  const double az = az_deg * kPi / 180, el = el_deg * kPi / 180, roll = roll_deg * kPi / 180;
  // Eye direction from the centre: az = el = 0 -> -y.
  const Vec3 back{std::sin(az) * std::cos(el), -std::cos(az) * std::cos(el), std::sin(el)};
  Camera c;
  c.width = width, c.height = height;
  c.forward = -1.0 * back;
  Vec3 world_up{0, 0, 1};
  if (std::abs(dot(world_up, back)) > 0.999999) world_up = {0, 1, 0};
  Vec3 right = normalized(cross(c.forward, world_up));
  Vec3 up = cross(right, c.forward);
  c.right = std::cos(roll) * right + std::sin(roll) * up;
  c.up = std::cos(roll) * up - std::sin(roll) * right;
  const double fit = radius / std::max(zoom, 1e-9);
  if (fov_deg <= 0) {
    c.kind = Camera::Kind::orthographic;
    c.half_height = fit * std::max(1.0, static_cast<double>(height) / width);
    c.eye = centre + (2 * radius) * back;
  } else {
    c.kind = Camera::Kind::perspective;
    c.tan_half_fov = std::tan(fov_deg * kPi / 360);
    const double half = std::min(c.tan_half_fov, c.tan_half_fov * width / height);
    // the sphere fits the narrower image side: distance = fit / sin(atan(half))
    c.eye = centre + (fit * std::sqrt(1 + half * half) / half) * back;
  }
  return c;
}

Camera look_at_camera(const Vec3& eye, const Vec3& target, const Vec3& up, double fov_deg, int width, int height) {
  Camera c;
  c.kind = Camera::Kind::perspective;
  c.width = width, c.height = height;
  c.eye = eye;
  if (norm(target - eye) == 0) throw std::invalid_argument("eye and look-at point coincide");
  c.forward = normalized(target - eye);
  const Vec3 r = cross(c.forward, up);
  if (norm(r) < 1e-12) throw std::invalid_argument("up vector parallel to the viewing direction");
  c.right = normalized(r);
  c.up = cross(c.right, c.forward);
  c.tan_half_fov = std::tan(fov_deg * kPi / 360);
  return c;
}

Camera off_axis_camera(const Vec3& pa, const Vec3& pb, const Vec3& pc, const Vec3& eye, int width, int height) {
  const Vec3 n = cross(pb - pa, pc - pa);
  if (norm(pb - pa) == 0 || norm(pc - pa) == 0 || norm(n) < 1e-12 * norm(pb - pa) * norm(pc - pa))
    throw std::invalid_argument("screen corners are degenerate (coincident or collinear)");
  const double d = dot(normalized(n), eye - pa);
  if (std::abs(d) < 1e-12 * norm(pb - pa)) throw std::invalid_argument("eye lies on the screen plane");
  Camera c;
  c.kind = Camera::Kind::off_axis;
  c.width = width, c.height = height;
  c.pa = pa, c.pb = pb, c.pc = pc, c.eye = eye;
  return c;
}

Frustum off_axis_frustum(const Camera& c, double n) {
  const Vec3 vr = c.screen_right(), vu = c.screen_up(), vn = c.screen_normal();
  const Vec3 va = c.pa - c.eye, vb = c.pb - c.eye, vc = c.pc - c.eye;
  const double d = -dot(vn, va);
  return {dot(vr, va) * n / d, dot(vr, vb) * n / d, dot(vu, va) * n / d, dot(vu, vc) * n / d, n, d};
}

std::pair<Camera, Camera> stereo_pair(const Camera& c, double ipd, const Vec3& head_right) {
  const Vec3 r = normalized(head_right);
  return {c.moved_eye((-ipd / 2) * r), c.moved_eye((ipd / 2) * r)};
}

}  // namespace fest::raycast

#pragma once
// Cameras as pure functions pixel -> ray (docs/volrender.md "Cameras"): orbit/look-at
// (perspective or orthographic), the generalized off-axis camera of head-tracked screens
// (Kooima's formulation), stereo eyes, and the Virtual Showcase's half-silvered mirror
// (Bimber et al. 2001; the planar-reflection construction is reconstructed).
//
// Pixel (i, j): i left to right, j top to bottom; pixel centres at (i + 1/2, j + 1/2).

#include <optional>
#include <string>
#include <vector>

#include "raycast/vec3.hpp"

namespace fest::raycast {

struct Ray {
  Vec3 origin;
  Vec3 dir;          // not normalised
  double t_min = 0;  // parameter where content may start (near plane, mirror plane)
  bool valid = true; // false: the pixel shows background (line of sight misses the mirror)
};

// The planar beam splitter {x : n.x = delta}, unit n.
struct Mirror {
  Vec3 n{0, 0, 1};
  double delta = 0;
  std::vector<Vec3> outline;  // the mirror's physical polygon (planar, convex); empty = unbounded
  Vec3 reflect(const Vec3& x) const { return x - 2.0 * (dot(n, x) - delta) * n; }
};

struct Camera {
  enum class Kind { perspective, orthographic, off_axis };
  Kind kind = Kind::perspective;
  int width = 256, height = 256;
  // perspective / orthographic: eye, unit right/up/forward, tan(fov_y / 2) or half height
  Vec3 eye{0, 0, 0}, right{1, 0, 0}, up{0, 1, 0}, forward{0, 0, -1};
  double tan_half_fov = 0.5;     // perspective
  double half_height = 1.0;      // orthographic: world half height of the image
  // off-axis: screen corners (lower left, lower right, upper left), world units
  Vec3 pa{-1, -1, 0}, pb{1, -1, 0}, pc{-1, 1, 0};
  double near = 0;               // rays start this far (world units along the ray direction, normalised)
  std::optional<Mirror> mirror;

  // The ray through continuous pixel position (x, y) (pixel centre: i + 0.5, j + 0.5).
  Ray ray(double x, double y) const;
  // Screen unit vectors v_r, v_u, v_n of the off-axis camera.
  Vec3 screen_right() const { return normalized(pb - pa); }
  Vec3 screen_up() const { return normalized(pc - pa); }
  Vec3 screen_normal() const { return normalized(cross(screen_right(), screen_up())); }
  // The same camera with the eye moved by `offset` (stereo).
  Camera moved_eye(const Vec3& offset) const;
};

// Orbit camera around a bounding sphere (centre, radius): azimuth about the world z axis,
// elevation above the xy plane, degrees; az = el = 0 looks along +y (the eye on the -y
// side), up = +z. fov_deg = 0 gives an orthographic camera. The distance fits the sphere
// in the image; zoom > 1 magnifies.
Camera orbit_camera(const Vec3& centre, double radius, double az_deg, double el_deg, double roll_deg, double fov_deg,
                    double zoom, int width, int height);

// Look-at camera (perspective, or orthographic with half height = tan(fov/2) when fov_deg = 0 -- not offered).
Camera look_at_camera(const Vec3& eye, const Vec3& target, const Vec3& up, double fov_deg, int width, int height);

// Generalized off-axis camera: screen corners pa (lower left), pb (lower right), pc (upper
// left) and an eye. Throws std::invalid_argument for degenerate corners or an eye on the
// screen plane (the tool maps it to a usage error).
Camera off_axis_camera(const Vec3& pa, const Vec3& pb, const Vec3& pc, const Vec3& eye, int width, int height);

// The OpenGL frustum of an off-axis camera at near distance n: l, r, b, t and the eye
// distance d to the screen plane (Kooima 2008).
struct Frustum {
  double left, right, bottom, top, near, distance;
};
Frustum off_axis_frustum(const Camera& c, double n);

// Eyes of a stereo pair: eye -/+ (ipd/2) * unit head_right.
std::pair<Camera, Camera> stereo_pair(const Camera& c, double ipd, const Vec3& head_right);

}  // namespace fest::raycast

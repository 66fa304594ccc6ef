#include "camera_args.hpp"

#include <cmath>
#include <stdexcept>

#include "core/error.hpp"
#include "raycast/render.hpp"

namespace fest::volrender_tool {
using raycast::operator+;
using raycast::operator-;
using raycast::operator*;

std::vector<raycast::Camera> make_cameras(const CameraArgs& a, const volume_pyramid::ScalarGrid* grid) {
  const int W = a.width, H = a.height;
  if (W < 1 || H < 1 || W > 16384 || H > 16384) throw usage_error("--size {}x{}: width and height must be 1..16384", W, H);
  raycast::Camera cam;
  try {
    if (!a.screen.empty()) {
      const auto& c = a.screen;
      if (c.size() != 3) throw usage_error("--screen takes three corners PA;PB;PC (lower left; lower right; upper left)");
      if (!a.eye) throw usage_error("--screen needs --eye");
      cam = raycast::off_axis_camera(c[0], c[1], c[2], *a.eye, W, H);
    } else if (a.eye) {
      if (!a.look_at) throw usage_error("--eye needs --look-at (or --screen)");
      cam = raycast::look_at_camera(*a.eye, *a.look_at, a.up, a.fov.value_or(30), W, H);
    } else {
      if (!grid) throw usage_error("an orbit camera needs the volume");
      const auto& v = a.view;
      if (v.size() < 2 || v.size() > 3) throw usage_error("--view takes AZ,EL[,ROLL]");
      const auto lo = grid->world(0, 0, 0);
      const auto hi = grid->world(double(grid->dims[0] - 1), double(grid->dims[1] - 1), double(grid->dims[2] - 1));
      raycast::Vec3 centre{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
      double radius = 0;
      for (int c = 0; c < 8; ++c) {
        const auto p = grid->world(c & 1 ? grid->dims[0] - 1.0 : 0.0, c & 2 ? grid->dims[1] - 1.0 : 0.0, c & 4 ? grid->dims[2] - 1.0 : 0.0);
        radius = std::max(radius, raycast::norm(raycast::Vec3{p[0], p[1], p[2]} - centre));
      }
      if (a.zoom <= 0) throw usage_error("--zoom must be positive");
      cam = raycast::orbit_camera(centre, radius, v[0], v[1], v.size() > 2 ? v[2] : 0.0, a.fov.value_or(30), a.zoom, W, H);
    }
  } catch (const std::invalid_argument& e) {
    throw usage_error("bad camera: {}", e.what());
  }
  if (a.near < 0) throw usage_error("--near must be >= 0");
  cam.near = a.near;
  if (a.mirror) {
    if (cam.kind != raycast::Camera::Kind::off_axis) throw usage_error("--mirror needs the off-axis camera (--screen and --eye)");
    const auto& m = *a.mirror;
    const raycast::Vec3 n{m[0], m[1], m[2]};
    if (raycast::norm(n) < 1e-12) throw usage_error("--mirror normal has zero length");
    raycast::Mirror mirror;
    const double len = raycast::norm(n);
    mirror.n = (1 / len) * n;
    mirror.delta = m[3] / len;
    if (!a.mirror_poly.empty()) {
      mirror.outline = a.mirror_poly;
      if (mirror.outline.size() < 3) throw usage_error("--mirror-poly needs at least 3 points");
    }
    cam.mirror = mirror;
  }
  if (grid && cam.kind != raycast::Camera::Kind::orthographic && !cam.mirror && cam.near == 0) {
    raycast::Ray r{cam.eye, {1, 0, 0}};
    double t0, t1;
    if (raycast::clip_to_grid(*grid, r, t0, t1) && t0 < 0 && t1 > 0)
      throw usage_error("camera eye {},{},{} is inside the volume (move it out, or clip with --near)", cam.eye[0], cam.eye[1], cam.eye[2]);
  }
  if (!a.stereo) return {cam};
  if (!(*a.stereo > 0)) throw usage_error("--stereo takes a positive eye separation");
  raycast::Vec3 right = cam.kind == raycast::Camera::Kind::off_axis ? cam.screen_right() : cam.right;
  if (a.head_right) right = *a.head_right;
  if (raycast::norm(right) < 1e-12) throw usage_error("--head-right has zero length");
  const auto [l, r] = raycast::stereo_pair(cam, *a.stereo, right);
  return {l, r};
}

nlohmann::json camera_json(const raycast::Camera& c) {
  using raycast::Camera;
  nlohmann::json j;
  j["width"] = c.width, j["height"] = c.height;
  j["eye"] = c.eye;
  j["kind"] = c.kind == Camera::Kind::perspective ? "perspective" : c.kind == Camera::Kind::orthographic ? "orthographic" : "off_axis";
  if (c.kind == Camera::Kind::off_axis) {
    j["screen"] = {c.pa, c.pb, c.pc};
    const double n = c.near > 0 ? c.near : 0.01;
    const auto f = raycast::off_axis_frustum(c, n);
    j["frustum"] = {{"left", f.left}, {"right", f.right}, {"bottom", f.bottom}, {"top", f.top}, {"near", f.near}, {"eye_screen_distance", f.distance}};
    const auto vr = c.screen_right(), vu = c.screen_up(), vn = c.screen_normal();
    // view matrix: rotation rows vr, vu, vn, then translation by -eye
    j["view_matrix"] = {{vr[0], vr[1], vr[2], -raycast::dot(vr, c.eye)},
                        {vu[0], vu[1], vu[2], -raycast::dot(vu, c.eye)},
                        {vn[0], vn[1], vn[2], -raycast::dot(vn, c.eye)},
                        {0, 0, 0, 1}};
  } else {
    j["forward"] = c.forward, j["right"] = c.right, j["up"] = c.up;
    if (c.kind == Camera::Kind::perspective) j["tan_half_fov"] = c.tan_half_fov;
    else j["half_height"] = c.half_height;
  }
  if (c.mirror) j["mirror"] = {{"normal", c.mirror->n}, {"delta", c.mirror->delta}};
  return j;
}

}  // namespace fest::volrender_tool

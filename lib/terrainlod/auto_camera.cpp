#include "terrainlod/auto_camera.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.hpp"

namespace fest::terrainlod {
namespace {

using Vec = std::array<double, 3>;
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
Vec normalized(const Vec& a) {
  const double n = std::sqrt(dot(a, a));
  return {a[0] / n, a[1] / n, a[2] / n};
}

struct Preset {
  const char* name;
  ViewDirection dir;
};
const Preset kPresets[] = {{"overview", {225, 35}}, {"oblique", {225, 20}}, {"north", {0, 30}}, {"south", {180, 30}},
                           {"east", {90, 30}},      {"west", {270, 30}},    {"top", {0, 90}}};

}  // namespace

const std::vector<std::string>& camera_preset_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& p : kPresets) n.push_back(p.name);
    return n;
  }();
  return names;
}

ViewDirection camera_preset(const std::string& name) {
  for (const auto& p : kPresets)
    if (name == p.name) return p.dir;
  std::string words;
  for (const auto& p : kPresets) words += (words.empty() ? "" : ", ") + std::string(p.name);
  throw usage_error("camera preset '{}' is not one of {}", name, words);
}

Camera frame_box(const WorldBox& box, const ViewDirection& dir, int width, int height, double fovy_deg, double margin) {
  const double az = dir.azimuth_deg * M_PI / 180, el = std::clamp(dir.elevation_deg, -89.0, 90.0) * M_PI / 180;
  // The direction from the centre to the eye: azimuth clockwise from north (+y).
  const Vec to_eye{std::cos(el) * std::sin(az), std::cos(el) * std::cos(az), std::sin(el)};
  const Vec f{-to_eye[0], -to_eye[1], -to_eye[2]};
  // Straight down the image's up is the azimuth's horizontal direction away from the eye
  // (north for 'top'); otherwise +z.
  const bool down = std::abs(std::sin(el)) > 1 - 1e-9;
  const Vec up = down ? Vec{-std::sin(az), -std::cos(az), 0} : Vec{0, 0, 1};
  const Vec r = normalized(cross(f, up));
  const Vec u = cross(r, f);
  const Vec c{(box.x0 + box.x1) / 2, (box.y0 + box.y1) / 2, (box.z0 + box.z1) / 2};
  const double tan_y = std::tan(fovy_deg * M_PI / 360) * (1 - margin);
  const double tan_x = tan_y * width / height;
  // Eye = c + D to_eye: a corner p at q = p - c has depth dot(q, f) + D and must satisfy
  // |dot(q, r)| <= depth tan_x and |dot(q, u)| <= depth tan_y; the smallest D that holds
  // every corner.
  double D = 0, reach = 0;
  for (int k = 0; k < 8; ++k) {
    const Vec q{(k & 1 ? box.x1 : box.x0) - c[0], (k & 2 ? box.y1 : box.y0) - c[1], (k & 4 ? box.z1 : box.z0) - c[2]};
    const double z = dot(q, f);
    D = std::max({D, std::abs(dot(q, r)) / tan_x - z, std::abs(dot(q, u)) / tan_y - z});
    reach = std::max(reach, std::sqrt(dot(q, q)));
  }
  // Outside the box's bounding sphere (only a very wide view would fit closer), so every
  // point of the box is in front of the eye by at least D - reach.
  D = std::max({D, 1.05 * reach, 1e-6});
  Camera cam;
  cam.eye = {c[0] + D * to_eye[0], c[1] + D * to_eye[1], c[2] + D * to_eye[2]};
  cam.target = c;
  cam.up = up;
  cam.fovy_deg = fovy_deg;
  cam.width = width;
  cam.height = height;
  // Near in front of the nearest point of the box, far beyond the farthest.
  cam.near = std::max(1e-9, (D - reach) * 0.5);
  cam.far = D + 2 * reach + 1;
  return cam;
}

}  // namespace fest::terrainlod

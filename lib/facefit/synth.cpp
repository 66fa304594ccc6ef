#include "facefit/synth.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.hpp"

namespace fest::facefit {

namespace {

// Mean head size (θ = 0): the grid's extent in mm.
constexpr double kW = 75, kH = 110, kD = 90;

double gauss2(double dx, double dy, double sx, double sy) {
  return std::exp(-0.5 * (dx * dx / (sx * sx) + dy * dy / (sy * sy)));
}

// Feature layout derived from θ: every quantity is a smooth nonlinear function of θ.
struct Layout {
  double W, H, D;
  double eye_y, eye_inner, eye_outer, eye_center, socket_depth;
  double brow_height;
  double nose_length, nose_height, nose_width, tip_y;
  double mouth_y, mouth_half_width, lip_height;
  double chin_y, chin_height;
  double cheek_height;
  double asym;
};

Layout layout_of(const std::array<double, 14>& t) {
  Layout L;
  L.W = kW * std::exp(0.08 * t[0]);
  L.H = kH * std::exp(0.07 * t[1]);
  L.D = kD * std::exp(0.066 * t[2]);
  L.nose_length = 45 * std::exp(0.08 * t[3]);
  L.nose_height = 18 * std::exp(0.22 * t[4] - 0.02 * t[4] * t[4]);
  L.nose_width = 8 * std::exp(0.15 * t[5]);
  L.eye_inner = 16 * std::exp(0.09 * t[6]);
  L.eye_outer = L.eye_inner + 28 * std::exp(0.05 * t[6] * t[7]);
  L.eye_center = (L.eye_inner + L.eye_outer) / 2;
  L.eye_y = 28 + 3 * std::tanh(t[7]) + 0.04 * L.H - 4.4;
  L.socket_depth = 7 * std::exp(0.25 * t[8]);
  L.brow_height = 5 * std::exp(0.25 * t[9]);
  L.tip_y = L.eye_y - L.nose_length;
  L.mouth_y = L.tip_y - 20 * std::exp(0.1 * t[10]);
  L.lip_height = 4 * std::exp(0.2 * t[11]);
  L.mouth_half_width = 24 * std::exp(0.1 * t[12]);
  L.chin_y = L.mouth_y - 28 * std::exp(0.06 * t[1] + 0.05 * t[13]);
  L.chin_height = 8 * std::exp(0.2 * t[13]);
  L.cheek_height = 5 * std::exp(0.15 * (t[0] - t[2]));
  L.asym = 1.5 * std::tanh(t[12] * t[13] + 0.5 * t[9]);
  return L;
}

double feature_depth(const Layout& L, double x, double y) {
  const double xs = x - L.asym;  // slight asymmetry: features move sideways together
  const double ax = std::abs(xs);
  double z = 0;
  // Eye sockets and eyeballs.
  z -= L.socket_depth * gauss2(ax - L.eye_center, y - L.eye_y, 11, 8);
  z += 3 * gauss2(ax - L.eye_center, y - L.eye_y, 5, 4);
  // Brow ridge.
  z += L.brow_height * gauss2(ax - L.eye_center, y - (L.eye_y + 13), 14, 5);
  // Nose: a ridge rising from the bridge to the tip, then the tip and the wings.
  const double t = (L.eye_y - y) / L.nose_length;  // 0 at the bridge, 1 at the tip
  double along;
  if (t < 0) along = 0.25 * std::exp(-0.5 * std::pow(t * L.nose_length / 8, 2));
  else if (t > 1) along = std::exp(-0.5 * std::pow((t - 1) * L.nose_length / 5, 2));
  else along = 0.25 + 0.75 * std::pow(t, 1.4);
  const double ridge_width = L.nose_width * (0.35 + 0.35 * std::clamp(t, 0.0, 1.0));
  z += L.nose_height * along * std::exp(-0.5 * xs * xs / (ridge_width * ridge_width));
  z += 5 * gauss2(ax - (L.nose_width + 3), y - (L.tip_y + 4), 5, 5);
  // Mouth: lips and the line between them.
  z += L.lip_height * gauss2(xs, y - (L.mouth_y + 4), 0.7 * L.mouth_half_width, 3);
  z += L.lip_height * gauss2(xs, y - (L.mouth_y - 5), 0.6 * L.mouth_half_width, 4);
  z -= 2 * gauss2(xs, y - L.mouth_y, L.mouth_half_width, 1.5);
  // Chin and cheeks.
  z += L.chin_height * gauss2(xs, y - L.chin_y, 14, 10);
  z += L.cheek_height * gauss2(ax - (L.eye_center + 12), y - (L.eye_y - 30), 18, 18);
  return z;
}

// Piecewise-linear monotone map through knots (a_i -> b_i), a ascending.
double through_knots(const double* a, const double* b, int count, double t) {
  if (t <= a[0]) return b[0] + (t - a[0]) * (b[1] - b[0]) / (a[1] - a[0]);
  for (int i = 0; i + 1 < count; ++i)
    if (t <= a[i + 1]) return b[i] + (t - a[i]) * (b[i + 1] - b[i]) / (a[i + 1] - a[i]);
  return b[count - 1] + (t - a[count - 1]) * (b[count - 1] - b[count - 2]) / (a[count - 1] - a[count - 2]);
}

// Dense correspondence: vertex (x0, y0) of the mean face (θ = 0) is the same anatomical
// point on every face, so the grid is warped to follow the features. Vertically the
// chin, mouth, nose tip, eyes and brows move to their places; horizontally the rows of
// the eyes and of the mouth widen with eye separation and mouth width; the centre
// shifts with the asymmetry. Landmarks then move in the image plane as on real faces.
void warp(const Layout& L0, const Layout& L, double x0, double y0, double& x, double& y) {
  const double a[7] = {-kH, L0.chin_y, L0.mouth_y, L0.tip_y, L0.eye_y, L0.eye_y + 13, kH};
  const double b[7] = {-L.H, L.chin_y, L.mouth_y, L.tip_y, L.eye_y, L.eye_y + 13, L.H};
  y = through_knots(a, b, 7, y0);
  const double base = L.W / kW;
  const double eye = L.eye_center / L0.eye_center, mouth = L.mouth_half_width / L0.mouth_half_width;
  const double sx = base + (eye - base) * std::exp(-0.5 * std::pow((y0 - L0.eye_y) / 15, 2)) *
                               std::exp(-0.5 * std::pow(x0 / 60, 2)) +
                    (mouth - base) * std::exp(-0.5 * std::pow((y0 - L0.mouth_y) / 10, 2)) *
                        std::exp(-0.5 * std::pow(x0 / 40, 2));
  x = x0 * sx + L.asym * std::exp(-0.5 * std::pow(x0 / 50, 2));
}

std::uint32_t nearest_unused(int R, double x, double y, std::set<std::uint32_t>& used) {
  // Grid of the mean face: x = kW u, y = kH w. Search outwards until a free vertex.
  const double gi = (x / kW + 1) / 2 * (R - 1), gj = (y / kH + 1) / 2 * (R - 1);
  for (int radius = 0; radius < R; ++radius) {
    double best = 1e300;
    int bi = -1, bj = -1;
    for (int j = 0; j < R; ++j)
      for (int i = 0; i < R; ++i) {
        if (std::abs(i - gi) > radius + 0.5 || std::abs(j - gj) > radius + 0.5) continue;
        const auto v = static_cast<std::uint32_t>(j * R + i);
        if (used.count(v)) continue;
        const double dx = (i - gi) * kW, dy = (j - gj) * kH;
        const double d = dx * dx + dy * dy;
        if (d < best) { best = d; bi = i; bj = j; }
      }
    if (bi >= 0) {
      const auto v = static_cast<std::uint32_t>(bj * R + bi);
      used.insert(v);
      return v;
    }
  }
  throw bad_input("grid of resolution {} has too few vertices for the landmark sets", R);
}

}  // namespace

FaceParameters draw_face(Rng& rng, double detail_mm) {
  FaceParameters face;
  for (auto& t : face.theta) t = rng.normal();
  face.detail.resize(24);
  for (auto& b : face.detail) {
    b.x = kW * rng.uniform(-0.9, 0.9);
    b.y = kH * rng.uniform(-0.9, 0.9);
    b.width = rng.uniform(6, 15);
    b.height = detail_mm * rng.normal();
    b.shift_x = detail_mm * rng.normal();
    b.shift_y = detail_mm * rng.normal();
  }
  return face;
}

Eigen::VectorXd face_shape(const FaceParameters& face, int R) {
  if (R < 8) throw usage_error("grid resolution must be at least 8, got {}", R);
  const Layout L = layout_of(face.theta);
  const Layout L0 = layout_of({});
  Eigen::VectorXd v(3 * R * R);
  for (int j = 0; j < R; ++j)
    for (int i = 0; i < R; ++i) {
      const double u = -1 + 2.0 * i / (R - 1), w = -1 + 2.0 * j / (R - 1);
      double x, y;
      warp(L0, L, kW * u, kH * w, x, y);
      double z = L.D * std::sqrt(std::max(0.0, 1 - u * u - 0.8 * w * w));
      z += feature_depth(L, x, y);
      // Individual detail moves vertices in all three directions: registered real scans
      // differ person by person in where each point lies in the image plane too.
      double dx = 0, dy = 0;
      for (const auto& b : face.detail) {
        const double g = gauss2(x - b.x, y - b.y, b.width, b.width);
        z += b.height * g;
        dx += b.shift_x * g;
        dy += b.shift_y * g;
      }
      x += dx;
      y += dy;
      const Eigen::Index k = 3 * (static_cast<Eigen::Index>(j) * R + i);
      v(k) = x;
      v(k + 1) = y;
      v(k + 2) = z;
    }
  return v;
}

std::vector<std::array<std::uint32_t, 3>> grid_triangles(int R) {
  std::vector<std::array<std::uint32_t, 3>> tris;
  tris.reserve(static_cast<std::size_t>(2 * (R - 1) * (R - 1)));
  for (int j = 0; j + 1 < R; ++j)
    for (int i = 0; i + 1 < R; ++i) {
      const auto a = static_cast<std::uint32_t>(j * R + i), b = a + 1;
      const auto c = static_cast<std::uint32_t>((j + 1) * R + i), d = c + 1;
      // x grows with i, y with j: (a, b, d) is counter-clockwise seen from +z.
      tris.push_back({a, b, d});
      tris.push_back({a, d, c});
    }
  return tris;
}

SynthLandmarks synth_landmarks(int R, std::uint64_t seed) {
  if (R < 16) throw usage_error("landmark sets need a grid resolution of 16 or more, got {}", R);
  const Layout L = layout_of({});
  SynthLandmarks out;
  std::set<std::uint32_t> used;
  auto add = [&](std::vector<NamedVertex>& set, const std::string& name, double x, double y) {
    set.push_back({name, nearest_unused(R, x, y, used)});
  };
  auto& s = out.set17;
  for (int side = -1; side <= 1; side += 2) {
    const std::string lr = side < 0 ? "right" : "left";  // the face's own right is image left
    add(s, "eye_outer_" + lr, side * L.eye_outer, L.eye_y);
    add(s, "eye_inner_" + lr, side * L.eye_inner, L.eye_y);
    add(s, "brow_inner_" + lr, side * (L.eye_inner - 4), L.eye_y + 14);
    add(s, "brow_outer_" + lr, side * (L.eye_outer + 2), L.eye_y + 12);
    add(s, "nostril_" + lr, side * (L.nose_width + 4), L.tip_y + 4);
    add(s, "mouth_corner_" + lr, side * L.mouth_half_width, L.mouth_y);
  }
  add(s, "nose_tip", 0, L.tip_y);
  add(s, "subnasale", 0, L.tip_y - 6);
  add(s, "upper_lip", 0, L.mouth_y + 4);
  add(s, "lower_lip", 0, L.mouth_y - 5);
  add(s, "chin", 0, L.chin_y);

  out.set50 = out.set17;
  auto& f = out.set50;
  for (int side = -1; side <= 1; side += 2) {
    const std::string lr = side < 0 ? "right" : "left";
    const double brow_x[3] = {20, 28, 37};
    for (int b = 0; b < 3; ++b) add(f, "brow_" + std::to_string(b + 1) + "_" + lr, side * brow_x[b], L.eye_y + 15);
    add(f, "eyelid_upper_" + lr, side * L.eye_center, L.eye_y + 5);
    add(f, "eyelid_lower_" + lr, side * L.eye_center, L.eye_y - 5);
    add(f, "nose_side_" + lr, side * 9, L.tip_y + 14);
    add(f, "upper_lip_" + lr, side * 10, L.mouth_y + 3);
    add(f, "lower_lip_" + lr, side * 10, L.mouth_y - 4);
    add(f, "lip_" + lr, side * 18, L.mouth_y + 1);
    const double alpha[6] = {0.1, 0.35, 0.6, 0.85, 1.1, 1.3};
    for (int a = 0; a < 6; ++a)
      add(f, "jaw_" + std::to_string(a + 1) + "_" + lr, side * 62 * std::cos(alpha[a]), -15 - 55 * std::sin(alpha[a]));
  }
  add(f, "bridge_1", 0, L.eye_y);
  add(f, "bridge_2", 0, L.eye_y - 12);
  add(f, "bridge_3", 0, L.eye_y - 28);

  for (int j = 0; j < R; ++j) {
    const double w = -1 + 2.0 * j / (R - 1);
    if (w < -0.8 || w > 0.7) continue;
    for (int i = 0; i < R; ++i) out.eval_mask.push_back(static_cast<std::uint32_t>(j * R + i));
  }
  // set1000: a seeded partial Fisher-Yates shuffle of the mask (all of it if smaller).
  std::vector<std::uint32_t> pool = out.eval_mask;
  Rng rng(seed ^ 0x5e71000ull);
  const std::size_t count = std::min<std::size_t>(1000, pool.size());
  for (std::size_t a = 0; a < count; ++a) {
    const std::size_t b = a + static_cast<std::size_t>(rng.below(pool.size() - a));
    std::swap(pool[a], pool[b]);
    out.set1000.push_back({"r" + std::to_string(a + 1), pool[a]});
  }
  return out;
}

}  // namespace fest::facefit

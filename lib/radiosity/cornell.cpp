#include "radiosity/cornell.hpp"

namespace fest::radiosity {
namespace {

using V = Eigen::Vector3d;

// Adds one quad to `o`, reversed if needed so that its normal points towards `inside`
// (toward = true) or away from it.
void add_quad(SceneObject& o, std::initializer_list<V> corners, const V& ref, bool toward) {
  std::vector<V> p(corners);
  const V n = (p[1] - p[0]).cross(p[2] - p[0]) + (p[2] - p[0]).cross(p[3] - p[0]);
  const V c = (p[0] + p[1] + p[2] + p[3]) / 4.0;
  if ((n.dot(ref - c) > 0) != toward) std::swap(p[1], p[3]);
  const auto base = static_cast<std::uint32_t>(o.vertices.size());
  for (const V& q : p) o.vertices.push_back(q);
  o.faces.push_back({base, base + 1, base + 2, base + 3});
}

SceneObject block(const std::string& name, const Rgb& rho, std::initializer_list<V> top) {
  SceneObject o{name, rho, Rgb::Zero(), {}, {}};
  std::vector<V> t(top);
  V c = V::Zero();
  for (const V& q : t) c += q;
  c /= 4.0;
  c.y() *= 0.5;  // the block's centre
  add_quad(o, {t[0], t[1], t[2], t[3]}, c, false);
  for (int k = 0; k < 4; ++k) {
    const V& a = t[k];
    const V& b = t[(k + 1) % 4];
    add_quad(o, {a, b, V(b.x(), 0, b.z()), V(a.x(), 0, a.z())}, c, false);
  }
  return o;
}

}  // namespace

Scene cornell_box(bool blocks) {
  const Rgb white(0.725, 0.71, 0.68), red(0.63, 0.065, 0.05), green(0.14, 0.45, 0.091);
  const V inside(278, 274, 280);
  Scene s;
  s.units = "mm";
  auto wall = [&](const std::string& name, const Rgb& rho, const Rgb& e, std::initializer_list<V> c) {
    SceneObject o{name, rho, e, {}, {}};
    add_quad(o, c, inside, true);
    s.objects.push_back(o);
  };
  wall("floor", white, Rgb::Zero(), {V(552.8, 0, 0), V(0, 0, 0), V(0, 0, 559.2), V(549.6, 0, 559.2)});
  wall("ceiling", white, Rgb::Zero(), {V(556, 548.8, 0), V(556, 548.8, 559.2), V(0, 548.8, 559.2), V(0, 548.8, 0)});
  wall("light", Rgb(0.78, 0.78, 0.78), Rgb(17, 12, 4),
       {V(343, 548.7, 227), V(343, 548.7, 332), V(213, 548.7, 332), V(213, 548.7, 227)});
  wall("back_wall", white, Rgb::Zero(),
       {V(549.6, 0, 559.2), V(0, 0, 559.2), V(0, 548.8, 559.2), V(556, 548.8, 559.2)});
  wall("right_wall", green, Rgb::Zero(), {V(0, 0, 559.2), V(0, 0, 0), V(0, 548.8, 0), V(0, 548.8, 559.2)});
  wall("left_wall", red, Rgb::Zero(), {V(552.8, 0, 0), V(549.6, 0, 559.2), V(556, 548.8, 559.2), V(556, 548.8, 0)});
  if (blocks) {
    s.objects.push_back(block("short_block", white, {V(130, 165, 65), V(82, 165, 225), V(240, 165, 272), V(290, 165, 114)}));
    s.objects.push_back(block("tall_block", white, {V(423, 330, 247), V(265, 330, 296), V(314, 330, 456), V(472, 330, 406)}));
  }
  return s;
}

}  // namespace fest::radiosity

// Synthetic scenes and the round trip synth -> lumitexels: every sample's normalised
// radiance r must equal the true material's f_r(u, v) u_z (docs/brdffit.md §1).

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "brdffit/lumitexel_builder.hpp"
#include "brdffit/synthetic_scene.hpp"
#include "reflectance/render.hpp"

using namespace fest::brdffit;
using namespace fest::reflectance;

TEST(Synth, IcosphereCountsAndRadius) {
  const TriangleMesh m = icosphere(3, 2.5);
  EXPECT_EQ(m.triangles.size(), 20u * 64u);
  EXPECT_EQ(m.vertices.size(), 10u * 64u + 2u);  // Euler: V = F/2 + 2
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    EXPECT_NEAR(m.vertices[i].norm(), 2.5, 1e-12);
    EXPECT_NEAR(m.normals[i].dot(m.vertices[i].normalized()), 1.0, 1e-12);
  }
}

TEST(Synth, MirrorLobePeakIsNormalisedPhong) {
  const LafortuneLobe lobe = mirror_lobe(Rgb(0.2, 0.3, 0.4), 40);
  LafortuneBrdf b;
  b.lobes = {lobe};
  const Eigen::Vector3d u = Eigen::Vector3d(0.3, -0.2, 0.9).normalized();
  const Eigen::Vector3d v(-u.x(), -u.y(), u.z());
  const Rgb f = evaluate(b, u, v);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], Rgb(0.2, 0.3, 0.4)[c] * 42 / (2 * M_PI), 1e-9);
}

TEST(Synth, PatchesUseEveryMaterial) {
  const TriangleMesh m = icosphere(3, 1);
  const std::vector<std::uint16_t> id = material_patches(m, 5, 1);
  std::vector<int> count(5, 0);
  for (std::uint16_t i : id) ++count[i];
  for (int c : count) EXPECT_GT(c, 100);
}

TEST(Synth, LumitexelSamplesEqualTheTrueBrdf) {
  const TriangleMesh m = icosphere(3, 1.0);
  SurfaceMaterials mats;
  mats.brdfs = palette(3);
  mats.triangle_material = material_patches(m, 3, 1);
  TurntableSetup s;
  s.views = 5;
  s.lights = 2;
  s.width = 160;
  s.height = 120;
  const std::vector<TurntableImage> imgs = turntable_images(m, s);
  std::vector<ImageView> views;
  for (const auto& i : imgs) views.push_back(i.view);
  auto load = [&](std::size_t k) {
    const Rendering r = render(m, mats, views[k].camera, views[k].light);
    return ImagePixels{r.radiance, r.mask, cv::Mat()};
  };
  LumitexelOptions o;
  o.threads = 2;
  LumitexelReport rep;
  const LumitexelSet set = build_lumitexels(m, views, load, o, &rep);
  ASSERT_GT(set.lumitexels.size(), 5000u);
  std::vector<double> rel;
  for (const Lumitexel& l : set.lumitexels) {
    const Eigen::Matrix3d frame = local_frame(l.n.cast<double>());
    for (std::uint16_t k = 0; k < l.count; ++k) {
      const Sample& x = set.samples[l.first_sample + k];
      const Eigen::Vector3d u = frame.transpose() * x.u_world.cast<double>();
      const Eigen::Vector3d v = frame.transpose() * x.v_world.cast<double>();
      const Rgb f = evaluate(mats.brdfs[mats.triangle_material[l.triangle]], u, v) * u.z();
      rel.push_back((x.r.cast<double>() - f).norm() / f.norm());
    }
  }
  std::sort(rel.begin(), rel.end());
  const double median = rel[rel.size() / 2], p90 = rel[rel.size() * 9 / 10];
  std::printf("r vs true f u_z: %zu samples, median relative error %.2e, 90th percentile %.2e, mean samples %.2f\n",
              rel.size(), median, p90, static_cast<double>(set.samples.size()) / set.lumitexels.size());
  // Bilinear resampling mixes neighbouring pixels (other points, other normals): small
  // errors, larger inside sharp highlights and at material borders.
  EXPECT_LT(median, 0.01);
  EXPECT_LT(p90, 0.05);
}

// Texture atlas (docs/brdffit.md §4) and the baked glTF maps (§6, `export`): chart geometry,
// packing without overlaps, gutters under bilinear lookups, and baked values that follow
// from the materials analytically.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "brdffit/home_atlas.hpp"
#include "brdffit/lafortune_model.hpp"
#include "brdffit/pbr_appearance.hpp"
#include "brdffit/synthetic_scene.hpp"
#include "brdffit/texture_atlas.hpp"
#include "brdffit/texture_bake.hpp"
#include "expect_error.hpp"

using namespace fest::brdffit;
using fest::reflectance::LafortuneBrdf;
using fest::reflectance::SurfaceMaterials;
using fest::reflectance::TriangleMesh;

namespace {

// An n x n grid of squares (2 triangles each) in the plane z = 0, side `size`, normals +z.
TriangleMesh plane(int n, double size) {
  TriangleMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      m.vertices.emplace_back(size * i / n, size * j / n, 0.0);
      m.normals.emplace_back(0.0, 0.0, 1.0);
    }
  auto id = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

LafortuneBrdf lobe_brdf(double rho, double n) {
  LafortuneBrdf b;
  b.rho_d = {rho, rho * 0.5, rho * 0.25};
  b.lobes.push_back({{-1, -1, -1}, {1, 1, 1}, {n, n, n}});
  return b;
}

bool rects_overlap(const AtlasChart& a, const AtlasChart& b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

// Number of triangles whose interior holds the texel centre (x + 0.5, y + 0.5).
int owners(const TextureAtlas& atlas, int x, int y) {
  int count = 0;
  const Eigen::Vector2d p(x + 0.5, y + 0.5);
  for (const auto& c : atlas.corners) {
    double s[3];
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d e = c[static_cast<std::size_t>((k + 1) % 3)] - c[static_cast<std::size_t>(k)];
      const Eigen::Vector2d q = p - c[static_cast<std::size_t>(k)];
      s[k] = e.x() * q.y() - e.y() * q.x();
    }
    if ((s[0] > 1e-9 && s[1] > 1e-9 && s[2] > 1e-9) || (s[0] < -1e-9 && s[1] < -1e-9 && s[2] < -1e-9)) ++count;
  }
  return count;
}

}  // namespace

TEST(BrdffitAtlas, SphereChartsHoldTheirTrianglesAndNeverOverlap) {
  const TriangleMesh mesh = icosphere(2, 10.0);
  AtlasOptions o;
  o.gutter = 2;
  const TextureAtlas atlas = build_atlas(mesh, axis_projection(mesh, texel_size_for(mesh, 128)), o);
  ASSERT_EQ(atlas.triangle_chart.size(), mesh.triangles.size());
  // Every triangle in exactly one chart, its corners inside the chart's rectangle less the gutter.
  std::vector<int> seen(mesh.triangles.size(), 0);
  for (std::size_t c = 0; c < atlas.charts.size(); ++c)
    for (std::uint32_t t : atlas.charts[c].triangles) {
      ++seen[t];
      EXPECT_EQ(atlas.triangle_chart[t], c);
    }
  for (int s : seen) EXPECT_EQ(s, 1);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const AtlasChart& ch = atlas.charts[atlas.triangle_chart[t]];
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d& p = atlas.corners[t][static_cast<std::size_t>(k)];
      EXPECT_GE(p.x(), ch.x + o.gutter);
      EXPECT_LE(p.x(), ch.x + ch.width - o.gutter);
      EXPECT_GE(p.y(), ch.y + o.gutter);
      EXPECT_LE(p.y(), ch.y + ch.height - o.gutter);
      const Eigen::Vector2d uv = atlas.uv(t, k);
      EXPECT_GE(uv.x(), 0.0);
      EXPECT_LE(uv.x(), 1.0);
      EXPECT_GE(uv.y(), 0.0);
      EXPECT_LE(uv.y(), 1.0);
    }
  }
  // Charts inside the atlas and pairwise disjoint.
  for (std::size_t a = 0; a < atlas.charts.size(); ++a) {
    const AtlasChart& ca = atlas.charts[a];
    EXPECT_GE(ca.x, 0);
    EXPECT_GE(ca.y, 0);
    EXPECT_LE(ca.x + ca.width, atlas.width);
    EXPECT_LE(ca.y + ca.height, atlas.height);
    for (std::size_t b = a + 1; b < atlas.charts.size(); ++b) EXPECT_FALSE(rects_overlap(ca, atlas.charts[b])) << a << " " << b;
  }
  // No texel centre lies inside two triangles (charts are flat maps without folds).
  for (int y = 0; y < atlas.height; ++y)
    for (int x = 0; x < atlas.width; ++x) ASSERT_LE(owners(atlas, x, y), 1) << x << "," << y;
  // The sphere's six axis groups: at least six charts, and the charts' area is the bulk
  // of the atlas (a dense packing).
  EXPECT_GE(atlas.charts.size(), 6u);
  double area = 0;
  for (const AtlasChart& c : atlas.charts) area += static_cast<double>(c.width) * c.height;
  EXPECT_GT(area / (static_cast<double>(atlas.width) * atlas.height), 0.6);
}

TEST(BrdffitAtlas, PlaneIsOneChartAtTheGivenTexelSize) {
  const TriangleMesh mesh = plane(4, 10.0);
  const double texel = 0.25;  // 40 texels across
  const TextureAtlas atlas = build_atlas(mesh, axis_projection(mesh, texel));
  ASSERT_EQ(atlas.charts.size(), 1u);
  EXPECT_EQ(atlas.width, 40 + 2 * 2);
  EXPECT_EQ(atlas.height, 40 + 2 * 2);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& v = mesh.vertices[mesh.triangles[t][static_cast<std::size_t>(k)]];
      const Eigen::Vector2d& p = atlas.corners[t][static_cast<std::size_t>(k)];
      EXPECT_NEAR(p.x(), v.x() / texel + 2, 1e-9);
      EXPECT_NEAR(p.y(), v.y() / texel + 2, 1e-9);
    }
}

TEST(BrdffitAtlas, FoldedFlatMapSplitsIntoCharts) {
  // Two triangles sharing an edge whose flat maps lie on top of each other (a fold).
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {1, 1, 5}};
  mesh.normals.assign(4, Eigen::Vector3d::UnitZ());
  mesh.triangles = {{0, 1, 2}, {1, 2, 3}};
  FlatTriangles flat;
  flat.group = {0, 0};
  flat.corners = {{Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 0), Eigen::Vector2d(0, 10)},
                  {Eigen::Vector2d(10, 0), Eigen::Vector2d(0, 10), Eigen::Vector2d(1, 1)}};
  const TextureAtlas folded = build_atlas(mesh, flat);
  EXPECT_EQ(folded.charts.size(), 2u);
  // Unfolded (the fourth corner across the shared edge): one chart.
  flat.corners[1][2] = Eigen::Vector2d(10, 10);
  EXPECT_EQ(build_atlas(mesh, flat).charts.size(), 1u);
  // Different groups never share a chart.
  flat.group = {0, 1};
  EXPECT_EQ(build_atlas(mesh, flat).charts.size(), 2u);
}

TEST(BrdffitAtlas, BadInput) {
  const TriangleMesh mesh = plane(1, 1.0);
  FlatTriangles flat = axis_projection(mesh, 0.1);
  FlatTriangles short_flat = flat;
  short_flat.group.pop_back();
  fest::test::expect_bad_input([&] { build_atlas(mesh, short_flat); }, "groups");
  FlatTriangles nan_flat = flat;
  nan_flat.corners[1][2].x() = std::nan("");
  fest::test::expect_bad_input([&] { build_atlas(mesh, nan_flat); }, "not finite");
  AtlasOptions narrow;
  narrow.max_width = 5;
  fest::test::expect_bad_input([&] { build_atlas(mesh, flat, narrow); }, "wide");
  fest::test::expect_bad_input([&] { axis_projection(mesh, 0.0); }, "texel size");
}

TEST(BrdffitBake, ConstantMaterialBakesItsAlbedoAndGuttersCoverBilinearLookups) {
  const TriangleMesh mesh = icosphere(2, 10.0);
  SurfaceMaterials mats;
  mats.brdfs = {lobe_brdf(0.6, 20)};
  mats.triangle_material.assign(mesh.triangles.size(), 0);
  const TextureAtlas atlas = build_atlas(mesh, axis_projection(mesh, texel_size_for(mesh, 96)));
  const TexelSurface texels = texel_surface(atlas);
  const PbrMaps maps = bake_pbr(mesh, atlas, texels, materials_surface(mesh, mats), 2);
  ASSERT_EQ(maps.base_color.cols, atlas.width);
  ASSERT_EQ(maps.base_color.rows, atlas.height);
  const double roughness = std::sqrt(2.0 / 22.0);
  int covered = 0;
  for (int y = 0; y < atlas.height; ++y)
    for (int x = 0; x < atlas.width; ++x) {
      if (!maps.coverage.at<std::uint8_t>(y, x)) continue;
      ++covered;
      const cv::Vec3f b = maps.base_color.at<cv::Vec3f>(y, x);
      EXPECT_FLOAT_EQ(b[0], 0.6f);
      EXPECT_FLOAT_EQ(b[1], 0.3f);
      EXPECT_FLOAT_EQ(b[2], 0.15f);
      EXPECT_NEAR(maps.metallic_roughness.at<cv::Vec3f>(y, x)[1], roughness, 1e-6);
      EXPECT_EQ(maps.metallic_roughness.at<cv::Vec3f>(y, x)[2], 0.f);
    }
  EXPECT_GT(covered, 0);
  // Every point of every triangle: the four texels a bilinear lookup reads are covered and
  // belong to the triangle's own chart.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int s = 0; s < 20; ++s) {
      double a = u(rng), b = u(rng);
      if (a + b > 1) {
        a = 1 - a;
        b = 1 - b;
      }
      const auto& c = atlas.corners[t];
      const Eigen::Vector2d p = (1 - a - b) * c[0] + a * c[1] + b * c[2];
      const int x0 = static_cast<int>(std::floor(p.x() - 0.5)), y0 = static_cast<int>(std::floor(p.y() - 0.5));
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
          const std::size_t i = static_cast<std::size_t>(y0 + dy) * static_cast<std::size_t>(atlas.width) +
                                static_cast<std::size_t>(x0 + dx);
          ASSERT_GE(texels.triangle[i], 0) << "triangle " << t;
          EXPECT_EQ(atlas.triangle_chart[static_cast<std::size_t>(texels.triangle[i])], atlas.triangle_chart[t]);
        }
    }
}

TEST(BrdffitBake, VertexBlendBakesTheLinearFunctionOfPosition) {
  // Weight of material 1 = x / 10 on a 10 x 10 plane: base colour linear in x.
  const TriangleMesh mesh = plane(5, 10.0);
  SurfaceMaterials mats;
  mats.brdfs = {lobe_brdf(0.2, 10), lobe_brdf(0.8, 100)};
  for (const auto& v : mesh.vertices) {
    mats.vertex_weights.push_back(static_cast<float>(1 - v.x() / 10));
    mats.vertex_weights.push_back(static_cast<float>(v.x() / 10));
  }
  const double texel = 0.2;
  const TextureAtlas atlas = build_atlas(mesh, axis_projection(mesh, texel));
  const PbrMaps maps = bake_pbr(mesh, atlas, texel_surface(atlas), materials_surface(mesh, mats), 1);
  // World x of a texel centre from the atlas corner of vertex 0 (independent of the bake).
  const Eigen::Vector2d origin = atlas.corners[0][0];
  for (int y = 0; y < atlas.height; ++y)
    for (int x = 0; x < atlas.width; ++x) {
      const double raw_x = (x + 0.5 - origin.x()) * texel, wy = (y + 0.5 - origin.y()) * texel;
      const double out_x = std::max({0.0, -raw_x, raw_x - 10}), out_y = std::max({0.0, -wy, wy - 10});
      if (std::hypot(out_x, out_y) > 2 * texel) continue;  // beyond the gutter
      const double wx = std::clamp(raw_x, 0.0, 10.0);     // the gutter repeats the border value
      ASSERT_TRUE(maps.coverage.at<std::uint8_t>(y, x)) << x << "," << y;
      const double t = wx / 10;
      EXPECT_NEAR(maps.base_color.at<cv::Vec3f>(y, x)[0], 0.2 * (1 - t) + 0.8 * t, 1e-5) << x << "," << y;
      EXPECT_NEAR(maps.metallic_roughness.at<cv::Vec3f>(y, x)[1],
                  std::sqrt(2.0 / ((t > 0.5 ? 100.0 : 10.0) + 2.0)), 1e-5 + (std::abs(t - 0.5) < 0.03 ? 1.0 : 0.0));
    }
}

TEST(BrdffitBake, NormalMapDecodesToTheRefinedNormalInTheGltfFrame) {
  const TriangleMesh mesh = icosphere(1, 5.0);
  const TextureAtlas atlas = build_atlas(mesh, axis_projection(mesh, texel_size_for(mesh, 64)));
  const TexelSurface texels = texel_surface(atlas);
  // Refined normal: the mesh's interpolated normal tilted by 10 degrees about a fixed axis.
  const Eigen::AngleAxisd tilt(10 * M_PI / 180, Eigen::Vector3d(1, 2, 3).normalized());
  auto refined = [&](std::uint32_t t, const Eigen::Vector3d& b) {
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < 3; ++k) n += b[static_cast<Eigen::Index>(k)] * mesh.normals[mesh.triangles[t][k]];
    return (tilt * n.normalized()).eval();
  };
  const PbrMaps maps = bake_pbr(mesh, atlas, texels, [&](std::uint32_t t, const Eigen::Vector3d& b) {
    PbrPoint p;
    p.normal = refined(t, b);
    return p;
  });
  // Decode as a glTF viewer does: n = T x + B y + N z with T, N interpolated from the
  // TANGENT and NORMAL attributes and B = cross(N, T) w.
  const auto tangents = corner_tangents(mesh, atlas);
  int checked = 0;
  for (std::size_t i = 0; i < texels.triangle.size(); ++i) {
    if (texels.triangle[i] < 0 || texels.distance[i] > 0) continue;
    const auto t = static_cast<std::size_t>(texels.triangle[i]);
    const Eigen::Vector3d& b = texels.bary[i];
    Eigen::Vector3d nrm = Eigen::Vector3d::Zero(), tan = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < 3; ++k) {
      nrm += b[static_cast<Eigen::Index>(k)] * mesh.normals[mesh.triangles[t][k]];
      tan += b[static_cast<Eigen::Index>(k)] * tangents[t][k].head<3>();
    }
    nrm.normalize();
    tan.normalize();
    const Eigen::Vector3d bit = nrm.cross(tan) * tangents[t][0].w();
    const cv::Vec3f e = maps.normal.at<cv::Vec3f>(static_cast<int>(i) / atlas.width, static_cast<int>(i) % atlas.width);
    const Eigen::Vector3d decoded = (tan * e[0] + bit * e[1] + nrm * e[2]).normalized();
    EXPECT_LT((decoded - refined(static_cast<std::uint32_t>(t), b)).norm(), 2e-3);
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(BrdffitPbr, RoughnessAndBlendFollowTheDocumentedMapping) {
  EXPECT_NEAR(pbr_roughness(lobe_brdf(0.5, 40)), std::sqrt(2.0 / 42.0), 1e-12);
  EXPECT_EQ(pbr_roughness(LafortuneBrdf{}), 1.0);
  const LafortuneBrdf a = lobe_brdf(0.4, 10), b = lobe_brdf(0.2, 200);
  const float w[2] = {0.3f, 0.7f};
  const PbrPoint p = pbr_of_blend({&a, &b}, w, false);
  EXPECT_NEAR(p.base_color[0], 0.3 * 0.4 + 0.7 * 0.2, 1e-6);
  EXPECT_NEAR(p.base_color[2], 0.3 * 0.1 + 0.7 * 0.05, 1e-6);
  EXPECT_NEAR(p.roughness, std::sqrt(2.0 / 202.0), 1e-12);  // b dominates
  EXPECT_EQ(p.metallic, 0.0);
  // rgb weights, channel-major: red takes only a, green and blue only b.
  const float wrgb[6] = {1, 0, 0.2f, 0.8f, 0.2f, 0.8f};
  const PbrPoint q = pbr_of_blend({&a, &b}, wrgb, true);
  EXPECT_NEAR(q.base_color[0], 0.4, 1e-6);
  EXPECT_NEAR(q.base_color[1], 0.2 * 0.2 + 0.8 * 0.1, 1e-6);
}

TEST(BrdffitPbr, LumitexelSurfaceTakesTheNearestLumitexelAndFallsBack) {
  const TriangleMesh mesh = plane(1, 10.0);  // triangles 0 and 1
  Projection p;
  p.basis.model.lobes = 1;
  p.basis.brdfs = {from_brdf(p.basis.model, lobe_brdf(0.2, 10)), from_brdf(p.basis.model, lobe_brdf(0.8, 50))};
  p.basis.cluster_basis = {{0, 1}};
  p.basis_size = 2;
  LumitexelSet set;
  for (float x : {2.f, 8.f}) {
    Lumitexel l;
    l.p = {x, 1, 0};
    l.triangle = 0;
    l.count = 3;
    set.lumitexels.push_back(l);
  }
  p.cluster = {0, 0};
  p.weights = {1, 0, 0, 1};  // lumitexel 0: pure f_0, lumitexel 1: pure f_1
  SurfaceMaterials fallback;
  fallback.brdfs = {lobe_brdf(0.5, 5)};
  fallback.triangle_material = {0, 0};
  const LumitexelSurface s(mesh, set, p, fallback, {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()});
  // Triangle 0 = (0,0), (10,0), (10,10): bary (0.8, 0.1, 0.1) is (2, 1): lumitexel 0.
  PbrPoint q = s(0, Eigen::Vector3d(0.8, 0.1, 0.1));
  EXPECT_NEAR(q.base_color[0], 0.2, 1e-6);
  EXPECT_EQ(q.normal, Eigen::Vector3d::UnitX());
  q = s(0, Eigen::Vector3d(0.1, 0.8, 0.1));  // (9, 1): lumitexel 1
  EXPECT_NEAR(q.base_color[0], 0.8, 1e-6);
  EXPECT_EQ(q.normal, Eigen::Vector3d::UnitY());
  q = s(1, Eigen::Vector3d(1.0 / 3, 1.0 / 3, 1.0 / 3));  // no lumitexel: the fallback
  EXPECT_NEAR(q.base_color[0], 0.5, 1e-6);
  EXPECT_EQ(q.normal, Eigen::Vector3d::Zero());
  fest::test::expect_bad_input([&] { LumitexelSurface(mesh, set, p, fallback, {Eigen::Vector3d::UnitX()}); },
                               "refined normals");
  Projection wrong = p;
  wrong.cluster = {0};
  fest::test::expect_bad_input([&] { LumitexelSurface(mesh, set, wrong, fallback); }, "lumitexels");
}

TEST(BrdffitHomeAtlas, TexelsReadTheirHomeImagesPixelsUnfiltered) {
  // A 2 x 2 plane seen head-on by one camera (100 px per unit); the "photograph" holds its
  // own pixel coordinates, radiance(i, j) = (i, j, 1).
  const TriangleMesh mesh = [] {
    TriangleMesh m = plane(4, 2.0);
    for (auto& v : m.vertices) v -= Eigen::Vector3d(1, 1, 0);
    return m;
  }();
  ImageView view;
  view.camera.fx = view.camera.fy = 100;
  view.camera.cx = view.camera.cy = 150;
  view.camera.width = view.camera.height = 300;
  view.camera.t = Eigen::Vector3d(0, 0, 10);
  HomeAssignment home;
  home.image.assign(mesh.triangles.size(), 0);
  const FlatTriangles flat = home_image_projection(mesh, {view}, home);
  const TextureAtlas atlas = build_atlas(mesh, flat);
  ASSERT_EQ(atlas.charts.size(), 1u);
  // The plane spans pixel centres 140..160 (edges on pixel centres): 21 texels, the corners
  // at half-integer texel coordinates, plus the gutters.
  EXPECT_EQ(atlas.width, 21 + 2 * 2);
  cv::Mat photo(300, 300, CV_32FC3);
  for (int y = 0; y < 300; ++y)
    for (int x = 0; x < 300; ++x) photo.at<cv::Vec3f>(y, x) = cv::Vec3f(static_cast<float>(x), static_cast<float>(y), 1);
  const TexelSurface texels = texel_surface(atlas);
  cv::Mat rgb(atlas.height, atlas.width, CV_32FC3, cv::Scalar(0, 0, 0));
  sample_home_image(mesh, texels, home, 0, view, photo, rgb);
  int inside = 0;
  for (int y = 0; y < atlas.height; ++y)
    for (int x = 0; x < atlas.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * atlas.width + x);
      if (texels.triangle[i] < 0 || texels.distance[i] > 0) continue;
      ++inside;
      const cv::Vec3f v = rgb.at<cv::Vec3f>(y, x);
      // A whole-pixel shift: texel (x, y) is pixel (x + dx, y + dy), one (dx, dy) for the chart.
      EXPECT_NEAR(v[0] - x, 140 - 2, 1e-4);
      EXPECT_NEAR(v[1] - y, 140 - 2, 1e-4);
      EXPECT_EQ(v[2], 1.f);
    }
  EXPECT_EQ(inside, 21 * 21);
  // Unseen triangles get charts of their own after the images.
  home.image[3] = -1;
  const FlatTriangles mixed = home_image_projection(mesh, {view}, home);
  EXPECT_GE(mixed.group[3], 1u);
  home.image.assign(mesh.triangles.size(), -1);
  fest::test::expect_bad_input([&] { home_image_projection(mesh, {view}, home); }, "no triangle");
}

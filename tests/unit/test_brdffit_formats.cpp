#include <cmath>

#include <gtest/gtest.h>

#include "brdffit/brdf_json.hpp"
#include "brdffit/lafortune_fit.hpp"
#include "brdffit/ltw_format.hpp"
#include "brdffit/merl.hpp"
#include "brdffit_test_data.hpp"
#include "core/error.hpp"
#include "formats/brdf/merl_io.hpp"

using namespace fest::brdffit;
using fest::reflectance::LafortuneBrdf;

namespace {

Projection small_projection(WeightMode mode) {
  Projection p;
  p.basis.model = ModelSpec{};
  for (const auto& m : brdffit_test::three_materials()) p.basis.brdfs.push_back(from_brdf(ModelSpec{}, m));
  p.basis.cluster_basis = {{0, 1, 2}, {1, 0}};
  p.basis_size = 3;
  p.mode = mode;
  p.cluster = {0, 1, 1, 0};
  for (int i = 0; i < 4 * p.values_per_lumitexel(); ++i) p.weights.push_back(0.25f * static_cast<float>(i) - 1);
  return p;
}

template <typename F>
fest::Status status_of(F&& f) {
  try {
    f();
  } catch (const fest::Error& e) {
    return e.status();
  }
  return fest::Status::ok;
}

}  // namespace

TEST(BrdffitLtw, RoundTripsBothWeightModes) {
  for (WeightMode mode : {WeightMode::scalar, WeightMode::rgb}) {
    const Projection p = small_projection(mode);
    const std::string bytes = encode_ltw(p, {{"mesh_sha256", "abc"}});
    EXPECT_EQ(bytes.substr(0, 8), "LUMIWGT1");
    nlohmann::json h;
    const Projection q = decode_ltw(bytes, &h);
    EXPECT_EQ(h["mesh_sha256"], "abc");
    EXPECT_EQ(q.cluster, p.cluster);
    EXPECT_EQ(q.weights, p.weights);
    EXPECT_EQ(q.basis.cluster_basis, p.basis.cluster_basis);
    EXPECT_EQ(q.mode, mode);
    ASSERT_EQ(q.basis.brdfs.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(q.basis.brdfs[i], p.basis.brdfs[i]);
  }
}

TEST(BrdffitLtw, WrongMagicTruncationAndBadRecordsAreBadInput) {
  const std::string bytes = encode_ltw(small_projection(WeightMode::scalar));
  std::string wrong = bytes;
  wrong[3] = 'X';
  EXPECT_EQ(status_of([&] { decode_ltw(wrong); }), fest::Status::bad_input);
  EXPECT_EQ(status_of([&] { decode_ltw(bytes.substr(0, bytes.size() - 1)); }), fest::Status::bad_input);
  EXPECT_EQ(status_of([&] { decode_ltw(bytes.substr(0, 20)); }), fest::Status::bad_input);
  EXPECT_EQ(status_of([&] { decode_ltw(bytes.substr(0, 5)); }), fest::Status::bad_input);
  std::string bad_cluster = bytes;
  bad_cluster[bytes.size() - 14] = 9;  // the last record's cluster (u16 + 3 f32 = 14 bytes)
  EXPECT_EQ(status_of([&] { decode_ltw(bad_cluster); }), fest::Status::bad_input);
  try {
    decode_ltw(bytes.substr(0, bytes.size() - 3));
  } catch (const fest::Error& e) {
    EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos);
  }
}

TEST(BrdffitJson, BrdfAndClustersRoundTrip) {
  const LafortuneBrdf clay = fest::reflectance::clay();
  const LafortuneBrdf back = brdf_from_json(nlohmann::json::parse(brdf_to_json(clay).dump()));
  EXPECT_EQ(back.rho_d, clay.rho_d);
  ASSERT_EQ(back.lobes.size(), 3u);
  EXPECT_EQ(back.lobes[2].n, clay.lobes[2].n);
  ClusterResult r;
  r.model = ModelSpec{1, false};
  MaterialCluster c;
  c.params = from_brdf(r.model, brdffit_test::three_materials()[1]);
  c.covariance = Eigen::MatrixXd::Identity(12, 12) * 0.5;
  c.members = 7;
  r.clusters = {c};
  r.history = {SplitRecord{0, 1, 2, 3, 10, 5}};
  const ClusterResult q = clusters_from_json(nlohmann::json::parse(clusters_to_json(r).dump()));
  EXPECT_EQ(q.clusters[0].params, c.params);
  EXPECT_EQ(q.clusters[0].covariance, c.covariance);
  EXPECT_EQ(q.clusters[0].members, 7u);
  EXPECT_EQ(status_of([] { brdf_from_json(nlohmann::json::parse(R"({"model":"phong"})")); }), fest::Status::bad_input);
  EXPECT_EQ(status_of([] { clusters_from_json(nlohmann::json::parse(R"({"model":{"lobes":1},"clusters":[{"params":[1]}]})")); }),
            fest::Status::bad_input);
}

TEST(BrdffitMerl, IndexMappingRoundTripsAndHasTheSquareRootWarp) {
  // docs/brdffit.md §7: cell centre -> directions -> half/diff angles -> the same cell.
  for (int a : {0, 1, 5, 44, 89})
    for (int b : {0, 17, 89})
      for (int c : {0, 90, 179}) {
        Eigen::Vector3d u, v;
        merl_cell_directions(a, b, c, &u, &v);
        double th, td, pd;
        half_diff(u, v, &th, &td, &pd);
        EXPECT_EQ(merl_theta_h_index(th), a);
        EXPECT_EQ(merl_theta_d_index(td), b);
        EXPECT_EQ(merl_phi_d_index(pd), c);
      }
  // theta_h = (i / 90)^2 pi / 2 is the start of cell i: index 45 at a quarter of 90 degrees.
  EXPECT_EQ(merl_theta_h_index(0.25 * M_PI / 2 + 1e-9), 45);
  EXPECT_EQ(merl_theta_h_index(0.25 * M_PI / 2 - 1e-9), 44);
  EXPECT_EQ(merl_theta_h_index(M_PI / 2), 89);
  EXPECT_EQ(merl_phi_d_index(-0.1), merl_phi_d_index(M_PI - 0.1));  // reciprocity
}

TEST(BrdffitMerl, GeneratedFileReadsBackExactlyAndFits) {
  // docs/brdffit.md §7: a file written in the MERL layout from a known analytic BRDF reads
  // back exactly; fitting its samples recovers the BRDF.
  LafortuneBrdf b;
  b.rho_d = fest::reflectance::Rgb(0.3, 0.2, 0.1);
  b.lobes = {fest::reflectance::LafortuneLobe{fest::reflectance::Rgb::Constant(-1), fest::reflectance::Rgb::Constant(1),
                                             fest::reflectance::Rgb::Constant(15)}};
  const MerlTable t = merl_from_brdf(b);
  fest::formats::MerlFile f;
  f.values = t.values;
  const std::string bytes = fest::formats::write_merl(f);
  EXPECT_EQ(bytes.size(), 12u + 8u * 3u * 90u * 90u * 180u);
  const fest::formats::MerlFile g = fest::formats::read_merl(bytes);
  EXPECT_EQ(g.values, t.values);
  Eigen::Vector3d u, v;
  merl_cell_directions(30, 20, 100, &u, &v);
  const Eigen::Vector3d looked = merl_lookup(MerlTable{g.values}, u, v);
  EXPECT_NEAR((looked - evaluate(b, u, v)).norm(), 0, 1e-12);
  FitOptions o;
  o.subsample = 20000;
  o.threads = 2;
  const FitResult r = fit_brdf(merl_samples(MerlTable{g.values}), o);
  EXPECT_LE(brdffit_test::relative_rms(r.brdf, b), 1e-6);
  EXPECT_EQ(status_of([&] { fest::formats::read_merl(bytes.substr(0, 1000)); }), fest::Status::bad_input);
  std::string dims = bytes;
  dims[0] = 91;
  EXPECT_EQ(status_of([&] { fest::formats::read_merl(dims); }), fest::Status::bad_input);
}

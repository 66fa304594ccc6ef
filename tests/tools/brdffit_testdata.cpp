// Known-answer inputs for brdffit's materials CLI tests (tests/cli/brdffit_materials.sh):
//
//   brdffit_testdata ltx COUNT PER MATERIALS NOISE SEED BUMP_DEG TRUTH.csv > set.ltx
//       COUNT lumitexels with PER samples each of material (i mod MATERIALS) from the
//       three materials of tests/unit/brdffit_test_data.hpp, multiplicative noise NOISE;
//       with BUMP_DEG > 0 the samples come from a normal tilted by BUMP_DEG from the
//       stored one. TRUTH.csv: material and true normal per lumitexel.
//   brdffit_testdata samples clay|onelobe COUNT SEED NOISE > samples.csv
//   brdffit_testdata merl > onelobe.binary      (the one-lobe BRDF in the MERL layout)
//
// The .ltx is written by the stand-in codec of tools/brdffit until the geometry side's
// ltx_format is merged.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

#include "brdffit/ltx_format.hpp"
#include "brdffit/merl.hpp"
#include "brdffit_test_data.hpp"
#include "formats/brdf/merl_io.hpp"

namespace {

using fest::reflectance::LafortuneBrdf;
using fest::reflectance::LafortuneLobe;
using fest::reflectance::Rgb;

LafortuneBrdf one_lobe() {
  LafortuneBrdf b;
  b.rho_d = Rgb::Constant(0.3);
  b.lobes = {LafortuneLobe{Rgb::Constant(-1.0), Rgb::Constant(1.0), Rgb::Constant(40)}};
  return b;
}

int usage() {
  std::fprintf(stderr, "usage: brdffit_testdata ltx COUNT PER MATERIALS NOISE SEED BUMP_DEG TRUTH.csv | samples clay|onelobe COUNT SEED NOISE | merl\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage();
  const std::string what = argv[1];
  if (what == "ltx" && argc == 9) {
    const int count = std::atoi(argv[2]), per = std::atoi(argv[3]), k = std::atoi(argv[4]);
    const double noise = std::atof(argv[5]), bump = std::atof(argv[7]) * M_PI / 180;
    const auto seed = static_cast<unsigned>(std::atoi(argv[6]));
    const auto mats = brdffit_test::three_materials();
    std::vector<Eigen::Vector3d> truth;
    fest::brdffit::LumitexelSet set =
        brdffit_test::make_set(count, per, seed, noise, [&](int i) { return mats[static_cast<std::size_t>(i % k)]; }, &truth);
    // The stored (mesh) normal is the true one tilted by BUMP_DEG in a random direction;
    // the samples stay those of the true normal.
    std::mt19937_64 rng(seed + 1);
    std::uniform_real_distribution<double> u01(0, 1);
    FILE* t = std::fopen(argv[8], "w");
    if (!t) return 4;
    std::fprintf(t, "material,nx,ny,nz\n");
    for (std::size_t i = 0; i < set.lumitexels.size(); ++i) {
      auto& l = set.lumitexels[i];
      l.p = Eigen::Vector3f(static_cast<float>(i), 0, 0);
      if (bump > 0) {
        const Eigen::Matrix3d f = fest::reflectance::local_frame(truth[i]);
        const double az = 2 * M_PI * u01(rng);
        l.n = (std::cos(bump) * truth[i] + std::sin(bump) * (std::cos(az) * f.col(0) + std::sin(az) * f.col(1))).normalized().cast<float>();
      }
      std::fprintf(t, "%d,%.9g,%.9g,%.9g\n", static_cast<int>(i) % k, truth[i].x(), truth[i].y(), truth[i].z());
    }
    std::fclose(t);
    set.mesh_sha256 = "0000test";
    // The .ltx names the images its samples come from; these sets have no real photographs.
    std::uint16_t images = 0;
    for (const auto& smp : set.samples) images = std::max<std::uint16_t>(images, static_cast<std::uint16_t>(smp.image + 1));
    for (std::uint16_t i = 0; i < images; ++i) set.images.push_back("synthetic_" + std::to_string(i));
    const std::vector<std::uint8_t> ltx = fest::brdffit::encode_ltx(set, nlohmann::json::object());
    std::cout.write(reinterpret_cast<const char*>(ltx.data()), static_cast<std::streamsize>(ltx.size()));
    return 0;
  }
  if (what == "samples" && argc == 6) {
    const std::string name = argv[2];
    const LafortuneBrdf b = name == "clay" ? fest::reflectance::clay() : one_lobe();
    // The directions and noise of brdffit_test::samples_of, written as text.
    std::mt19937_64 rng(static_cast<unsigned>(std::atoi(argv[4])));
    std::normal_distribution<double> g(0, 1);
    std::printf("ux,uy,uz,vx,vy,vz,r,g,b\n");
    for (int i = 0; i < std::atoi(argv[3]); ++i) {
      const Eigen::Vector3d u = brdffit_test::hemisphere(rng);
      const Eigen::Vector3d v = (i % 2) ? brdffit_test::near_mirror(rng, u, 0.25) : brdffit_test::hemisphere(rng);
      Eigen::Vector3d r = evaluate(b, u, v) * u.z();
      if (std::atof(argv[5]) > 0)
        for (int c = 0; c < 3; ++c) r[c] *= 1 + std::atof(argv[5]) * g(rng);
      std::printf("%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", u.x(), u.y(), u.z(), v.x(), v.y(), v.z(), r[0], r[1], r[2]);
    }
    return 0;
  }
  if (what == "merl" && argc == 2) {
    fest::formats::MerlFile f;
    f.values = fest::brdffit::merl_from_brdf(one_lobe()).values;
    std::cout << fest::formats::write_merl(f);
    return 0;
  }
  return usage();
}

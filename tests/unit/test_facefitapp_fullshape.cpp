// fest_facefit_app called with typed options (no argv): a model built from three meshes
// in correspondence spans their mean and differences, so projecting one of them into the
// model with η = 0 gives it back exactly -- known by construction (the regularised
// projection with L = identity, docs/facefit.md).

#include <unistd.h>

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "commands.hpp"

namespace {

namespace fs = std::filesystem;
using namespace fest::facefit_tool;
using Points = std::vector<std::array<double, 3>>;

void write_off(const fs::path& p, const Points& v) {
  std::ofstream out(p);
  out << "OFF\n" << v.size() << " 2 0\n";
  for (const auto& x : v) out << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
  out << "3 0 1 2\n3 0 2 3\n";
}

Points read_off(const fs::path& p) {
  std::ifstream in(p);
  std::string magic;
  std::size_t nv = 0, nf = 0, ne = 0;
  in >> magic >> nv >> nf >> ne;
  Points v(nv);
  for (auto& x : v) in >> x[0] >> x[1] >> x[2];
  return v;
}

TEST(FacefitApp, ExampleMeshProjectsOntoItself) {
  const fs::path dir = fs::temp_directory_path() / ("fest_facefitapp_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const Points a{{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}};
  const Points b{{0, 0, 1}, {10, 0, 0}, {10, 10, 2}, {0, 10, 0}};
  const Points c{{1, 0, 0}, {10, 0, 3}, {10, 11, 0}, {0, 10, -1}};
  write_off(dir / "a.off", a);
  write_off(dir / "b.off", b);
  write_off(dir / "c.off", c);

  BuildArgs build;
  build.examples = {(dir / "a.off").string(), (dir / "b.off").string(), (dir / "c.off").string()};
  build.output = (dir / "model.mmb").string();
  build.f64 = true;
  ASSERT_EQ(run_build(build), 0);

  FitArgs fit;
  fit.model = build.output;
  fit.full_shape = (dir / "c.off").string();
  fit.eta.value = 0;
  fit.output = (dir / "fit.off").string();
  ASSERT_EQ(run_fit(fit), 0);

  const Points got = read_off(dir / "fit.off");
  ASSERT_EQ(got.size(), c.size());
  for (std::size_t i = 0; i < c.size(); ++i)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[i][k], c[i][k], 1e-6) << "vertex " << i << " axis " << k;
  fs::remove_all(dir);
}

}  // namespace

// Where a limit of the materials stages is reported: lib/brdffit in its own terms, the
// tool (tools/brdffit/option_checks) in the flags' names, with the same exit status.

#include "option_checks.hpp"

#include <string>

#include <gtest/gtest.h>

#include "brdffit/cluster.hpp"
#include "brdffit/lafortune_model.hpp"
#include "brdffit/normals.hpp"
#include "brdffit_test_data.hpp"
#include "core/error.hpp"

using namespace fest;

namespace {

// The message of the usage error `f` throws.
template <typename F>
std::string usage_message(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), Status::usage);
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return {};
}

}  // namespace

TEST(BrdffitOptionChecks, FitFlagsNameTheFlags) {
  brdffit_tool::FitFlags f;
  f.lobes = 4;
  EXPECT_EQ(usage_message([&] { brdffit_tool::fit_options(f); }), "--lobes must be 1, 2 or 3, not 4");
  f.lobes = 1;
  f.starts = 0;
  EXPECT_EQ(usage_message([&] { brdffit_tool::fit_options(f); }), "--starts must be 1..4, not 0");
  f.starts = 2;
  f.huber_delta = 0.5;
  const brdffit::FitOptions o = brdffit_tool::fit_options(f);
  EXPECT_EQ(o.starts, 2);
  EXPECT_EQ(o.huber_delta, 0.5);
  EXPECT_GE(o.threads, 1);
}

TEST(BrdffitOptionChecks, LibraryStatesTheSameLimitsWithoutFlags) {
  brdffit::ModelSpec spec;
  spec.lobes = 4;
  const std::string lib = usage_message([&] { brdffit::parameter_count(spec); });
  EXPECT_EQ(lib.find("--"), std::string::npos) << lib;
  EXPECT_NE(lib.find("lobe"), std::string::npos) << lib;

  brdffit::ClusterOptions c;
  c.split_scale = 0;
  EXPECT_EQ(usage_message([&] { brdffit_tool::check_cluster_options(c); }), "--split-scale must be positive");
  const brdffit::LumitexelSet set = brdffit_test::make_set(
      20, 6, 1, 0.0, [](int) { return brdffit_test::three_materials()[0]; });
  const std::string in_lib = usage_message([&] { brdffit::cluster_lumitexels(set, brdffit::local_samples(set, 1), c); });
  EXPECT_EQ(in_lib.find("--"), std::string::npos) << in_lib;

  brdffit::NormalOptions n;
  n.max_tilt_deg = 95;
  EXPECT_EQ(usage_message([&] { brdffit_tool::check_normal_options(n); }), "--max-tilt must lie in (0, 90) degrees");
  EXPECT_EQ(usage_message([] { brdffit_tool::check_basis(65); }), "--basis must be 1..64, not 65");
}

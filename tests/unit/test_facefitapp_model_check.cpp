// lib/core's model check refuses a basis that is not orthonormal in the model's own terms;
// the tool adds the flag that would accept it (--fix-basis), and only where it would.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "face_files.hpp"
#include "facefit_fixtures.hpp"

namespace {

using namespace facefit_test;

std::string refusal(Model m, bool fix_basis) {
  try {
    fest::facefit_tool::check_model_naming_flags(m, fix_basis);
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::bad_input);
    return e.what();
  }
  return {};
}

TEST(FacefitAppModelCheck, NonUnitColumnNamesFixBasis) {
  Model m = g1_model(true, 5);
  Eigen::MatrixXd S = basis_matrix(m);
  S.col(2) *= 1.5;
  set_owned_basis(m, S);
  const std::string what = refusal(m, false);
  EXPECT_EQ(what, "model: basis column 2 has norm 1.5, not 1; --fix-basis renormalises it");
  EXPECT_EQ(refusal(m, true), "");
  Model fixed = m;
  EXPECT_TRUE(fest::facefit_tool::check_model_naming_flags(fixed, true).renormalised);
  EXPECT_NEAR(basis_matrix(fixed).col(2).norm(), 1.0, 1e-12);
}

TEST(FacefitAppModelCheck, OtherRefusalsDoNotNameIt) {
  Model m = g1_model(true, 5);
  m.mean[3] = std::nan("");
  EXPECT_EQ(refusal(m, false), "model: non-finite value in the mean");
  Eigen::MatrixXd S = basis_matrix(m);
  S.col(1) *= 2;
  set_owned_basis(m, S);  // both wrong: renormalising alone would not accept it
  EXPECT_EQ(refusal(m, false), "model: non-finite value in the mean");
}

}  // namespace

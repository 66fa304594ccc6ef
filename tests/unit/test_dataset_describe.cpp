// describe_dataset against values known from how the samples are built.

#include <cmath>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_dataset_vtk_adapter.hpp"
#include "lib/core/error.hpp"
#include "test_dataset_samples.hpp"

namespace fest::formats {
namespace {

const nlohmann::json* find_array(const nlohmann::json& arrays, const std::string& name) {
  for (const auto& a : arrays)
    if (a.at("name") == name) return &a;
  return nullptr;
}

TEST(DatasetDescribe, ImageGeometryAndAnalyticRange) {
  nlohmann::json d = describe_dataset(test::make_image());
  EXPECT_EQ(d.at("dataset_type"), "vtkImageData");
  EXPECT_EQ(d.at("points"), 4 * 5 * 6);
  EXPECT_EQ(d.at("cells"), 3 * 4 * 5);
  EXPECT_EQ(d.at("dimensions"), nlohmann::json({4, 5, 6}));
  EXPECT_EQ(d.at("spacing"), nlohmann::json({1.0, 1.0, 1.0}));
  EXPECT_EQ(d.at("origin"), nlohmann::json({0.0, 0.0, 0.0}));
  EXPECT_EQ(d.at("bbox").at("min"), nlohmann::json({0.0, 0.0, 0.0}));
  EXPECT_EQ(d.at("bbox").at("max"), nlohmann::json({3.0, 4.0, 5.0}));
  const nlohmann::json* f = find_array(d.at("point_arrays"), "f");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->at("components"), 1);
  EXPECT_EQ(f->at("type"), "double");
  EXPECT_EQ(f->at("range_of"), "values");
  // f = x + 2y + 3z over x < 4, y < 5, z < 6.
  EXPECT_EQ(f->at("range"), nlohmann::json({0.0, 3.0 + 2 * 4.0 + 3 * 5.0}));
  const nlohmann::json* ids = find_array(d.at("cell_arrays"), "cell_id");
  ASSERT_NE(ids, nullptr);
  EXPECT_EQ(ids->at("range"), nlohmann::json({0.0, 59.0}));
}

TEST(DatasetDescribe, RotationFieldMagnitude) {
  nlohmann::json d = describe_dataset(test::make_tets());
  EXPECT_EQ(d.at("dataset_type"), "vtkUnstructuredGrid");
  EXPECT_EQ(d.at("points"), 8);
  EXPECT_EQ(d.at("cells"), 6);
  EXPECT_EQ(d.at("bbox").at("min"), nlohmann::json({0.0, 0.0, 0.0}));
  EXPECT_EQ(d.at("bbox").at("max"), nlohmann::json({1.0, 1.0, 1.0}));
  EXPECT_FALSE(d.contains("dimensions"));
  const nlohmann::json* v = find_array(d.at("point_arrays"), "velocity");
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->at("components"), 3);
  EXPECT_EQ(v->at("range_of"), "magnitude");
  // |(-y, x, 0)| = sqrt(x^2 + y^2): 0 on the z axis, sqrt(2) at x = y = 1.
  EXPECT_DOUBLE_EQ(v->at("range")[0].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(v->at("range")[1].get<double>(), std::sqrt(2.0));
  const nlohmann::json* region = find_array(d.at("cell_arrays"), "region");
  ASSERT_NE(region, nullptr);
  EXPECT_EQ(region->at("type"), "int");
  EXPECT_EQ(region->at("range"), nlohmann::json({10.0, 15.0}));
}

TEST(DatasetDescribe, PolyDataCountsEveryCellKind) {
  nlohmann::json d = describe_dataset(test::make_poly());
  EXPECT_EQ(d.at("dataset_type"), "vtkPolyData");
  EXPECT_EQ(d.at("points"), 8);
  EXPECT_EQ(d.at("cells"), 3 + 1 + 1 + 1);  // quads, strip, line, vertex
  EXPECT_EQ(d.at("bbox").at("max"), nlohmann::json({1.5, 0.25, 0.0}));
  const nlohmann::json* h = find_array(d.at("point_arrays"), "height");
  ASSERT_NE(h, nullptr);
  EXPECT_EQ(h->at("range"), nlohmann::json({0.0, 1.5 * 0.25}));
}

TEST(DatasetDescribe, EmptyDatasetHasNoBoundingBox) {
  nlohmann::json d = describe_dataset(vtkSmartPointer<vtkUnstructuredGrid>::New());
  EXPECT_EQ(d.at("points"), 0);
  EXPECT_FALSE(d.contains("bbox"));
  EXPECT_TRUE(d.at("point_arrays").empty());
}

TEST(DatasetDescribe, NullIsAnError) { EXPECT_THROW(describe_dataset(nullptr), Error); }

}  // namespace
}  // namespace fest::formats

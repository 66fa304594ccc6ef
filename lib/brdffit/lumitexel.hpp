#pragma once
// Lumitexels (docs/brdffit.md §4; chapter 8 §8.4.3, §8.6.3): one surface point with
// every observation of it. Stored flat, as in the .ltx file: the samples of lumitexel i are
// samples[first_sample, first_sample + count), and the lumitexels of one triangle are
// contiguous so a texture atlas can be built from them later.
//
// A sample's radiance is normalised for the point light: r = L d^2 / I = f_r(u, v) u_z,
// with u towards the light and v towards the camera (world frame; the local frame of a
// lumitexel is reflectance::local_frame(n)).

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace fest::brdffit {

struct Sample {
  std::uint16_t image = 0;  // index into LumitexelSet::images
  Eigen::Vector3f u_world = Eigen::Vector3f::Zero();
  Eigen::Vector3f v_world = Eigen::Vector3f::Zero();
  Eigen::Vector3f r = Eigen::Vector3f::Zero();  // RGB
  float weight = 1;
};

struct Lumitexel {
  Eigen::Vector3f p = Eigen::Vector3f::Zero();
  Eigen::Vector3f n = Eigen::Vector3f::UnitZ();  // unit
  std::uint32_t triangle = 0;
  std::uint16_t home_image = 0;
  Eigen::Vector2f home_pixel = Eigen::Vector2f::Zero();
  std::uint64_t first_sample = 0;
  std::uint16_t count = 0;
};

struct LumitexelSet {
  std::string mesh_sha256;          // of the mesh the points lie on (checked by readers)
  std::vector<std::string> images;  // the HDR images the samples came from, as in the rig
  std::vector<Lumitexel> lumitexels;
  std::vector<Sample> samples;
};

}  // namespace fest::brdffit

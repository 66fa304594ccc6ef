#pragma once
// The MERL isotropic BRDF table (Matusik, Pfister, Brand, McMillan 2003): 90 x 90 x 180
// cells over (theta_h, theta_d, phi_d) in the half/difference parameterisation of
// Rusinkiewicz, theta_h warped by a square root; three planes of doubles (R, G, B) with
// scales 1/1500, 1.15/1500, 1.66/1500; negative = not measured. The byte layout is read
// by formats/brdf; this is the index mathematics and the conversion to fit samples.

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "brdffit/fit_sample.hpp"
#include "reflectance/lafortune.hpp"

namespace fest::brdffit {

inline constexpr int kMerlThetaH = 90, kMerlThetaD = 90, kMerlPhiD = 180;
inline constexpr std::size_t kMerlCells = std::size_t{kMerlThetaH} * kMerlThetaD * kMerlPhiD;
inline constexpr double kMerlScale[3] = {1.0 / 1500, 1.15 / 1500, 1.66 / 1500};

struct MerlTable {
  std::vector<double> values;  // 3 x kMerlCells, raw (unscaled) as in the file
};

// Cell indices of the half/difference angles (MERL's own rounding: floor, clamped).
int merl_theta_h_index(double theta_h);
int merl_theta_d_index(double theta_d);
int merl_phi_d_index(double phi_d);  // phi_d in [0, pi) after reciprocity
std::size_t merl_cell(double theta_h, double theta_d, double phi_d);

// Half/difference angles of a pair of unit directions in the local frame.
void half_diff(const Eigen::Vector3d& u, const Eigen::Vector3d& v, double* theta_h, double* theta_d, double* phi_d);
// The light and view directions at the centre of a cell (phi_h = 0).
void merl_cell_directions(int ith, int itd, int ipd, Eigen::Vector3d* u, Eigen::Vector3d* v);

// BRDF value (scaled) for local directions; negative channels where not measured.
Eigen::Vector3d merl_lookup(const MerlTable& table, const Eigen::Vector3d& u, const Eigen::Vector3d& v);

// A table sampled from an analytic BRDF at the cell centres (tests, synthetic data).
MerlTable merl_from_brdf(const reflectance::LafortuneBrdf& brdf);

// Fit samples at every measured cell centre with both directions above 0.05 in z,
// r = f u_z. Throws bad_input when the table has the wrong size or no usable cell.
std::vector<FitSample> merl_samples(const MerlTable& table);

}  // namespace fest::brdffit

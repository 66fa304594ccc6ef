#pragma once
// The station's frames (docs/capture.md §1): at turntable angle theta the object frame
// T maps to the camera frame C by X_C = R_T0 Rz(theta) X_T + t_T0, and a light fixed in C
// at q sits at Rz(-theta) R_T0^T (q - t_T0) in T.

#include <cmath>

#include <Eigen/Core>

namespace fest::capture {

// Rz: rotation about the turntable axis (z) by `deg` degrees, counter-clockwise seen
// from above (positive angles).
inline Eigen::Matrix3d rotation_about_axis(double deg) {
  const double a = deg * M_PI / 180, c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d m;
  m << c, -s, 0, s, c, 0, 0, 0, 1;
  return m;
}

}  // namespace fest::capture

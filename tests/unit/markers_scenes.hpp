#pragma once
// Shared synthetic scenes for the markers tests: a 640 x 480 camera (f = 600 px) and
// random marker poses with the benchmark's degradations (lib/markers/synth.hpp).

#include <algorithm>
#include <cmath>

#include "core/rng.hpp"
#include "markers/synth.hpp"

namespace fest::test {

inline markers::CameraModel camera640(bool distorted = false) {
  markers::CameraModel c;
  c.K = cv::Matx33d(600, 0, 319.5, 0, 600, 239.5, 0, 0, 1);
  if (distorted) c.dist = cv::Vec<double, 5>(-0.12, 0.05, 0.0005, -0.0005, 0);
  c.width = 640;
  c.height = 480;
  return c;
}

struct Scene {
  markers::PlacedMarker marker;
  markers::Degradation degradation;
  double side_px = 0;  // the marker's side in pixels (mean of its four projected sides)
  int id = 0;
};

// Marker of `side` metres whose projected side is about `px` pixels, at a random place,
// viewed at min_tilt..max_tilt degrees off its normal, any roll.
inline Scene random_scene(const markers::CameraModel& cam, const markers::Dictionary& dict, double px,
                          double min_tilt, double max_tilt, Rng& rng, double side = 0.05) {
  Scene s;
  s.id = static_cast<int>(rng.uniform() * dict.codes.size());
  s.marker.art = markers::binary_art(dict, s.id);
  s.marker.side = side;
  const double distance = cam.K(0, 0) * side / px;
  const double margin = 0.9 * px + 10;
  s.marker.pose = markers::pose_facing(cam, rng.uniform(margin, cam.width - margin),
                                       rng.uniform(margin, cam.height - margin), distance, rng.uniform(min_tilt, max_tilt),
                                       rng.uniform(0, 360), rng.uniform(0, 360));
  const markers::Corners c = markers::project_corners(cam, s.marker.pose, side);
  for (int i = 0; i < 4; ++i) s.side_px += cv::norm(c[(i + 1) % 4] - c[i]) / 4;
  return s;
}

}  // namespace fest::test

#pragma once
// A key-framed motion path (docs/quatpath.md): positions by linear, Catmull-Rom or
// Kochanek-Bartels splines, orientations by slerp or squad with a per-segment choice of
// the short or the long way round (seed 004 §18, "individual path segment orientation
// reversal"), optional arc-length reparametrisation for constant speed, and sampling at
// a frame rate.

#include <string>
#include <vector>

#include "motionpath/quat.hpp"

namespace fest::motionpath {

enum class Way { shortest, longest };

struct Key {
  double t = 0;
  Vec3 p;
  Quat q;
  Way way = Way::shortest;  // how the segment from this key to the next turns
  double tension = 0, continuity = 0, bias = 0;  // Kochanek-Bartels parameters
};

enum class PositionMode { linear, catmull_rom, kb };
enum class OrientationMode { slerp, squad };

struct PathOptions {
  PositionMode position = PositionMode::catmull_rom;
  OrientationMode orientation = OrientationMode::slerp;
  bool constant_speed = false;  // arc-length reparametrisation
};

struct Pose {
  double t = 0;
  Vec3 p;
  Quat q;
};

class Path {
 public:
  // Validates the keys (>= 2, finite, strictly increasing times, non-zero quaternions,
  // no segment that turns exactly 360 degrees) and throws fest::Error(bad_input) naming
  // the key. Quaternions are normalised.
  Path(std::vector<Key> keys, PathOptions opt);

  double t_begin() const { return keys_.front().t; }
  double t_end() const { return keys_.back().t; }
  double length() const { return total_length_; }
  const std::vector<Key>& keys() const { return keys_; }
  const std::vector<Quat>& oriented() const { return q_; }  // keys' quaternions, signs chosen

  // The pose at time t (clamped to the key range). With constant_speed the position moves
  // at length / duration along the curve, and orientation follows the same curve parameter.
  Pose at(double t) const;
  // Position derivative d p / d u inside segment i (Hermite form).
  Vec3 velocity_param(std::size_t seg, double u) const;
  // Poses at t_begin + k / fps for k = 0, 1, ... while <= t_end (+ a last one at t_end when
  // the duration is not a whole number of frames and include_end is set).
  std::vector<Pose> sample(double fps, bool include_end) const;

  // Curve parameter (segment, u in [0,1]) at arc length s from the start.
  void locate_length(double s, std::size_t& seg, double& u) const;
  double length_to(std::size_t seg, double u) const;

 private:
  std::vector<Key> keys_;
  PathOptions opt_;
  std::vector<Quat> q_;         // sign-adjusted: q_[i+1] on the chosen side of q_[i]
  std::vector<Quat> s_;         // squad control points
  std::vector<Vec3> d_out_, d_in_;  // Hermite tangents per key (per unit of u)
  std::vector<double> seg_len_, cum_len_;  // arc length per segment and cumulative
  std::vector<double> sub_cum_;           // per segment: length at u = k/16, k = 0..16
  double total_length_ = 0;

  Vec3 position(std::size_t seg, double u) const;
  double gauss(std::size_t seg, double a, double b) const;  // 8-point Gauss-Legendre of |p'| on [a, b]
  Quat orientation(std::size_t seg, double u) const;
  void segment_of_time(double t, std::size_t& seg, double& u) const;
};

}  // namespace fest::motionpath

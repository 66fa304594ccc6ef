#include "motionpath/path.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace fest::motionpath {

namespace {

// 8-point Gauss-Legendre nodes and weights on [-1, 1].
constexpr double gl_x[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                            0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
constexpr double gl_w[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                            0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
constexpr int sub_intervals = 16;

bool finite(double v) { return std::isfinite(v); }

}  // namespace

Path::Path(std::vector<Key> keys, PathOptions opt) : keys_(std::move(keys)), opt_(opt) {
  const std::size_t n = keys_.size();
  if (n < 2) throw bad_input("a path needs at least two keys (got {})", n);
  for (std::size_t i = 0; i < n; ++i) {
    Key& k = keys_[i];
    if (!finite(k.t) || !finite(k.p.x) || !finite(k.p.y) || !finite(k.p.z) || !finite(k.q.w) || !finite(k.q.x) ||
        !finite(k.q.y) || !finite(k.q.z))
      throw bad_input("key {} has a value that is not a finite number", i + 1);
    if (i > 0 && !(k.t > keys_[i - 1].t))
      throw bad_input("key times must increase strictly (key {}: t = {} after {})", i + 1, k.t, keys_[i - 1].t);
    const double qn = norm(k.q);
    if (!(qn > 1e-9)) throw bad_input("key {} has a zero quaternion", i + 1);
    k.q = normalized(k.q);
    if (!finite(k.tension) || !finite(k.continuity) || !finite(k.bias))
      throw bad_input("key {} has a non-finite tension, continuity or bias", i + 1);
  }
  // Orientation: per segment, q or -q for the next key, so that the great arc from q_i
  // goes the short way (q_i . q_{i+1} >= 0) or the requested long way (< 0) -- the
  // seed's per-segment orientation reversal (§18).
  q_.resize(n);
  q_[0] = keys_[0].q;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    Quat next = keys_[i + 1].q;
    const double d = dot(q_[i], next);
    const bool want_long = keys_[i].way == Way::longest;
    if ((d < 0) != want_long) next = -next;
    if (dot(q_[i], next) < -1.0 + 1e-12)
      throw bad_input("keys {} and {}: the long way is a full 360-degree turn about no defined axis", i + 1, i + 2);
    q_[i + 1] = next;
  }
  s_.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    s_[i] = i == 0 || i + 1 == n ? q_[i] : squad_control(q_[i - 1], q_[i], q_[i + 1]);

  // Position tangents: Kochanek-Bartels (1984) eqs. 8-9 with the time-spacing correction
  // of eq. 11; Catmull-Rom is t = c = b = 0; the end keys use a reflected neighbour.
  d_out_.resize(n);
  d_in_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 p = keys_[i].p;
    const Vec3 prev = i > 0 ? keys_[i - 1].p : 2.0 * p - keys_[1].p;
    const Vec3 next = i + 1 < n ? keys_[i + 1].p : 2.0 * p - keys_[n - 2].p;
    double tn = 0, c = 0, b = 0;
    if (opt_.position == PositionMode::kb) {
      tn = keys_[i].tension;
      c = keys_[i].continuity;
      b = keys_[i].bias;
    }
    const Vec3 a = p - prev, e = next - p;
    Vec3 out = ((1 - tn) * (1 + b) * (1 - c) / 2) * a + ((1 - tn) * (1 - b) * (1 + c) / 2) * e;
    Vec3 in = ((1 - tn) * (1 + b) * (1 + c) / 2) * a + ((1 - tn) * (1 - b) * (1 - c) / 2) * e;
    if (i > 0 && i + 1 < n) {
      const double dt0 = keys_[i].t - keys_[i - 1].t, dt1 = keys_[i + 1].t - keys_[i].t;
      out = (2 * dt1 / (dt0 + dt1)) * out;
      in = (2 * dt0 / (dt0 + dt1)) * in;
    }
    d_out_[i] = out;
    d_in_[i] = in;
  }
  // Arc length per segment: composite 8-point Gauss-Legendre over 16 sub-intervals.
  seg_len_.resize(n - 1);
  cum_len_.assign(n, 0.0);
  sub_cum_.assign((n - 1) * (sub_intervals + 1), 0.0);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    double* cum = &sub_cum_[i * (sub_intervals + 1)];
    for (int k = 0; k < sub_intervals; ++k)
      cum[k + 1] = cum[k] + gauss(i, static_cast<double>(k) / sub_intervals, static_cast<double>(k + 1) / sub_intervals);
    seg_len_[i] = cum[sub_intervals];
    cum_len_[i + 1] = cum_len_[i] + seg_len_[i];
  }
  total_length_ = cum_len_.back();
  if (opt_.constant_speed && !(total_length_ > 0))
    throw bad_input("constant speed needs a path of non-zero length (all key positions are equal)");
}

Vec3 Path::position(std::size_t i, double u) const {
  const Vec3 p0 = keys_[i].p, p1 = keys_[i + 1].p;
  if (opt_.position == PositionMode::linear) return (1 - u) * p0 + u * p1;
  const double u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * d_out_[i] + (-2 * u3 + 3 * u2) * p1 + (u3 - u2) * d_in_[i + 1];
}

Vec3 Path::velocity_param(std::size_t i, double u) const {
  const Vec3 p0 = keys_[i].p, p1 = keys_[i + 1].p;
  if (opt_.position == PositionMode::linear) return p1 - p0;
  const double u2 = u * u;
  return (6 * u2 - 6 * u) * p0 + (3 * u2 - 4 * u + 1) * d_out_[i] + (-6 * u2 + 6 * u) * p1 + (3 * u2 - 2 * u) * d_in_[i + 1];
}

double Path::gauss(std::size_t seg, double a, double b) const {
  const double mid = (a + b) / 2, half = (b - a) / 2;
  double total = 0;
  for (int g = 0; g < 8; ++g) total += gl_w[g] * half * norm(velocity_param(seg, mid + gl_x[g] * half));
  return total;
}

double Path::length_to(std::size_t seg, double u) const {
  // Whole sub-intervals from the table, the last partial one by one more rule.
  u = std::clamp(u, 0.0, 1.0);
  const int k = std::min(sub_intervals - 1, static_cast<int>(u * sub_intervals));
  const double a = static_cast<double>(k) / sub_intervals;
  return sub_cum_[seg * (sub_intervals + 1) + static_cast<std::size_t>(k)] + gauss(seg, a, u);
}

void Path::locate_length(double s, std::size_t& seg, double& u) const {
  s = std::clamp(s, 0.0, total_length_);
  seg = static_cast<std::size_t>(std::upper_bound(cum_len_.begin(), cum_len_.end(), s) - cum_len_.begin());
  seg = seg == 0 ? 0 : seg - 1;
  if (seg + 1 >= keys_.size()) seg = keys_.size() - 2;
  const double target = s - cum_len_[seg];
  if (seg_len_[seg] <= 0) {
    u = 0;
    return;
  }
  // Newton on L(u) = target with a bisection bracket (L is monotone).
  double lo = 0, hi = 1;
  u = target / seg_len_[seg];
  for (int it = 0; it < 100; ++it) {
    const double f = length_to(seg, u) - target;
    if (std::fabs(f) <= 1e-13 * std::max(1.0, total_length_)) break;
    if (f > 0) hi = u;
    else lo = u;
    const double speed = norm(velocity_param(seg, u));
    double next = speed > 0 ? u - f / speed : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - u) < 1e-15) {
      u = next;
      break;
    }
    u = next;
  }
}

void Path::segment_of_time(double t, std::size_t& seg, double& u) const {
  t = std::clamp(t, t_begin(), t_end());
  auto it = std::upper_bound(keys_.begin(), keys_.end(), t, [](double v, const Key& k) { return v < k.t; });
  seg = static_cast<std::size_t>(it - keys_.begin());
  seg = seg == 0 ? 0 : seg - 1;
  if (seg + 1 >= keys_.size()) seg = keys_.size() - 2;
  u = (t - keys_[seg].t) / (keys_[seg + 1].t - keys_[seg].t);
}

Quat Path::orientation(std::size_t i, double u) const {
  if (opt_.orientation == OrientationMode::squad) return squad(q_[i], q_[i + 1], s_[i], s_[i + 1], u);
  return slerp(q_[i], q_[i + 1], u);
}

Pose Path::at(double t) const {
  std::size_t seg;
  double u;
  if (opt_.constant_speed) {
    const double f = (std::clamp(t, t_begin(), t_end()) - t_begin()) / (t_end() - t_begin());
    locate_length(f * total_length_, seg, u);
  } else {
    segment_of_time(t, seg, u);
  }
  return Pose{t, position(seg, u), orientation(seg, u)};
}

std::vector<Pose> Path::sample(double fps, bool include_end) const {
  if (!(fps > 0) || !std::isfinite(fps)) throw usage_error("frame rate must be a positive number (got {})", fps);
  const double duration = t_end() - t_begin();
  const double frames = duration * fps;
  if (frames > 1e8) throw usage_error("{} frames at {} fps is more than 10^8", frames, fps);
  // k / fps from the start, not repeated additions: no drift over long paths.
  const auto last = static_cast<long long>(std::floor(frames + 1e-9));
  std::vector<Pose> out;
  out.reserve(static_cast<std::size_t>(last) + 2);
  for (long long k = 0; k <= last; ++k) out.push_back(at(t_begin() + static_cast<double>(k) / fps));
  if (include_end && std::fabs(static_cast<double>(last) - frames) > 1e-9) out.push_back(at(t_end()));
  return out;
}

}  // namespace fest::motionpath

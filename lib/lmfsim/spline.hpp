#pragma once
// Natural cubic spline through (t_i, y_i) keys (C2), clamped to the end values outside the
// key range (docs/lmfsim.md §2 `path`, `motor` Omega(t), PID goals).

#include <vector>

namespace fest::lmfsim {

class Spline {
 public:
  Spline() = default;
  // Keys strictly increasing in t; throws bad_input otherwise.
  Spline(std::vector<double> t, std::vector<double> y);
  bool empty() const { return t_.empty(); }
  double value(double t) const;
  double derivative(double t) const;
  double second_derivative(double t) const;

 private:
  std::size_t segment(double t) const;
  std::vector<double> t_, y_, m_;  // m_: second derivatives at the keys
};

}  // namespace fest::lmfsim

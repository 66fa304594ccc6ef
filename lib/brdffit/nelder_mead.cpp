#include "brdffit/nelder_mead.hpp"

#include <algorithm>
#include <numeric>

namespace fest::brdffit {

SimplexResult nelder_mead(const std::function<double(const Eigen::VectorXd&)>& f, const Eigen::VectorXd& x0,
                          const Eigen::VectorXd& step, int max_iters, double f_tol, double x_tol) {
  const Eigen::Index n = x0.size();
  std::vector<Eigen::VectorXd> p(static_cast<std::size_t>(n + 1), x0);
  std::vector<double> v(static_cast<std::size_t>(n + 1));
  for (Eigen::Index i = 0; i < n; ++i) p[static_cast<std::size_t>(i + 1)][i] += step[i];
  for (std::size_t i = 0; i < p.size(); ++i) v[i] = f(p[i]);
  std::vector<std::size_t> order(p.size());
  int it = 0;
  for (; it < max_iters; ++it) {
    std::iota(order.begin(), order.end(), 0);
    // Stable order on ties keeps runs reproducible.
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
    const std::size_t best = order.front(), worst = order.back(), second = order[order.size() - 2];
    double size = 0;
    for (std::size_t i = 0; i < p.size(); ++i) size = std::max(size, (p[i] - p[best]).cwiseAbs().maxCoeff());
    if (v[worst] - v[best] <= f_tol && size <= x_tol) break;
    if (size <= x_tol) break;
    Eigen::VectorXd centroid = Eigen::VectorXd::Zero(n);
    for (std::size_t i = 0; i < p.size(); ++i)
      if (i != worst) centroid += p[i];
    centroid /= static_cast<double>(n);
    const Eigen::VectorXd xr = centroid + (centroid - p[worst]);
    const double fr = f(xr);
    if (fr < v[best]) {
      const Eigen::VectorXd xe = centroid + 2 * (centroid - p[worst]);
      const double fe = f(xe);
      if (fe < fr) {
        p[worst] = xe;
        v[worst] = fe;
      } else {
        p[worst] = xr;
        v[worst] = fr;
      }
    } else if (fr < v[second]) {
      p[worst] = xr;
      v[worst] = fr;
    } else {
      const bool outside = fr < v[worst];
      const Eigen::VectorXd xc = outside ? Eigen::VectorXd(centroid + 0.5 * (xr - centroid))
                                         : Eigen::VectorXd(centroid + 0.5 * (p[worst] - centroid));
      const double fc = f(xc);
      if (fc < std::min(fr, v[worst])) {
        p[worst] = xc;
        v[worst] = fc;
      } else {
        for (std::size_t i = 0; i < p.size(); ++i) {
          if (i == best) continue;
          p[i] = p[best] + 0.5 * (p[i] - p[best]);
          v[i] = f(p[i]);
        }
      }
    }
  }
  std::size_t best = 0;
  for (std::size_t i = 1; i < p.size(); ++i)
    if (v[i] < v[best]) best = i;
  return {p[best], v[best], it};
}

}  // namespace fest::brdffit

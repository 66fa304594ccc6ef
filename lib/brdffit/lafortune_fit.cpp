#include "brdffit/lafortune_fit.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "brdffit/parallel_chunks.hpp"
#include "core/error.hpp"

namespace fest::brdffit {

namespace {

constexpr std::size_t kChunk = 8192;

struct Normal {
  Eigen::MatrixXd jtj;
  Eigen::VectorXd jtr;
  double energy = 0;
};

// E, J^T J and J^T e at p (e = r - f u_z, J = de/dp). Chunks are summed in order so the
// result does not depend on the thread count.
Normal normal_equations(const ModelSpec& spec, const Eigen::VectorXd& p, const std::vector<FitSample>& s,
                        double huber, int threads) {
  const int np = static_cast<int>(p.size());
  const std::size_t chunks = chunk_count(s.size(), kChunk);
  std::vector<Normal> parts(chunks);
  const ModelEvaluator model(spec, p);
  for_each_chunk(s.size(), kChunk, threads, [&](std::size_t ci, std::size_t b, std::size_t e) {
    Normal& out = parts[ci];
    out.jtj = Eigen::MatrixXd::Zero(np, np);
    out.jtr = Eigen::VectorXd::Zero(np);
    int idx[kMaxChannelParams];
    double grad[kMaxChannelParams];
    int ng = 0;
    for (std::size_t i = b; i < e; ++i) {
      const FitSample& q = s[i];
      for (int c = 0; c < 3; ++c) {
        const double f = model.value(c, q.xy, q.z, idx, grad, &ng);
        const double res = q.r[c] - f * q.uz;
        double w = q.w;
        if (huber > 0 && std::abs(res) > huber) {
          out.energy += w * (2 * huber * std::abs(res) - huber * huber);
          w *= huber / std::abs(res);  // IRLS weight of Huber's loss
        } else {
          out.energy += w * res * res;
        }
        for (int a = 0; a < ng; ++a) {
          const double ja = -q.uz * grad[a];
          out.jtr[idx[a]] += w * ja * res;
          for (int bb = 0; bb <= a; ++bb) out.jtj(idx[a], idx[bb]) += w * ja * (-q.uz * grad[bb]);
        }
      }
    }
  });
  Normal total;
  total.jtj = Eigen::MatrixXd::Zero(np, np);
  total.jtr = Eigen::VectorXd::Zero(np);
  for (const Normal& part : parts) {
    total.jtj += part.jtj;
    total.jtr += part.jtr;
    total.energy += part.energy;
  }
  // Only the lower triangle was accumulated (parameter indices grow along a channel).
  for (int a = 0; a < np; ++a)
    for (int b = a + 1; b < np; ++b) {
      const double v = total.jtj(a, b) + total.jtj(b, a);
      total.jtj(a, b) = total.jtj(b, a) = v;
    }
  return total;
}

void check_samples(const std::vector<FitSample>& s) {
  if (s.empty()) throw bad_input("no samples to fit a BRDF to");
  for (std::size_t i = 0; i < s.size(); ++i) {
    const FitSample& q = s[i];
    if (!std::isfinite(q.xy) || !std::isfinite(q.z) || !std::isfinite(q.uz) || !std::isfinite(q.r[0]) ||
        !std::isfinite(q.r[1]) || !std::isfinite(q.r[2]) || !std::isfinite(q.w) || q.w < 0)
      throw bad_input("sample {} has a non-finite direction, radiance or weight", i);
  }
}

// `iteration` (may be empty) hears every LM iteration's number.
FitResult levenberg_marquardt(const std::vector<FitSample>& s, Eigen::VectorXd p, const FitOptions& o,
                              const std::function<void(int)>& iteration = {}) {
  const ModelSpec& spec = o.model;
  clamp_to_bounds(spec, p);
  Normal cur = normal_equations(spec, p, s, o.huber_delta, o.threads);
  FitResult r;
  if (!std::isfinite(cur.energy)) {
    r.params = p;
    r.energy = std::numeric_limits<double>::infinity();
    return r;
  }
  double mu = 1e-3 * std::max(cur.jtj.diagonal().maxCoeff(), 1e-12);
  const Eigen::Index np = p.size();
  int it = 0;
  for (; it < o.max_iterations && cur.energy > 0; ++it) {
    if (iteration) iteration(it);
    const Eigen::MatrixXd a = cur.jtj + mu * Eigen::MatrixXd::Identity(np, np);
    Eigen::VectorXd step = a.ldlt().solve(-cur.jtr);
    if (!step.allFinite()) break;
    Eigen::VectorXd trial = p + step;
    clamp_to_bounds(spec, trial);
    Normal next = normal_equations(spec, trial, s, o.huber_delta, o.threads);
    if (std::isfinite(next.energy) && next.energy < cur.energy) {
      const double decrease = (cur.energy - next.energy) / cur.energy;
      p = trial;
      cur = std::move(next);
      mu = std::max(mu / 10, 1e-300);
      if (decrease < o.tolerance) {
        ++it;
        break;
      }
    } else {
      mu *= 10;
      if (mu > 1e16 * std::max(cur.jtj.diagonal().maxCoeff(), 1e-12)) break;  // no descent left
    }
  }
  r.params = p;
  r.energy = cur.energy;
  r.iterations = it;
  const double m = 3.0 * static_cast<double>(s.size());
  r.sigma2 = m > static_cast<double>(np) ? cur.energy / (m - static_cast<double>(np)) : 0;
  // Pseudo-inverse: parameters the data do not constrain (a lobe that is zero on every
  // sample) get zero variance instead of an infinite one.
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(cur.jtj);
  const Eigen::VectorXd& ev = eig.eigenvalues();
  const double cut = 1e-12 * std::max(ev.cwiseAbs().maxCoeff(), 1e-300);
  Eigen::VectorXd inv(np);
  for (Eigen::Index i = 0; i < np; ++i) inv[i] = ev[i] > cut ? 1 / ev[i] : 0;
  r.covariance = r.sigma2 * eig.eigenvectors() * inv.asDiagonal() * eig.eigenvectors().transpose();
  return r;
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

// Per channel: the 95th percentile of what the model p leaves unexplained, in BRDF units.
Eigen::Vector3d residual_peak(const ModelSpec& spec, const Eigen::VectorXd& p, const std::vector<FitSample>& s) {
  Eigen::Vector3d peak;
  for (int c = 0; c < 3; ++c) {
    std::vector<double> v;
    v.reserve(s.size());
    for (const FitSample& q : s)
      if (q.uz > 0.05f) v.push_back(q.r[c] / q.uz - channel_value(spec, p, c, q.xy, q.z));
    peak[c] = std::max(percentile(std::move(v), 0.95), 1e-4);
  }
  return peak;
}

// Sets lobe k of p to the shape (sxy, sz) scaled so that its peak is about `peak`.
void seed_lobe(const ModelSpec& spec, Eigen::VectorXd& p, int k, double n, double sxy, double sz,
               const Eigen::Vector3d& peak) {
  if (!spec.shared) {
    const int m = 1 + 3 * spec.lobes;
    for (int c = 0; c < 3; ++c) {
      // docs/brdffit.md §3: C_z = -C_xy = (s (N + 2) / (2 pi))^(1/N).
      const double scale = std::pow(peak[c] * (n + 2) / (2 * M_PI), 1 / n);
      p[c * m + 1 + 3 * k] = sxy * scale;
      p[c * m + 2 + 3 * k] = sz * scale;
      p[c * m + 3 + 3 * k] = std::log(n);
    }
  } else {
    const int o = 3 + 5 * k;
    for (int c = 0; c < 3; ++c) p[o + c] = peak[c] * (n + 2) / (2 * M_PI);
    p[o + 3] = sxy / std::abs(sz);
    p[o + 4] = std::log(n);
  }
}

// Replaces the diffuse albedo and the scale of lobe k (its shape and N kept) by their
// least-squares values: with the shape fixed, rho_d / pi u_z and A max(0, base)^N u_z are
// linear in (rho_d, A), so each start begins at the best amplitude for its N instead of
// the percentile guess of docs/brdffit.md §3 (which, for a broad dim lobe, can be off by a factor of
// ten and send LM into a retro-reflective local minimum). Channels whose solution is not
// positive keep the guess.
void fit_lobe_amplitude(const ModelSpec& spec, Eigen::VectorXd& p, int k, const std::vector<FitSample>& s) {
  const int m = 1 + 3 * spec.lobes;
  Eigen::VectorXd rest = p;  // every other lobe, without the diffuse part and lobe k
  for (int c = 0; c < 3; ++c) rest[spec.shared ? c : c * m] = 0;
  double n = 0, sxy = 0, sz = 1;
  if (spec.shared) {
    const int o = 3 + 5 * k;
    for (int c = 0; c < 3; ++c) rest[o + c] = 0;
    sxy = p[o + 3];
    n = std::exp(p[o + 4]);
  } else {
    for (int c = 0; c < 3; ++c) rest[c * m + 1 + 3 * k] = rest[c * m + 2 + 3 * k] = 0;
    n = std::exp(p[3 + 3 * k]);
  }
  for (int c = 0; c < 3; ++c) {
    if (!spec.shared) {  // the unit shape of this channel's lobe
      const double cxy = p[c * m + 1 + 3 * k], cz = p[c * m + 2 + 3 * k];
      const double scale = std::max(std::abs(cxy), std::abs(cz));
      if (!(scale > 0)) continue;
      sxy = cxy / scale;
      sz = cz / scale;
    }
    Eigen::Matrix2d a = Eigen::Matrix2d::Zero();
    Eigen::Vector2d b = Eigen::Vector2d::Zero();
    for (const FitSample& q : s) {
      const double base = sxy * q.xy + sz * q.z;
      const Eigen::Vector2d g(q.uz / M_PI, base > 0 ? q.uz * std::pow(base, n) : 0.0);
      const double y = q.r[c] - q.uz * channel_value(spec, rest, c, q.xy, q.z);
      a += q.w * g * g.transpose();
      b += q.w * y * g;
    }
    const Eigen::Vector2d x = a.ldlt().solve(b);
    if (!x.allFinite() || !(x[0] >= 0) || !(x[1] > 0)) continue;
    if (spec.shared) {
      p[c] = x[0];
      p[3 + 5 * k + c] = x[1];
    } else {
      p[c * m] = x[0];
      const double scale = std::pow(x[1], 1 / n);
      p[c * m + 1 + 3 * k] = sxy * scale;
      p[c * m + 2 + 3 * k] = sz * scale;
    }
  }
}

const double kStartExponents[] = {5, 20, 80, 300};

}  // namespace

std::vector<std::size_t> subsample_indices(std::size_t n, std::size_t count, std::uint64_t seed) {
  std::vector<std::size_t> idx(n);
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  if (count == 0 || count >= n) return idx;
  // Partial Fisher-Yates with splitmix64: portable, unlike std's distributions.
  std::uint64_t state = seed;
  auto next = [&state] {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  };
  for (std::size_t i = 0; i < count; ++i) std::swap(idx[i], idx[i + next() % (n - i)]);
  idx.resize(count);
  std::sort(idx.begin(), idx.end());
  return idx;
}

double albedo_bound_in_data_units(double max_lobe_albedo, const std::vector<FitSample>& samples) {
  if (!(max_lobe_albedo > 0)) return max_lobe_albedo;
  std::vector<double> apparent;
  const std::size_t stride = std::max<std::size_t>(1, samples.size() / 100000);
  for (std::size_t i = 0; i < samples.size(); i += stride) {
    const FitSample& q = samples[i];
    if (q.uz > 0.05f) apparent.push_back(M_PI * (q.r[0] + q.r[1] + q.r[2]) / (3 * q.uz));
  }
  return max_lobe_albedo * std::max(1.0, percentile(std::move(apparent), 0.5));
}

double mean_squared_residual(const ModelSpec& spec, const Eigen::VectorXd& p, const FitSample* b, const FitSample* e) {
  return mean_squared_residual(ModelEvaluator(spec, p), b, e);
}

double mean_squared_residual(const ModelEvaluator& f, const FitSample* b, const FitSample* e) {
  double sum = 0, weight = 0;
  for (const FitSample* q = b; q != e; ++q) {
    double r2 = 0;
    for (int c = 0; c < 3; ++c) {
      const double res = q->r[c] - f.value(c, q->xy, q->z) * q->uz;
      r2 += res * res;
    }
    sum += q->w * r2;
    weight += q->w;
  }
  return weight > 0 ? sum / (3 * weight) : 0;
}

namespace {

FitResult finish(const std::vector<FitSample>& all, const std::vector<FitSample>& used, FitResult r,
                 const FitOptions& o) {
  if (!r.params.allFinite() || !std::isfinite(r.energy) || !r.covariance.allFinite())
    throw runtime_failure("the BRDF fit produced NaN or infinity");
  r.brdf = to_brdf(o.model, r.params);
  r.samples_used = used.size();
  r.mean_squared = mean_squared_residual(o.model, r.params, all.data(), all.data() + all.size());
  return r;
}

const std::vector<FitSample>& fit_set(const std::vector<FitSample>& s, const FitOptions& o,
                                      std::vector<FitSample>& storage) {
  if (o.subsample == 0 || s.size() <= o.subsample) return s;
  storage.clear();
  for (std::size_t i : subsample_indices(s.size(), o.subsample, o.seed)) storage.push_back(s[i]);
  return storage;
}

}  // namespace

FitResult refine_brdf(const std::vector<FitSample>& samples, const Eigen::VectorXd& start, const FitOptions& o) {
  check_samples(samples);
  if (start.size() != parameter_count(o.model)) throw usage_error("start vector has the wrong size");
  std::vector<FitSample> storage;
  const std::vector<FitSample>& used = fit_set(samples, o, storage);
  return finish(samples, used, levenberg_marquardt(used, start, o), o);
}

FitResult fit_brdf(const std::vector<FitSample>& samples, const FitOptions& o) {
  check_samples(samples);
  const int np = parameter_count(o.model);
  if (o.starts < 1 || o.starts > 4) throw usage_error("multi-start count {} is outside 1..4", o.starts);
  std::vector<FitSample> storage;
  const std::vector<FitSample>& s = fit_set(samples, o, storage);

  // Diffuse part: the 25th percentile of pi r / u_z per channel (docs/brdffit.md §3).
  Eigen::VectorXd base = Eigen::VectorXd::Zero(np);
  for (int c = 0; c < 3; ++c) {
    std::vector<double> v;
    for (const FitSample& q : s)
      if (q.uz > 0.05f) v.push_back(M_PI * q.r[c] / q.uz);
    const double rho = std::max(0.0, percentile(std::move(v), 0.25));
    if (o.model.shared) base[c] = rho;
    else base[c * (1 + 3 * o.model.lobes)] = rho;
  }
  // Lobes not yet seeded are inert: C = 0 makes the base 0 and the lobe and its
  // derivatives vanish, so the LM leaves them where they are.
  FitResult best;
  best.energy = std::numeric_limits<double>::infinity();
  Eigen::VectorXd current = base;
  // Progress: max_iterations steps per start, one start per (exponent, shape) and lobe.
  const auto per_run = static_cast<std::uint64_t>(std::max(1, o.max_iterations));
  const std::uint64_t runs = static_cast<std::uint64_t>(o.starts) * static_cast<std::uint64_t>(2 * o.model.lobes - 1);
  std::uint64_t run = 0;
  std::function<void(int)> iteration;
  if (o.progress)
    iteration = [&](int it) { o.progress(run * per_run + static_cast<std::uint64_t>(it), runs * per_run); };
  for (int k = 0; k < o.model.lobes; ++k) {
    const Eigen::Vector3d peak = residual_peak(o.model, current, s);
    // A mirror lobe first; later lobes may also be the grazing (C_z < 0) kind, as in the
    // first lobe of the measured clay.
    std::vector<std::pair<double, double>> shapes = {{-1, 1}};
    if (k > 0) shapes.push_back(o.model.shared ? std::pair<double, double>{-1.5, 1} : std::pair<double, double>{-1, -1});
    FitResult stage;
    stage.energy = std::numeric_limits<double>::infinity();
    for (int st = 0; st < o.starts; ++st)
      for (const auto& [sxy, sz] : shapes) {
        Eigen::VectorXd p = current;
        seed_lobe(o.model, p, k, kStartExponents[st], sxy, sz, peak);
        fit_lobe_amplitude(o.model, p, k, s);
        FitResult r = levenberg_marquardt(s, p, o, iteration);
        ++run;
        if (o.progress) o.progress(run * per_run, runs * per_run);
        if (r.energy < stage.energy) stage = std::move(r);
      }
    if (!std::isfinite(stage.energy)) throw runtime_failure("the BRDF fit produced NaN or infinity");
    current = stage.params;
    best = std::move(stage);
  }
  return finish(samples, s, std::move(best), o);
}

}  // namespace fest::brdffit

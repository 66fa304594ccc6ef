#include "brdffit/cluster.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <Eigen/Eigenvalues>

#include "brdffit/parallel_chunks.hpp"
#include "core/error.hpp"

namespace fest::brdffit {

namespace {

using Members = std::vector<std::size_t>;
constexpr std::size_t kChunk = 1024;

const FitSample* first_of(const LumitexelSet& set, const std::vector<FitSample>& local, std::size_t i) {
  return local.data() + set.lumitexels[i].first_sample;
}

// The samples of the members, or a deterministic subsample of at most `limit` of them.
std::vector<FitSample> gather(const LumitexelSet& set, const std::vector<FitSample>& local, const Members& members,
                              std::size_t limit, std::uint64_t seed) {
  std::size_t total = 0;
  for (std::size_t i : members) total += set.lumitexels[i].count;
  std::vector<FitSample> out;
  if (limit == 0 || total <= limit) {
    out.reserve(total);
    for (std::size_t i : members) {
      const FitSample* s = first_of(set, local, i);
      out.insert(out.end(), s, s + set.lumitexels[i].count);
    }
    return out;
  }
  const std::vector<std::size_t> pick = subsample_indices(total, limit, seed);
  out.reserve(limit);
  std::size_t m = 0, offset = 0;  // walk members and the sorted picks together
  for (std::size_t k : pick) {
    while (k >= offset + set.lumitexels[members[m]].count) offset += set.lumitexels[members[m++]].count;
    out.push_back(first_of(set, local, members[m])[k - offset]);
  }
  return out;
}

std::vector<double> distances(const LumitexelSet& set, const std::vector<FitSample>& local, const Members& members,
                              const ModelSpec& model, const Eigen::VectorXd& p, int threads) {
  std::vector<double> d(members.size());
  const ModelEvaluator f(model, p);
  for_each_chunk(members.size(), kChunk, threads, [&](std::size_t, std::size_t b, std::size_t e) {
    for (std::size_t k = b; k < e; ++k) {
      const FitSample* s = first_of(set, local, members[k]);
      d[k] = mean_squared_residual(f, s, s + set.lumitexels[members[k]].count);
    }
  });
  return d;
}

struct Clusterer {
  const LumitexelSet& set;
  const std::vector<FitSample>& local;
  const ClusterOptions& o;
  Members active;  // lumitexels with samples

  FitResult fit_new(const Members& m, int id, std::size_t limit = 0) const {
    FitOptions fo = o.fit;
    fo.subsample = 0;
    if (limit == 0 || (o.fit.subsample != 0 && o.fit.subsample < limit)) limit = o.fit.subsample;
    try {
      return fit_brdf(gather(set, local, m, limit, o.fit.seed), fo);
    } catch (const Error& e) {
      if (e.status() == Status::failure) throw runtime_failure("the BRDF fit of cluster {} produced NaN", id);
      throw;
    }
  }
  FitResult refit(const Members& m, const Eigen::VectorXd& start, int id, std::size_t limit = 0) const {
    FitOptions fo = o.fit;
    fo.subsample = 0;
    fo.max_iterations = o.refit_iterations;
    fo.tolerance = o.refit_tolerance;
    if (limit == 0 || (o.fit.subsample != 0 && o.fit.subsample < limit)) limit = o.fit.subsample;
    try {
      return refine_brdf(gather(set, local, m, limit, o.fit.seed), start, fo);
    } catch (const Error& e) {
      if (e.status() == Status::failure) throw runtime_failure("the BRDF fit of cluster {} produced NaN", id);
      throw;
    }
  }
  // The better (in E on the same subsample) of the warm-started refit and a fresh fit
  // from docs/brdffit.md §3's initialisation: a warm start inherits the search's lobe, which may be
  // the compromise of a mixture or, projected onto the albedo bound, a narrow spike;
  // the fresh multi-start fit finds the broad lobe of a broad material (N = 5 of 5).
  FitResult refit_or_restart(const Members& m, const Eigen::VectorXd& start, int id) const {
    FitResult warm = refit(m, start, id);
    // The multi-start runs on the split's small subsample, its winner is refined on the
    // full one (where its E compares with the warm refit's): a quarter of the cost.
    FitResult fresh = refit(m, fit_new(m, id, o.split_subsample).params, id);
    return fresh.energy < warm.energy ? fresh : warm;
  }
  void set_fit(MaterialCluster& c, const FitResult& r) const {
    c.params = r.params;
    c.covariance = r.covariance;
  }
  // Members, sample count and error of every cluster from the assignment and each
  // lumitexel's distance to its own cluster.
  void tally(std::vector<MaterialCluster>& cs, const std::vector<std::uint16_t>& a, const std::vector<double>& own) const {
    for (MaterialCluster& c : cs) c.members = c.samples = 0, c.error = 0;
    for (std::size_t k = 0; k < active.size(); ++k) {
      MaterialCluster& c = cs[a[active[k]]];
      const double n = set.lumitexels[active[k]].count;
      ++c.members;
      c.samples += set.lumitexels[active[k]].count;
      c.error += n * own[k];
    }
  }
  std::vector<Members> member_lists(std::size_t count, const std::vector<std::uint16_t>& a) const {
    std::vector<Members> m(count);
    for (std::size_t i : active) m[a[i]].push_back(i);
    return m;
  }
  // D of every active lumitexel to its own cluster.
  std::vector<double> own_distances(const std::vector<MaterialCluster>& cs, const std::vector<std::uint16_t>& a) const {
    std::vector<double> own(active.size());
    std::vector<ModelEvaluator> fs;
    for (const MaterialCluster& c : cs) fs.emplace_back(o.fit.model, c.params);
    for_each_chunk(active.size(), kChunk, o.fit.threads, [&](std::size_t, std::size_t b, std::size_t e) {
      for (std::size_t k = b; k < e; ++k) {
        const FitSample* s = first_of(set, local, active[k]);
        own[k] = mean_squared_residual(fs[a[active[k]]], s, s + set.lumitexels[active[k]].count);
      }
    });
    return own;
  }
  // D of every active lumitexel to every cluster (row = lumitexel).
  Eigen::MatrixXd distance_matrix(const std::vector<MaterialCluster>& cs) const {
    Eigen::MatrixXd d(static_cast<Eigen::Index>(active.size()), static_cast<Eigen::Index>(cs.size()));
    for (std::size_t j = 0; j < cs.size(); ++j) {
      const std::vector<double> col = distances(set, local, active, o.fit.model, cs[j].params, o.fit.threads);
      for (std::size_t k = 0; k < col.size(); ++k) d(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(j)) = col[k];
    }
    return d;
  }
  // Every lumitexel to its nearest cluster; refit the clusters whose members changed.
  // Returns each active lumitexel's distance to its own cluster.
  std::vector<double> reassign(std::vector<MaterialCluster>& cs, std::vector<std::uint16_t>& a, int rounds) const {
    std::vector<double> own(active.size());
    for (int round = 0; round < std::max(1, rounds); ++round) {
      const Eigen::MatrixXd d = distance_matrix(cs);
      std::vector<bool> changed(cs.size() + 1, false);  // + the orphans of remove_small
      bool any = false;
      for (std::size_t k = 0; k < active.size(); ++k) {
        Eigen::Index best = 0;
        own[k] = d.row(static_cast<Eigen::Index>(k)).minCoeff(&best);
        const auto nb = static_cast<std::uint16_t>(best);
        if (a[active[k]] != nb) {
          changed[a[active[k]]] = changed[nb] = true;
          a[active[k]] = nb;
          any = true;
        }
      }
      if (!any || rounds == 0) break;
      const std::vector<Members> m = member_lists(cs.size(), a);
      for (std::size_t j = 0; j < cs.size(); ++j)
        if (changed[j] && !m[j].empty()) set_fit(cs[j], refit(m[j], cs[j].params, static_cast<int>(j)));
      if (round + 1 == rounds) {  // distances for the refitted clusters
        const Eigen::MatrixXd d2 = distance_matrix(cs);
        for (std::size_t k = 0; k < active.size(); ++k) own[k] = d2(static_cast<Eigen::Index>(k), a[active[k]]);
      }
    }
    return own;
  }
  // Dissolves clusters below the size limit; their members go to the nearest others.
  bool remove_small(std::vector<MaterialCluster>& cs, std::vector<std::uint16_t>& a) const {
    const double limit = o.min_cluster * static_cast<double>(active.size());
    std::vector<int> remap(cs.size(), -1);
    std::vector<MaterialCluster> kept;
    for (std::size_t j = 0; j < cs.size(); ++j)
      if (cs[j].members > 0 && static_cast<double>(cs[j].members) >= limit) {
        remap[j] = static_cast<int>(kept.size());
        kept.push_back(cs[j]);
      }
    if (kept.size() == cs.size() || kept.empty()) return false;
    const auto orphan = static_cast<std::uint16_t>(kept.size());
    for (std::size_t i : active) a[i] = remap[a[i]] >= 0 ? static_cast<std::uint16_t>(remap[a[i]]) : orphan;
    cs = std::move(kept);
    return true;
  }
};

}  // namespace

double lumitexel_distance(const LumitexelSet& set, const std::vector<FitSample>& local, std::size_t i,
                          const ModelSpec& model, const Eigen::VectorXd& p) {
  const FitSample* s = first_of(set, local, i);
  return mean_squared_residual(model, p, s, s + set.lumitexels[i].count);
}

std::vector<std::uint16_t> nearest_clusters(const LumitexelSet& set, const std::vector<FitSample>& local,
                                            const ModelSpec& model, const std::vector<Eigen::VectorXd>& params,
                                            int threads, const ProgressFn& progress) {
  std::vector<std::uint16_t> a(set.lumitexels.size(), 0);
  std::vector<ModelEvaluator> fs;
  for (const Eigen::VectorXd& p : params) fs.emplace_back(model, p);
  ProgressCounter chunks(progress, chunk_count(a.size(), kChunk));
  for_each_chunk(a.size(), kChunk, threads, [&](std::size_t, std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      double best = std::numeric_limits<double>::infinity();
      const FitSample* s = first_of(set, local, i);
      for (std::size_t j = 0; j < params.size(); ++j) {
        const double d = mean_squared_residual(fs[j], s, s + set.lumitexels[i].count);
        if (d < best) best = d, a[i] = static_cast<std::uint16_t>(j);
      }
    }
    chunks.step();
  });
  chunks.finish();
  return a;
}

namespace {

// docs/brdffit.md §5's inner loop. Returns the two children (+, -) and the members of each, or nothing.
struct SplitOutcome {
  FitResult plus, minus;
  Members plus_members, minus_members;
  int iterations = 0;
};

bool split_cluster(const Clusterer& cl, const Members& members, const MaterialCluster& c, int id, SplitOutcome& out) {
  const ClusterOptions& o = cl.o;
  if (members.size() < 2) return false;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(c.covariance);
  const Eigen::Index top = c.covariance.rows() - 1;  // eigenvalues ascend
  const double sigma = std::sqrt(std::max(0.0, eig.eigenvalues()[top]));
  const Eigen::VectorXd e = eig.eigenvectors().col(top);
  Eigen::VectorXd pp = c.params + o.split_scale * sigma * e, pm = c.params - o.split_scale * sigma * e;
  clamp_to_bounds(o.fit.model, pp);
  clamp_to_bounds(o.fit.model, pm);
  std::vector<bool> side(members.size(), false), last(members.size(), false);  // true = plus
  for (int it = 0; it < std::max(1, o.split_iters); ++it) {
    const std::vector<double> dp = distances(cl.set, cl.local, members, o.fit.model, pp, o.fit.threads);
    const std::vector<double> dm = distances(cl.set, cl.local, members, o.fit.model, pm, o.fit.threads);
    std::size_t plus = 0, changed = 0;
    for (std::size_t k = 0; k < members.size(); ++k) {
      side[k] = dp[k] < dm[k];
      plus += side[k];
    }
    if (plus == 0 || plus == members.size()) {
      // The two BRDFs do not divide the cluster (sigma too small to matter): split at the
      // median of the distance difference instead, so that both halves can be refitted.
      std::vector<double> diff(members.size());
      for (std::size_t k = 0; k < members.size(); ++k) diff[k] = dp[k] - dm[k];
      std::vector<double> sorted = diff;
      std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
      const double median = sorted[sorted.size() / 2];
      plus = 0;
      for (std::size_t k = 0; k < members.size(); ++k) plus += side[k] = diff[k] < median;
      if (plus == 0 || plus == members.size()) return false;
    }
    for (std::size_t k = 0; k < members.size(); ++k) changed += it > 0 && side[k] != last[k];
    last = side;
    out.plus_members.clear();
    out.minus_members.clear();
    for (std::size_t k = 0; k < members.size(); ++k) (side[k] ? out.plus_members : out.minus_members).push_back(members[k]);
    // Inside the loop the two BRDFs only have to divide the members: small subsets.
    pp = cl.refit(out.plus_members, pp, id, o.split_subsample).params;
    pm = cl.refit(out.minus_members, pm, id, o.split_subsample).params;
    out.iterations = it + 1;
    if (it > 0 && static_cast<double>(changed) < o.stable * static_cast<double>(members.size())) break;
  }
  out.plus = cl.refit(out.plus_members, pp, id);
  out.minus = cl.refit(out.minus_members, pm, id);
  return true;
}

void check_options(const ClusterOptions& o) {
  if (o.clusters < 0 || o.clusters > 65535)
    throw usage_error("cluster count {} is outside 1..65535 (0 = split until the gain is small)", o.clusters);
  if (!(o.split_scale > 0)) throw usage_error("the split step kappa must be positive, not {}", o.split_scale);
  if (o.split_iters < 1) throw usage_error("refits per split must be at least 1, not {}", o.split_iters);
  if (o.global_iters < 0) throw usage_error("global reassignment rounds must be >= 0, not {}", o.global_iters);
  if (!(o.stable >= 0 && o.stable < 1))
    throw usage_error("the stable fraction of changed members must lie in [0, 1), not {}", o.stable);
  if (!(o.min_cluster >= 0 && o.min_cluster < 1))
    throw usage_error("the smallest cluster fraction must lie in [0, 1), not {}", o.min_cluster);
  if (!(o.min_gain >= 0)) throw usage_error("the smallest split gain must be >= 0, not {}", o.min_gain);
}

}  // namespace

std::vector<Eigen::VectorXd> trial_split(const LumitexelSet& set, const std::vector<FitSample>& local,
                                         const Members& members, const MaterialCluster& cluster,
                                         const ClusterOptions& options) {
  Clusterer cl{set, local, options, {}};
  SplitOutcome out;
  if (!split_cluster(cl, members, cluster, -1, out)) return {};
  return {out.plus.params, out.minus.params};
}

ClusterResult cluster_lumitexels(const LumitexelSet& set, const std::vector<FitSample>& local,
                                 const ClusterOptions& options) {
  check_options(options);
  if (local.size() != set.samples.size()) throw usage_error("local samples do not match the lumitexel set");
  // The split-and-refit search runs without the lobes' albedo bound; the bound applies
  // to the clusters' final BRDFs (below). The search only has to divide the lumitexels,
  // and D sees a BRDF only at the sampled directions, where an unbounded lobe is as good
  // as a plausible one; bounded warm-started refits, in contrast, were seen to settle in
  // mixtures (the broad and the sharp material of the e2e test 90 % apart, not 98 %).
  ClusterOptions bounded_options = options;
  bounded_options.fit.model.max_lobe_albedo = albedo_bound_in_data_units(options.fit.model.max_lobe_albedo, local);
  ClusterOptions o = options;
  o.fit.model.max_lobe_albedo = 0;
  Clusterer cl{set, local, o, {}};
  for (std::size_t i = 0; i < set.lumitexels.size(); ++i)
    if (set.lumitexels[i].count > 0) cl.active.push_back(i);
  if (cl.active.empty()) throw bad_input("no lumitexel has a sample");

  ClusterResult res;
  res.model = bounded_options.fit.model;
  res.assignment.assign(set.lumitexels.size(), 0);
  std::vector<MaterialCluster> cs(1);
  cl.set_fit(cs[0], cl.fit_new(cl.active, 0));
  std::vector<double> own = distances(set, local, cl.active, o.fit.model, cs[0].params, o.fit.threads);
  cl.tally(cs, res.assignment, own);
  double total = cs[0].error;
  const double initial = total;

  const int target = o.clusters == 0 ? o.max_auto_clusters : o.clusters;
  // The final bounded refits count as one more step.
  const auto report = [&] {
    if (o.progress) o.progress(cs.size(), static_cast<std::uint64_t>(target) + 1);
  };
  report();
  while (static_cast<int>(cs.size()) < target) {
    std::size_t worst = 0;
    for (std::size_t j = 1; j < cs.size(); ++j)
      if (cs[j].error > cs[worst].error) worst = j;
    const std::vector<Members> lists = cl.member_lists(cs.size(), res.assignment);
    SplitOutcome split;
    if (!split_cluster(cl, lists[worst], cs[worst], static_cast<int>(worst), split)) break;

    std::vector<MaterialCluster> next = cs;
    std::vector<std::uint16_t> next_a = res.assignment;
    const auto created = static_cast<std::uint16_t>(next.size());
    next.emplace_back();
    cl.set_fit(next[worst], split.plus);
    cl.set_fit(next[created], split.minus);
    for (std::size_t i : split.minus_members) next_a[i] = created;
    std::vector<double> next_own = cl.reassign(next, next_a, o.global_iters);
    cl.tally(next, next_a, next_own);
    if (cl.remove_small(next, next_a)) {
      next_own = cl.reassign(next, next_a, o.global_iters);
      cl.tally(next, next_a, next_own);
    }
    double next_total = 0;
    for (const MaterialCluster& c : next) next_total += c.error;
    // The drop is measured against the one-cluster error (the variance the clustering
    // explains, as with a scree plot): relative to the current error, splitting pure
    // noise would look like a gain of 10 % and more.
    const double gain = initial > 0 ? (total - next_total) / initial : 0;
    if (o.clusters == 0 && gain < o.min_gain) break;  // auto: this split did not pay
    if (next.size() <= cs.size()) break;              // the split was dissolved again
    SplitRecord rec;
    rec.split = static_cast<int>(worst);
    rec.created = created;
    rec.clusters = static_cast<int>(next.size());
    rec.split_iterations = split.iterations;
    rec.error_before = total;
    rec.error_after = next_total;
    res.history.push_back(rec);
    cs = std::move(next);
    res.assignment = std::move(next_a);
    total = next_total;
    report();
    if (total == 0) break;
  }
  // Final BRDFs of the clusters with the bound: what is rendered from them must be
  // physically plausible also where no sample looked (see lafortune_model.hpp).
  if (bounded_options.fit.model.max_lobe_albedo > 0) {
    // Two rounds of: each lumitexel to its nearest cluster, then the bounded fits. The
    // search's last refits can leave a few lumitexels with a cluster that is no longer
    // their nearest, and a broad material's cluster that misses its most telling
    // lumitexels prefers a lobe about the normal; the second round repairs that.
    const Clusterer bounded{set, local, bounded_options, cl.active};
    for (int round = 0; round < 2; ++round) {
      (round == 0 ? cl : bounded).reassign(cs, res.assignment, 0);  // D by the search's / the bounded BRDFs
      const std::vector<Members> lists = cl.member_lists(cs.size(), res.assignment);
      for (std::size_t j = 0; j < cs.size(); ++j)
        if (!lists[j].empty()) {
          Eigen::VectorXd start = cs[j].params;
          clamp_to_bounds(bounded_options.fit.model, start);
          bounded.set_fit(cs[j], bounded.refit_or_restart(lists[j], start, static_cast<int>(j)));
        }
    }
    cl.tally(cs, res.assignment, bounded.own_distances(cs, res.assignment));
    total = 0;
    for (const MaterialCluster& c : cs) total += c.error;
  }
  res.clusters = std::move(cs);
  res.total_error = total;
  return res;
}

}  // namespace fest::brdffit

#include "patnet/markov.hpp"

#include <cmath>

#include <fmt/format.h>

namespace fest::patnet {

MarkovEstimate estimate_markov(const std::vector<int>& seq, int states, bool no_self) {
  MarkovEstimate e;
  e.states = states;
  const auto n = static_cast<std::size_t>(states);
  e.counts.assign(n, std::vector<std::int64_t>(n, 0));
  e.p.assign(n, std::vector<double>(n, 0.0));
  for (std::size_t k = 0; k + 1 < seq.size(); ++k) {
    const int i = seq[k], j = seq[k + 1];
    if (no_self && i == j) continue;
    ++e.counts[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    ++e.transitions;
  }
  for (std::size_t i = 0; i < n; ++i) {
    std::int64_t row = 0;
    for (std::int64_t c : e.counts[i]) row += c;
    if (row == 0) {
      e.unvisited.push_back(static_cast<int>(i));
      const double u = 1.0 / static_cast<double>(no_self ? n - 1 : n);
      for (std::size_t j = 0; j < n; ++j) e.p[i][j] = no_self && i == j ? 0.0 : u;
      if (n == 1) e.p[i][i] = 1.0;
      continue;
    }
    for (std::size_t j = 0; j < n; ++j) e.p[i][j] = static_cast<double>(e.counts[i][j]) / static_cast<double>(row);
  }
  return e;
}

int gaze_state(double ts, double g1, double g2) {
  if (!(ts >= 0 && ts <= 5 && ts == std::floor(ts))) return -1;
  if (!(g1 == 0 || g1 == 1) || !(g2 == 0 || g2 == 1)) return -1;
  return 4 * static_cast<int>(ts) + 2 * static_cast<int>(g1) + static_cast<int>(g2);
}

std::string markov_net(const MarkovEstimate& est, const std::string& net_name, int start, bool gaze_labels) {
  std::string out = fmt::format("; {}: transition probabilities estimated by `patnet markov` from {} transitions\n",
                                net_name, est.transitions);
  if (gaze_labels)
    out += "; state S<k>, k = 4 turn_state + 2 gaze1 + gaze2 (seed section 23: turn states 0-2 agent1 has\n"
           "; the floor, 3-5 agent2 has it; gazeN = 1 when agentN looks at the other's face)\n";
  out += fmt::format("(defnet {} :start S{}\n", net_name, start);
  for (int i = 0; i < est.states; ++i) {
    std::string line = fmt::format("  (def-probnode S{} :no-op", i);
    // Probabilities printed to 17 digits reproduce the doubles; their sum may exceed 1
    // by rounding, which the checker tolerates (1e-9).
    for (int j = 0; j < est.states; ++j) {
      const double p = est.p[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
      if (p > 0) line += fmt::format(" ({:.17g} S{})", p, j);
    }
    line += ")";
    if (gaze_labels) line += fmt::format("  ; turn state {}, gaze {}{}", i / 4, (i / 2) % 2, i % 2);
    out += line + "\n";
  }
  out += ")\n";
  return out;
}

}  // namespace fest::patnet

#pragma once
// Transition probabilities of a state sequence (docs/patnet.md "markov", seed §23): the
// gaze automaton's 24 states (turn state x agent1 gazes x agent2 gazes) estimated from a
// dialog transcript, written as a matrix or as a net of def-probnodes.

#include <cstdint>
#include <string>
#include <vector>

namespace fest::patnet {

struct MarkovEstimate {
  int states = 0;
  std::vector<std::vector<double>> p;          // row-stochastic
  std::vector<std::vector<std::int64_t>> counts;
  std::vector<int> unvisited;                  // rows with no observed transition (uniform)
  std::int64_t transitions = 0;
};

// Maximum-likelihood estimate P(i -> j) = n_ij / sum_j n_ij from consecutive pairs of
// `seq` (values in [0, states)). With no_self, pairs i -> i are not counted (the chain of
// changes) and an unvisited row is uniform over the other states.
MarkovEstimate estimate_markov(const std::vector<int>& seq, int states, bool no_self);

// The seed's gaze state: 4 turn_state + 2 gaze1 + gaze2 (0..23). -1 if out of range.
int gaze_state(double turn_state, double gaze1, double gaze2);

// A .pat file: one def-probnode S<i> per state, starting in `start`.
std::string markov_net(const MarkovEstimate& est, const std::string& net_name, int start, bool gaze_labels);

}  // namespace fest::patnet

// Construction, solution and minimisation of the chapter's state machines (docs/ebcode.md §3).
#include "edgebreaker/state_machine.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "core/error.hpp"

namespace fest::edgebreaker {
namespace {

constexpr std::array<Symbol, 5> all_symbols{Symbol::C, Symbol::L, Symbol::E, Symbol::R, Symbol::S};

std::vector<std::string> used_patterns(const ModelParams& params) {
  std::vector<std::string> used;
  const auto& all = exclusion_patterns();
  for (int k = 0; k < params.cmax && k < static_cast<int>(all.size()); ++k) {
    const std::string& p = all[static_cast<std::size_t>(k)];
    if (!params.all_patterns && p.rfind("EE", 0) == 0) continue;
    used.push_back(p);
  }
  return used;
}

class Builder {
 public:
  explicit Builder(const ModelParams& params) : params_(params), patterns_(used_patterns(params)) {}

  std::vector<MachineState> build() {
    add({"", -1, -1, -1});
    for (std::size_t i = 0; i < states_.size(); ++i) {
      const MachineState current = states_[i];
      const bool c_ok = c_allowed(current);
      states_[i].c_allowed = c_ok;
      for (Symbol s : all_symbols) {
        if (s == Symbol::C && !c_ok) continue;
        const int target = add(proceed(current, s));
        states_[i].next[static_cast<std::size_t>(s)] = target;
      }
    }
    return states_;
  }

 private:
  // Lengths: -1 is "?", and "?" stays "?" under any arithmetic.
  static int plus(int a, int b) { return a < 0 || b < 0 ? -1 : a + b; }
  static int shift(int a, int d) { return a < 0 ? -1 : a + d; }
  static int limit(int value, int max) { return max < 0 || value > max ? -1 : value; }

  bool is_prefix_of_pattern(const std::string& h) const {
    for (const std::string& p : patterns_)
      if (p.compare(0, h.size(), h) == 0 && h.size() <= p.size()) return true;
    return false;
  }
  bool c_allowed(const MachineState& st) const {
    if (st.l == 3) return false;
    for (const std::string& p : patterns_) {
      if (params_.literal_rule) {
        if (st.history == p) return false;
      } else if (st.history.size() >= p.size() &&
                 st.history.compare(st.history.size() - p.size(), p.size(), p) == 0) {
        return false;
      }
    }
    return true;
  }
  MachineState proceed(const MachineState& st, Symbol s) const {
    MachineState n;
    n.history = st.history + to_char(s);
    switch (s) {
      case Symbol::C: n.l = shift(st.l, -1), n.p = st.p, n.s = st.s; break;
      case Symbol::L:
      case Symbol::R: n.l = shift(st.l, 1), n.p = st.p, n.s = st.s; break;
      case Symbol::S: n.l = shift(plus(st.l, st.p), -1), n.p = st.s, n.s = -1; break;
      case Symbol::E: n.l = 3, n.p = st.l, n.s = st.p; break;
    }
    n.l = limit(n.l, params_.lmax);
    n.p = limit(n.p, params_.pmax);
    n.s = limit(n.s, params_.smax);
    while (!n.history.empty() && !is_prefix_of_pattern(n.history)) n.history.erase(0, 1);
    return n;
  }
  int add(const MachineState& st) {
    const auto key = std::make_tuple(st.history, st.l, st.p, st.s);
    const auto it = index_.find(key);
    if (it != index_.end()) return it->second;
    const int id = static_cast<int>(states_.size());
    index_.emplace(key, id);
    states_.push_back(st);
    return id;
  }

  ModelParams params_;
  std::vector<std::string> patterns_;
  std::vector<MachineState> states_;
  std::map<std::tuple<std::string, int, int, int>, int> index_;
};

double weight(Symbol s, double alpha) { return s == Symbol::C ? 0.5 : alpha; }

// Dominant eigenvalue of M(alpha) by power iteration normalised at the root; leaves the
// eigenvector (root = 1) in u.
double dominant_eigenvalue(const std::vector<MachineState>& states, double alpha, std::vector<double>& u) {
  u.assign(states.size(), 1.0);
  std::vector<double> w(states.size());
  double lambda = 0;
  for (int iteration = 0; iteration < 100000; ++iteration) {
    for (std::size_t i = 0; i < states.size(); ++i) {
      double sum = 0;
      for (Symbol s : all_symbols) {
        const int n = states[i].next[static_cast<std::size_t>(s)];
        if (n >= 0) sum += weight(s, alpha) * u[static_cast<std::size_t>(n)];
      }
      w[i] = sum;
    }
    const double root = w[0];
    double change = std::fabs(root - lambda);
    for (std::size_t i = 0; i < states.size(); ++i) {
      const double v = w[i] / root;
      change = std::max(change, std::fabs(v - u[i]));
      u[i] = v;
    }
    lambda = root;
    if (change < 1e-14) break;
  }
  return lambda;
}

// Moore-style refinement: states with equal unity (to 1e-9) and the same allowed symbols
// leading to the same classes are one state. Class order follows the lowest member, so
// the root stays state 0.
std::vector<MachineState> minimise(const std::vector<MachineState>& states) {
  const std::size_t n = states.size();
  std::vector<int> cls(n);
  {
    std::map<std::pair<long long, int>, int> first;
    for (std::size_t i = 0; i < n; ++i) {
      const auto key = std::make_pair(std::llround(states[i].unity * 1e9), states[i].c_allowed ? 1 : 0);
      cls[i] = first.emplace(key, static_cast<int>(first.size())).first->second;
    }
  }
  for (;;) {
    std::map<std::vector<int>, int> sig;
    std::vector<int> next_cls(n);
    for (std::size_t i = 0; i < n; ++i) {
      std::vector<int> key{cls[i]};
      for (int t : states[i].next) key.push_back(t < 0 ? -1 : cls[static_cast<std::size_t>(t)]);
      next_cls[i] = sig.emplace(key, static_cast<int>(sig.size())).first->second;
    }
    const std::size_t before = std::set<int>(cls.begin(), cls.end()).size();
    cls = next_cls;
    if (sig.size() == before) break;
  }
  // Renumber classes by lowest member.
  std::vector<int> label(n, -1);
  std::vector<std::size_t> representative;
  for (std::size_t i = 0; i < n; ++i) {
    int& l = label[static_cast<std::size_t>(cls[i])];
    if (l == -1) {
      l = static_cast<int>(representative.size());
      representative.push_back(i);
    }
  }
  std::vector<MachineState> out;
  out.reserve(representative.size());
  for (std::size_t r : representative) {
    MachineState st = states[r];
    for (int& t : st.next)
      if (t >= 0) t = label[static_cast<std::size_t>(cls[static_cast<std::size_t>(t)])];
    out.push_back(st);
  }
  return out;
}

}  // namespace

const std::vector<std::string>& exclusion_patterns() {
  static const std::vector<std::string> patterns{
      "E",       "L",       "ESC",     "ELSCC",   "ERSCC",   "ERCSC",   "ELLSCCC",
      "ELRSCCC", "ELRCCSC", "ERRCSCC", "EESSCCC", "ERCRSCC", "ERRCCSC", "ERRSCCC",
      "ERCRCSC", "EESCSCC", "ERCLSCC", "ERLSCCC", "ELRCSCC"};
  return patterns;
}

double StateMachine::rate() const { return 1.0 + std::log2(1.0 / alpha); }

double StateMachine::probability(int state, Symbol s) const {
  const MachineState& st = states[static_cast<std::size_t>(state)];
  const int n = st.next[static_cast<std::size_t>(s)];
  if (n < 0) return 0;
  return weight(s, alpha) * states[static_cast<std::size_t>(n)].unity / st.unity;
}

StateMachine build_state_machine(const ModelParams& params, bool minimise_states) {
  if (params.lmax > 64 || params.pmax > 64 || params.smax > 64 || params.cmax < 0 || params.cmax > 19)
    throw usage_error("model limits out of range (lengths at most 64, 0..19 patterns)");
  StateMachine m;
  std::vector<MachineState> states = Builder(params).build();
  m.raw_states = states.size();
  double lo = 0.125, hi = 0.2102;
  std::vector<double> u;
  for (int step = 0; step < 50; ++step) {
    const double mid = 0.5 * (lo + hi);
    (dominant_eigenvalue(states, mid, u) < 1.0 ? lo : hi) = mid;
  }
  m.alpha = 0.5 * (lo + hi);
  dominant_eigenvalue(states, m.alpha, u);
  for (std::size_t i = 0; i < states.size(); ++i) states[i].unity = u[i];
  m.states = minimise_states ? minimise(states) : std::move(states);
  return m;
}

const std::vector<NamedModel>& named_models() {
  static const std::vector<NamedModel> models{
      {"m2", 1, {-1, -1, -1, 2, false, false}},
      {"m26", 2, {9, -1, -1, 19, false, false}},
      {"m68", 3, {8, 4, -1, 19, false, false}},
      {"m236", 4, {10, 6, 3, 19, false, false}},
      {"m240x", 5, {10, 6, 3, 19, true, false}},
  };
  return models;
}

const NamedModel& named_model(std::string_view name) {
  for (const NamedModel& m : named_models())
    if (name == m.name) return m;
  throw usage_error("unknown model '{}' (m2, m26, m68, m236, m240x)", name);
}

std::vector<std::array<std::uint16_t, 5>> frequency_table(const StateMachine& machine) {
  std::vector<std::array<std::uint16_t, 5>> out(machine.states.size());
  for (std::size_t i = 0; i < machine.states.size(); ++i) {
    std::array<long, 5> f{};
    long sum = 0;
    for (Symbol s : all_symbols) {
      const double p = machine.probability(static_cast<int>(i), s);
      if (machine.states[i].next[static_cast<std::size_t>(s)] < 0) continue;
      f[static_cast<std::size_t>(s)] = std::max(1L, std::lround(p * static_total));
      sum += f[static_cast<std::size_t>(s)];
    }
    const auto largest = std::max_element(f.begin(), f.end());
    *largest += static_cast<long>(static_total) - sum;
    for (std::size_t k = 0; k < 5; ++k) out[i][k] = static_cast<std::uint16_t>(f[k]);
  }
  return out;
}

StaticCoderState::StaticCoderState(int model_id) {
  if (model_id == 0) return;
  table_ = static_model_table(model_id);
  if (table_ == nullptr) throw bad_input("unknown static model id {}", model_id);
  load();
}

void StaticCoderState::load() {
  std::uint32_t cum = 0;
  for (std::size_t k = 0; k < 5; ++k) {
    current_.f[k] = table_->freq[state_][k];
    current_.cum[k] = cum;
    cum += current_.f[k];
  }
}

void StaticCoderState::advance(Symbol s) {
  if (table_ == nullptr) return;
  const int n = table_->next[state_][static_cast<std::size_t>(s)];
  state_ = n < 0 ? 0 : n;
  load();
}

}  // namespace fest::edgebreaker

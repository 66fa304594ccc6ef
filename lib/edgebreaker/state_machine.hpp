#pragma once
// The chapter's conditional-unity state machines (seed sections 5.4-5.6, docs/ebcode.md §3):
// states (H; l, p, s) of reversed-history suffix and loop lengths, the exclusion patterns
// that say where C is impossible, the unity equations u = M(alpha) u solved by bisection
// on alpha with power iteration, and minimisation by partition refinement.
//
// Building a model is offline work (`ebcode model`); the coder uses the frequency tables
// generated from it and committed as ebm_models.inc, never a fresh floating-point solve.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "edgebreaker/clers.hpp"

namespace fest::edgebreaker {

// Limits of the state (-1: the length is never tracked) and how many of the 19 patterns
// are used (the first cmax of the chapter's list). Without all_patterns the two patterns
// that start with EE are left out, as the chapter's tables require (docs/ebcode.md §3).
struct ModelParams {
  int lmax = -1;
  int pmax = -1;
  int smax = -1;
  int cmax = 19;
  bool all_patterns = false;
  // The literal reading of the seed's isConstraint(H) (H itself is a pattern) instead of
  // "some suffix of H is a pattern"; a negative test only (docs/ebcode.md §3).
  bool literal_rule = false;
};

// The chapter's 19 exclusion patterns in decoding (reversed) order: C never follows one.
const std::vector<std::string>& exclusion_patterns();

struct MachineState {
  std::string history;  // decoding order
  int l = -1, p = -1, s = -1;  // -1 = unknown
  bool c_allowed = true;
  std::array<int, 5> next{{-1, -1, -1, -1, -1}};  // per Symbol; -1 where not allowed
  double unity = 0;
};

struct StateMachine {
  std::vector<MachineState> states;  // states[0] is the root
  std::size_t raw_states = 0;        // before minimisation
  double alpha = 0;
  double rate() const;               // bits per vertex: 1 + log2(1/alpha)
  // p(sigma | state) = w_sigma U(next) / U(state), w_C = 1/2, w_LRSE = alpha.
  double probability(int state, Symbol s) const;
};

// Builds, solves and (optionally) minimises. Throws usage_error for limits out of range.
StateMachine build_state_machine(const ModelParams& params, bool minimise = true);

// The models the coder knows, by .ebm model id: 1 m2, 2 m26, 3 m68, 4 m236, 5 m240x.
struct NamedModel {
  const char* name;
  int id;
  ModelParams params;
};
const std::vector<NamedModel>& named_models();
// Throws usage_error for an unknown name.
const NamedModel& named_model(std::string_view name);

// Per state, the frequencies of C, L, E, R, S (Symbol order) scaled to 2^15:
// max(1, round(p * 2^15)) where allowed, 0 elsewhere, the largest adjusted so they sum
// to exactly 2^15.
constexpr std::uint32_t static_total = 1u << 15;
std::vector<std::array<std::uint16_t, 5>> frequency_table(const StateMachine& machine);

// The generated tables of one model, as committed in ebm_models.inc.
struct StaticModelTable {
  int id;
  const char* name;
  std::size_t states;
  const std::uint16_t (*freq)[5];
  const std::int16_t (*next)[5];
};
// nullptr for an unknown id.
const StaticModelTable* static_model_table(int id);

struct StaticFrequencies {
  std::array<std::uint32_t, 5> f{};
  std::array<std::uint32_t, 5> cum{};
};

// The coder's walk through a committed model. Model id 0 is "no model": advance() does
// nothing and frequencies() must not be called.
class StaticCoderState {
 public:
  explicit StaticCoderState(int model_id);
  const StaticFrequencies& frequencies() const { return current_; }
  void advance(Symbol s);

 private:
  void load();
  const StaticModelTable* table_ = nullptr;
  int state_ = 0;
  StaticFrequencies current_;
};

}  // namespace fest::edgebreaker

#pragma once
// The control component (docs/segbrain.md §2): SLD resolution over the knowledge base with
// chronological backtracking, cut, if-then-else, negation as failure, the built-ins of
// the rule language, and foreign predicates (the methods pool) registered from C++.
//
// Solving is written in continuation-passing style: solve(goal, k) calls k once per
// solution and undoes its bindings when k fails. A cut returns a signal that unwinds to
// the predicate call that owns it, so a cut inside a nested call never cuts the caller.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/stack_budget.hpp"
#include "core/stopwatch.hpp"
#include "segbrain/kb_parser.hpp"
#include "segbrain/term.hpp"

namespace fest::segbrain {

// One port of the trace (docs/segbrain.md §2 "Trace").
struct TraceEvent {
  double t_ms = 0;
  const char* port = "call";   // call | exit | fail | redo | error
  int depth = 0;
  std::string goal;
  std::string clause;          // file:line of the clause that called the goal
  double dur_ms = -1;          // exit/fail: time since the call
  std::vector<std::pair<std::string, double>> measure;
};

class Engine;

// A foreign predicate: reads/binds its arguments, returns false to fail. Measurements
// put into engine.measure() appear in the trace of this call.
using Foreign = std::function<bool(Engine&, const std::vector<Term>&)>;

struct ForeignInfo {
  std::string name;
  std::string modes;   // e.g. "+Img, +SigmaMM, -Out"
  std::string doc;
  Foreign fn;
};

struct Limits {
  int max_depth = 10000;
  std::uint64_t max_inferences = 10000000;
  double time_limit_s = 0;   // 0 = none
};

struct Counters {
  std::uint64_t inferences = 0;
  std::uint64_t backtracks = 0;
  std::uint64_t foreign_calls = 0;
};

class Engine {
 public:
  Engine();

  // Adds the clauses of a parsed program (directives: dynamic/1 only; include/1 must
  // have been resolved by the caller).
  void consult(const Program& program);
  void add_clause(const Clause& clause, bool front = false);
  // Removes every clause of name/arity (to override a fact).
  void remove_predicate(const std::string& name, int arity);
  bool defines(const std::string& name, int arity) const;
  void register_foreign(const std::string& name, int arity, ForeignInfo info);
  // The same from its parts: the modes and documentation are what `segbrain ops` lists.
  void register_foreign(const std::string& name, int arity, const char* modes, const char* doc, Foreign fn) {
    register_foreign(name, arity, ForeignInfo{"", modes, doc, std::move(fn)});
  }
  const std::map<std::string, ForeignInfo>& foreigns() const { return foreign_; }
  // Every name/arity called from a clause body that is neither defined, built in nor
  // foreign: (indicator, "file:line").
  std::vector<std::pair<std::string, std::string>> undefined_calls() const;

  // Proves `goal` once. Returns false when it fails after all alternatives. Throws
  // fest::Error: bad_input for unknown predicates and type errors (with file:line),
  // failure when a limit is hit.
  bool prove(const Term& goal);

  // Binding helpers for foreign predicates (trailed, undone on backtracking).
  bool unify(const Term& a, const Term& b);
  // Registers an undo action run when execution backtracks over this point.
  void on_backtrack(std::function<void()> undo);

  // Arithmetic evaluation (is/2); throws bad_input on type errors.
  double eval_number(const Term& t, bool& is_int, std::int64_t& ival);
  double eval(const Term& t);

  std::vector<std::pair<std::string, double>>& measure() { return measure_; }
  void set_trace(std::function<void(const TraceEvent&)> sink) { trace_ = std::move(sink); }
  void set_log(std::function<void(const std::string&)> sink) { log_ = std::move(sink); }
  void set_limits(const Limits& l) { limits_ = l; }
  // --set NAME=VALUE for param/2.
  void set_param(const std::string& name, const Term& value) { params_[name] = value; }

  const Counters& counters() const { return counters_; }
  // The last check that failed (clause head name and the failing comparison with the
  // measurement behind it), for "goal ... failed" messages.
  const std::string& last_failing_check() const { return last_check_; }
  // Goals given to optional/1 that failed (recorded as skipped, docs/segbrain.md §2).
  const std::vector<std::string>& skipped() const { return skipped_; }
  // Clause (file:line) that proved each user goal last, keyed by predicate name.
  const std::map<std::string, std::string>& accepted_by() const { return accepted_by_; }

  std::string where(const Clause* c) const;

 private:
  enum class Sig { fail, stop, cut };
  struct Res {
    Sig sig = Sig::fail;
    std::uint64_t barrier = 0;
  };
  using Cont = std::function<Res()>;

  struct Pred {
    std::vector<std::shared_ptr<Clause>> clauses;
    bool dynamic = false;
  };
  struct TrailEntry {
    Node* var = nullptr;
    std::function<void()> undo;
  };

  Res solve(const Term& goal, std::uint64_t cut_barrier, int depth, const Clause* ctx, const Cont& k);
  Res call_user(const Term& goal, Pred& pred, int depth, const Clause* ctx, const Cont& k);
  Res call_builtin(const std::string& key, const Term& goal, std::uint64_t cut_barrier, int depth,
                   const Clause* ctx, const Cont& k, bool& handled);
  bool unify_rec(const Term& a, const Term& b);
  void bind(const Term& var, const Term& value);
  std::size_t mark() const { return trail_.size(); }
  void undo_to(std::size_t m);
  void emit(const char* port, int depth, const Term& goal, const Clause* ctx, double dur_ms, bool with_measure);
  double now_ms() const;
  void tick(int depth, const Clause* ctx, const Term& goal);
  bool compare_numbers(const std::string& op, const Term& a, const Term& b, const Clause* ctx);
  void add_prelude();
  [[noreturn]] void type_error(const Clause* ctx, const std::string& what) const;

  std::map<std::string, Pred> preds_;
  std::map<std::string, ForeignInfo> foreign_;
  std::map<std::string, Term> params_;
  std::vector<TrailEntry> trail_;
  std::uint64_t next_barrier_ = 1;
  Limits limits_;
  Counters counters_;
  SteadyClock::time_point start_;
  std::function<void(const TraceEvent&)> trace_;
  std::function<void(const std::string&)> log_;
  std::vector<std::pair<std::string, double>> measure_;
  std::string last_check_;
  std::vector<std::string> skipped_;
  std::map<std::string, std::string> accepted_by_;
  int cxx_depth_ = 0;
  // The outermost solve()'s frame and how far below it the proof may recurse: solve()
  // nests C++ frames per goal, so the stack, not only max_depth, bounds a proof.
  StackBudget stack_;
};

}  // namespace fest::segbrain

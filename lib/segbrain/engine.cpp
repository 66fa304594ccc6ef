// SLD resolution, built-ins and the trace of the rule engine.
#include "segbrain/engine.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "core/error.hpp"

namespace fest::segbrain {
namespace {

// Library predicates written in the rule language itself.
const char* kPrelude = R"PL(
member(X, [X|_]).
member(X, [_|T]) :- member(X, T).
memberchk(X, L) :- member(X, L), !.
append([], L, L).
append([H|T], L, [H|R]) :- append(T, L, R).
nth0(I, L, E) :- nth0_(L, 0, I, E).
nth0_([H|_], I, I, H).
nth0_([_|T], I0, I, E) :- I1 is I0 + 1, nth0_(T, I1, I, E).
last([X], X) :- !.
last([_|T], X) :- last(T, X).
once(G) :- call(G), !.
forall(C, A) :- \+ (call(C), \+ call(A)).
)PL";

std::string key_of(const Term& t) {
  Term d = deref(t);
  return fmt::format("{}/{}", d->name, d->kind == Kind::compound ? d->args.size() : 0);
}

const std::set<std::string>& builtin_keys() {
  static const std::set<std::string> keys = {
      "true/0", ",/2", ";/2", "->/2", "\\+/1", "!/0", "call/1", "call/2", "call/3", "call/4", "call/5",
      "call/6", "findall/3", "optional/1", "between/3", "fail/0", "false/0", "=/2", "\\=/2", "==/2",
      "\\==/2", "is/2", "</2", ">/2", "=</2", ">=/2", "=:=/2", "=\\=/2", "atom/1", "number/1",
      "integer/1", "var/1", "nonvar/1", "assertz/1", "retract/1", "format/1", "format/2", "format_atom/3", "param/2",
      "msort/2", "sum_list/2", "min_list/2", "max_list/2", "length/2"};
  return keys;
}

}  // namespace

Engine::Engine() : start_(SteadyClock::now()) { add_prelude(); }

void Engine::add_prelude() { consult(parse_program(kPrelude, "<prelude>")); }

void Engine::consult(const Program& program) {
  for (const auto& d : program.directives) {
    Term g = deref(d.goal);
    if (g->kind == Kind::compound && g->name == "dynamic" && g->args.size() == 1) {
      Term spec = deref(g->args[0]);
      if (spec->kind == Kind::compound && spec->name == "/" && spec->args.size() == 2) {
        Term n = deref(spec->args[0]), a = deref(spec->args[1]);
        if (n->kind == Kind::atom && a->kind == Kind::integer) {
          preds_[fmt::format("{}/{}", n->name, a->ival)].dynamic = true;
          continue;
        }
      }
      throw bad_input("{}:{}: dynamic/1 expects Name/Arity", d.file, d.line);
    }
    if (g->kind == Kind::compound && g->name == "include") continue;  // resolved by the caller
    throw bad_input("{}:{}: unknown directive {}", d.file, d.line, to_string(g));
  }
  for (const auto& c : program.clauses) add_clause(c);
}

void Engine::add_clause(const Clause& clause, bool front) {
  std::string key = key_of(clause.head);
  if (builtin_keys().count(key) || foreign_.count(key))
    throw bad_input("{}:{}: cannot redefine built-in predicate {}", clause.file, clause.line, key);
  auto& p = preds_[key];
  auto c = std::make_shared<Clause>(clause);
  if (front) p.clauses.insert(p.clauses.begin(), c);
  else p.clauses.push_back(c);
}

void Engine::remove_predicate(const std::string& name, int arity) {
  preds_[fmt::format("{}/{}", name, arity)].clauses.clear();
}

bool Engine::defines(const std::string& name, int arity) const {
  auto it = preds_.find(fmt::format("{}/{}", name, arity));
  return it != preds_.end() && (!it->second.clauses.empty() || it->second.dynamic);
}

void Engine::register_foreign(const std::string& name, int arity, ForeignInfo info) {
  info.name = fmt::format("{}/{}", name, arity);
  foreign_[info.name] = std::move(info);
}

std::vector<std::pair<std::string, std::string>> Engine::undefined_calls() const {
  std::vector<std::pair<std::string, std::string>> out;
  std::set<std::string> seen;
  std::function<void(const Term&, const Clause&)> walk = [&](const Term& t0, const Clause& c) {
    Term t = deref(t0);
    if (t->kind == Kind::var) return;
    std::string k = key_of(t);
    if (k == ",/2" || k == ";/2" || k == "->/2") {
      walk(t->args[0], c);
      walk(t->args[1], c);
      return;
    }
    if (k == "\\+/1" || k == "optional/1" || k == "once/1" || k == "call/1") {
      walk(t->args[0], c);
      return;
    }
    if (k == "findall/3" || k == "forall/2") {
      walk(t->args[1], c);
      if (k == "forall/2") walk(t->args[0], c);
      return;
    }
    if (!is_callable(t)) return;
    if (builtin_keys().count(k) || foreign_.count(k)) return;
    auto it = preds_.find(k);
    if (it != preds_.end() && (!it->second.clauses.empty() || it->second.dynamic)) return;
    if (seen.insert(k + c.file + std::to_string(c.line)).second) out.emplace_back(k, where(&c));
  };
  for (const auto& [k, p] : preds_)
    for (const auto& c : p.clauses)
      if (c->file != "<prelude>") walk(c->body, *c);
  return out;
}

std::string Engine::where(const Clause* c) const {
  return c ? fmt::format("{}:{}", c->file, c->line) : std::string("goal");
}

void Engine::type_error(const Clause* ctx, const std::string& what) const {
  throw bad_input("{}: {}", where(ctx), what);
}

double Engine::now_ms() const {
  return ms_since(start_);
}

void Engine::bind(const Term& var, const Term& value) {
  var->ref = value;
  trail_.push_back({var.get(), nullptr});
}

void Engine::on_backtrack(std::function<void()> undo) { trail_.push_back({nullptr, std::move(undo)}); }

void Engine::undo_to(std::size_t m) {
  while (trail_.size() > m) {
    TrailEntry e = std::move(trail_.back());
    trail_.pop_back();
    if (e.var) e.var->ref.reset();
    else if (e.undo) e.undo();
  }
}

bool Engine::unify(const Term& a, const Term& b) {
  std::size_t m = mark();
  if (unify_rec(a, b)) return true;
  undo_to(m);
  return false;
}

bool Engine::unify_rec(const Term& a0, const Term& b0) {
  Term a = deref(a0), b = deref(b0);
  if (a == b) return true;
  if (a->kind == Kind::var) {
    bind(a, b);
    return true;
  }
  if (b->kind == Kind::var) {
    bind(b, a);
    return true;
  }
  if (a->kind != b->kind) return false;
  switch (a->kind) {
    case Kind::atom:
    case Kind::string: return a->name == b->name;
    case Kind::integer: return a->ival == b->ival;
    case Kind::real: return a->fval == b->fval;
    case Kind::compound:
      if (a->name != b->name || a->args.size() != b->args.size()) return false;
      for (std::size_t i = 0; i < a->args.size(); ++i)
        if (!unify_rec(a->args[i], b->args[i])) return false;
      return true;
    case Kind::var: break;
  }
  return false;
}

void Engine::emit(const char* port, int depth, const Term& goal, const Clause* ctx, double dur_ms, bool with_measure) {
  if (!trace_) return;
  TraceEvent e;
  e.t_ms = now_ms();
  e.port = port;
  e.depth = depth;
  e.goal = to_string(goal);
  e.clause = where(ctx);
  e.dur_ms = dur_ms;
  if (with_measure) e.measure = measure_;
  trace_(e);
}

void Engine::tick(int depth, const Clause* ctx, const Term& goal) {
  ++counters_.inferences;
  if (counters_.inferences > limits_.max_inferences)
    throw runtime_failure("inference limit {} reached at {} ({})", limits_.max_inferences, to_string(goal), where(ctx));
  if (depth > limits_.max_depth || cxx_depth_ > 4 * limits_.max_depth)
    throw runtime_failure("depth limit {} reached at {} ({})", limits_.max_depth, to_string(goal), where(ctx));
  if (limits_.time_limit_s > 0 && (counters_.inferences & 255) == 0 && now_ms() > 1000 * limits_.time_limit_s)
    throw runtime_failure("time limit {} s reached at {} ({})", limits_.time_limit_s, to_string(goal), where(ctx));
}

bool Engine::prove(const Term& goal) {
  last_check_.clear();
  Res r = solve(goal, next_barrier_++, 0, nullptr, [] { return Res{Sig::stop, 0}; });
  return r.sig == Sig::stop;
}

double Engine::eval(const Term& t) {
  bool is_int;
  std::int64_t i;
  return eval_number(t, is_int, i);
}

double Engine::eval_number(const Term& t0, bool& is_int, std::int64_t& ival) {
  Term t = deref(t0);
  switch (t->kind) {
    case Kind::integer: is_int = true; ival = t->ival; return static_cast<double>(t->ival);
    case Kind::real: is_int = false; return t->fval;
    case Kind::var: throw bad_input("arithmetic: unbound variable {}", t->name);
    case Kind::string: throw bad_input("arithmetic: string \"{}\" is not a number", t->name);
    case Kind::atom:
      is_int = false;
      if (t->name == "inf" || t->name == "infinite") return INFINITY;
      if (t->name == "pi") return M_PI;
      if (t->name == "e") return M_E;
      throw bad_input("arithmetic: atom {} is not a number", t->name);
    case Kind::compound: break;
  }
  const std::string& f = t->name;
  if (t->args.size() == 1) {
    bool ai;
    std::int64_t av = 0;  // set only for integers
    double a = eval_number(t->args[0], ai, av);
    is_int = false;
    if (f == "-") { is_int = ai; ival = -av; return -a; }
    if (f == "+") { is_int = ai; ival = av; return a; }
    if (f == "abs") { is_int = ai; ival = av < 0 ? -av : av; return std::fabs(a); }
    if (f == "sqrt") return std::sqrt(a);
    if (f == "exp") return std::exp(a);
    if (f == "log") return std::log(a);
    if (f == "sin") return std::sin(a);
    if (f == "cos") return std::cos(a);
    if (f == "floor" || f == "ceiling" || f == "round" || f == "truncate") {
      double r = f == "floor" ? std::floor(a) : f == "ceiling" ? std::ceil(a) : f == "round" ? std::round(a) : std::trunc(a);
      is_int = std::abs(r) < 9.2e18;  // else the double alone (the cast would overflow)
      ival = is_int ? static_cast<std::int64_t>(r) : 0;
      return r;
    }
    if (f == "float") return a;
  } else if (t->args.size() == 2) {
    bool ai, bi;
    std::int64_t av = 0, bv = 0;  // set only for integers
    double a = eval_number(t->args[0], ai, av);
    double b = eval_number(t->args[1], bi, bv);
    bool ints = ai && bi;
    is_int = false;
    // Integer results only where they fit in 64 bits; otherwise the double stands.
    if (f == "+") { is_int = ints && !__builtin_add_overflow(av, bv, &ival); return a + b; }
    if (f == "-") { is_int = ints && !__builtin_sub_overflow(av, bv, &ival); return a - b; }
    if (f == "*") { is_int = ints && !__builtin_mul_overflow(av, bv, &ival); return a * b; }
    if (f == "/") {
      if (b == 0) throw bad_input("arithmetic: division by zero");
      if (ints && av % bv == 0) { is_int = true; ival = av / bv; }
      return a / b;
    }
    if (f == "//" || f == "mod") {
      if (!ints) throw bad_input("arithmetic: {} needs integers", f);
      if (bv == 0) throw bad_input("arithmetic: division by zero");
      is_int = true;
      ival = f == "//" ? av / bv : ((av % bv) + bv) % bv;
      return static_cast<double>(ival);
    }
    if (f == "min") { is_int = ints; ival = std::min(av, bv); return std::min(a, b); }
    if (f == "max") { is_int = ints; ival = std::max(av, bv); return std::max(a, b); }
    if (f == "**") return std::pow(a, b);
    if (f == "atan2") return std::atan2(a, b);
  }
  throw bad_input("arithmetic: unknown function {}", indicator(t));
}

bool Engine::compare_numbers(const std::string& op, const Term& a, const Term& b, const Clause* ctx) {
  double x, y;
  try {
    x = eval(a);
    y = eval(b);
  } catch (const Error& e) {
    type_error(ctx, e.what());
  }
  bool ok = op == "<" ? x < y : op == ">" ? x > y : op == "=<" ? x <= y : op == ">=" ? x >= y
          : op == "=:=" ? x == y : x != y;
  if (!ok && ctx) {
    // Names the failing check with the measured value, so the message says why it failed.
    std::string detail = fmt::format("{} {} {}", x, op, y);
    if (!measure_.empty()) {
      detail.clear();
      for (const auto& [k, v] : measure_) detail += fmt::format("{}{} {}", detail.empty() ? "" : ", ", k, v);
      detail += fmt::format("; {} {} {} is false", x, op, y);
    }
    last_check_ = fmt::format("{} ({})", deref(ctx->head)->name, detail);
    // The bound that was crossed joins the measurement, so the failing lines of the
    // trace explain themselves ({"skin_contact_fraction":0.0124,"max":0.003}).
    if (!measure_.empty()) measure_.push_back({op == "<" || op == "=<" ? "max" : op == ">" || op == ">=" ? "min" : "expected", y});
  }
  return ok;
}

Engine::Res Engine::call_user(const Term& goal, Pred& pred, int depth, const Clause* ctx, const Cont& k) {
  const std::uint64_t barrier = next_barrier_++;
  auto clauses = pred.clauses;  // logical update view: assertz during the call is not seen
  const double t0 = now_ms();
  emit("call", depth, goal, ctx, -1, false);
  bool first = true;
  for (const auto& c : clauses) {
    std::size_t m = mark();
    // Renames the clause by copying head and body together (shared variables stay shared).
    Term both = copy_term(make_compound(":-", {c->head, c->body}));
    if (!unify_rec(goal, both->args[0])) {
      undo_to(m);
      continue;
    }
    if (!first) {
      ++counters_.backtracks;
      // A new alternative starts: the measurement that explained the failure is spent.
      measure_.clear();
      emit("redo", depth, goal, ctx, -1, false);
    }
    first = false;
    const Clause* cl = c.get();
    Res r = solve(both->args[1], barrier, depth + 1, cl, [&]() -> Res {
      accepted_by_[deref(goal)->name] = where(cl);
      emit("exit", depth, goal, ctx, now_ms() - t0, false);
      return k();
    });
    if (r.sig == Sig::stop) return r;
    undo_to(m);
    if (r.sig == Sig::cut) {
      if (r.barrier == barrier) break;
      return r;
    }
  }
  emit("fail", depth, goal, ctx, now_ms() - t0, true);
  return Res{Sig::fail, 0};
}

Engine::Res Engine::solve(const Term& goal0, std::uint64_t cut_barrier, int depth, const Clause* ctx, const Cont& k) {
  Term goal = deref(goal0);
  if (goal->kind == Kind::var) type_error(ctx, "instantiation error: unbound goal " + goal->name);
  if (!is_callable(goal)) type_error(ctx, "type error: goal " + to_string(goal) + " is not callable");
  // A deep recursion within max_depth can still exhaust the stack (default limits, an
  // 8 MiB stack and a one-clause loop did): stop it with a message, not SIGSEGV.
  const char* frame = stack_position();
  if (cxx_depth_ == 0) {
    stack_.arm(frame);
  } else if (stack_.exhausted(frame)) {
    throw runtime_failure("proof nested too deeply for the stack ({} KiB, depth {}) at {} ({})",
                          stack_.budget_bytes() >> 10, depth, to_string(goal), where(ctx));
  }
  struct DepthGuard {
    int& d;
    explicit DepthGuard(int& x) : d(x) { ++d; }
    ~DepthGuard() { --d; }
  } guard(cxx_depth_);
  tick(depth, ctx, goal);
  const std::string key = key_of(goal);

  bool handled = true;
  Res r = call_builtin(key, goal, cut_barrier, depth, ctx, k, handled);
  if (handled) return r;

  auto fit = foreign_.find(key);
  if (fit != foreign_.end()) {
    ++counters_.foreign_calls;
    measure_.clear();
    const double t0 = now_ms();
    emit("call", depth, goal, ctx, -1, false);
    std::size_t m = mark();
    bool ok;
    try {
      ok = fit->second.fn(*this, goal->args);
    } catch (const Error& e) {
      if (e.status() == Status::bad_input) type_error(ctx, fmt::format("{}: {}", to_string(goal), e.what()));
      throw;
    }
    if (!ok) {
      undo_to(m);
      if (!measure_.empty() && ctx) {
        std::string detail;
        for (const auto& [mk, v] : measure_) detail += fmt::format("{}{} {}", detail.empty() ? "" : ", ", mk, v);
        last_check_ = fmt::format("{} ({})", deref(goal)->name, detail);
      }
      emit("fail", depth, goal, ctx, now_ms() - t0, true);
      return Res{Sig::fail, 0};
    }
    emit("exit", depth, goal, ctx, now_ms() - t0, true);
    // The measurement stays until the next operator call, so the comparison that
    // checks it can name it when it fails.
    Res rr = k();
    if (rr.sig != Sig::stop) undo_to(m);
    return rr;
  }

  auto pit = preds_.find(key);
  if (pit == preds_.end() || (pit->second.clauses.empty() && !pit->second.dynamic))
    throw bad_input("{}: unknown predicate {}", where(ctx), key);
  return call_user(goal, pit->second, depth, ctx, k);
}

Engine::Res Engine::call_builtin(const std::string& key, const Term& goal, std::uint64_t cut_barrier, int depth,
                                 const Clause* ctx, const Cont& k, bool& handled) {
  const auto& a = goal->args;
  auto det = [&](bool ok) -> Res {  // a deterministic built-in: continue or fail
    if (!ok) return Res{Sig::fail, 0};
    return k();
  };
  auto det_unify = [&](const Term& x, const Term& y) -> Res {
    std::size_t m = mark();
    if (!unify_rec(x, y)) {
      undo_to(m);
      return Res{Sig::fail, 0};
    }
    Res r = k();
    if (r.sig != Sig::stop) undo_to(m);
    return r;
  };
  auto number_list = [&](const Term& t, const char* who) {
    std::vector<Term> items;
    if (!list_items(t, items)) type_error(ctx, fmt::format("{}: expected a list", who));
    std::vector<double> v;
    for (const auto& x : items) {
      try {
        v.push_back(eval(x));
      } catch (const Error& e) {
        type_error(ctx, fmt::format("{}: {}", who, e.what()));
      }
    }
    return v;
  };
  auto make_num = [](double v, bool is_int, std::int64_t i) { return is_int ? make_int(i) : make_real(v); };

  if (key == "true/0") return k();
  if (key == "fail/0" || key == "false/0") return Res{Sig::fail, 0};
  if (key == ",/2")
    return solve(a[0], cut_barrier, depth, ctx, [&]() { return solve(a[1], cut_barrier, depth, ctx, k); });
  if (key == "!/0") {
    Res r = k();
    if (r.sig == Sig::fail) return Res{Sig::cut, cut_barrier};
    return r;
  }
  if (key == ";/2") {
    Term lhs = deref(a[0]);
    if (lhs->kind == Kind::compound && lhs->name == "->" && lhs->args.size() == 2) {
      // (C -> T ; E): the condition is opaque to cut and proved at most once.
      const std::uint64_t b = next_barrier_++;
      bool cond = false;
      std::size_t m = mark();
      Res r = solve(lhs->args[0], b, depth, ctx, [&]() -> Res {
        cond = true;
        Res rt = solve(lhs->args[1], cut_barrier, depth, ctx, k);
        if (rt.sig == Sig::fail) return Res{Sig::cut, b};
        return rt;
      });
      if (r.sig == Sig::stop) return r;
      if (r.sig == Sig::cut && r.barrier != b) return r;
      if (cond) return Res{Sig::fail, 0};
      undo_to(m);
      return solve(a[1], cut_barrier, depth, ctx, k);
    }
    std::size_t m = mark();
    Res r = solve(a[0], cut_barrier, depth, ctx, k);
    if (r.sig != Sig::fail) return r;
    undo_to(m);
    ++counters_.backtracks;
    return solve(a[1], cut_barrier, depth, ctx, k);
  }
  if (key == "->/2") {
    const std::uint64_t b = next_barrier_++;
    Res r = solve(a[0], b, depth, ctx, [&]() -> Res {
      Res rt = solve(a[1], cut_barrier, depth, ctx, k);
      if (rt.sig == Sig::fail) return Res{Sig::cut, b};
      return rt;
    });
    if (r.sig == Sig::cut && r.barrier == b) return Res{Sig::fail, 0};
    return r;
  }
  if (key == "\\+/1") {
    const std::uint64_t b = next_barrier_++;
    std::size_t m = mark();
    bool found = false;
    Res r = solve(a[0], b, depth, ctx, [&]() -> Res {
      found = true;
      return Res{Sig::cut, b};
    });
    undo_to(m);
    if (r.sig == Sig::cut && r.barrier != b) return r;
    return found ? Res{Sig::fail, 0} : k();
  }
  if (key.rfind("call/", 0) == 0) {
    Term g = deref(a[0]);
    if (a.size() > 1) {
      if (!is_callable(g)) type_error(ctx, "call/N: not callable: " + to_string(g));
      std::vector<Term> args = g->kind == Kind::compound ? g->args : std::vector<Term>{};
      args.insert(args.end(), a.begin() + 1, a.end());
      g = make_compound(g->name, args);
    }
    // call/N is opaque to cut: a cut inside cuts only the called goal.
    const std::uint64_t b = next_barrier_++;
    Res r = solve(g, b, depth, ctx, k);
    if (r.sig == Sig::cut && r.barrier == b) return Res{Sig::fail, 0};
    return r;
  }
  if (key == "optional/1") {
    const std::uint64_t b = next_barrier_++;
    bool proved = false;
    std::size_t m = mark();
    Res r = solve(a[0], b, depth, ctx, [&]() -> Res {
      proved = true;
      Res rk = k();
      if (rk.sig == Sig::fail) return Res{Sig::cut, b};  // once: no retry of the goal
      return rk;
    });
    if (r.sig == Sig::stop || (r.sig == Sig::cut && r.barrier != b)) return r;
    if (proved) return Res{Sig::fail, 0};
    undo_to(m);
    skipped_.push_back(to_string(a[0]));
    on_backtrack([this] { skipped_.pop_back(); });
    return k();
  }
  if (key == "findall/3") {
    std::vector<Term> found;
    const std::uint64_t b = next_barrier_++;
    std::size_t m = mark();
    Res r = solve(a[1], b, depth, ctx, [&]() -> Res {
      found.push_back(copy_term(a[0]));
      return Res{Sig::fail, 0};
    });
    undo_to(m);
    if (r.sig == Sig::cut && r.barrier != b) return r;
    return det_unify(a[2], make_list(found));
  }
  if (key == "between/3") {
    double lo, hi;
    try {
      lo = eval(a[0]);
      hi = eval(a[1]);
    } catch (const Error& e) {
      type_error(ctx, std::string("between/3: ") + e.what());
    }
    Term x = deref(a[2]);
    if (x->kind != Kind::var) {
      double v = number_value(x);
      return det(is_number(x) && v >= lo && v <= hi);
    }
    for (auto i = static_cast<std::int64_t>(lo); i <= hi; ++i) {
      std::size_t m = mark();
      bind(x, make_int(i));
      Res r = k();
      if (r.sig != Sig::fail) return r;
      undo_to(m);
      ++counters_.backtracks;
    }
    return Res{Sig::fail, 0};
  }
  if (key == "=/2") return det_unify(a[0], a[1]);
  if (key == "\\=/2") {
    std::size_t m = mark();
    bool u = unify_rec(a[0], a[1]);
    undo_to(m);
    return det(!u);
  }
  if (key == "==/2") return det(compare_terms(a[0], a[1]) == 0);
  if (key == "\\==/2") return det(compare_terms(a[0], a[1]) != 0);
  if (key == "is/2") {
    bool is_int = false;
    std::int64_t i = 0;
    double v;
    try {
      v = eval_number(a[1], is_int, i);
    } catch (const Error& e) {
      type_error(ctx, e.what());
    }
    return det_unify(a[0], make_num(v, is_int, i));
  }
  if (key == "</2" || key == ">/2" || key == "=</2" || key == ">=/2" || key == "=:=/2" || key == "=\\=/2")
    return det(compare_numbers(goal->name, a[0], a[1], ctx));
  if (key == "atom/1") return det(deref(a[0])->kind == Kind::atom);
  if (key == "number/1") return det(is_number(a[0]));
  if (key == "integer/1") return det(deref(a[0])->kind == Kind::integer);
  if (key == "var/1") return det(deref(a[0])->kind == Kind::var);
  if (key == "nonvar/1") return det(deref(a[0])->kind != Kind::var);
  if (key == "assertz/1" || key == "retract/1") {
    Term c = deref(a[0]);
    Term head = c, body = make_atom("true");
    if (c->kind == Kind::compound && c->name == ":-" && c->args.size() == 2) {
      head = deref(c->args[0]);
      body = c->args[1];
    }
    if (!is_callable(head)) type_error(ctx, goal->name + ": not a clause: " + to_string(c));
    auto it = preds_.find(key_of(head));
    if (it == preds_.end() || !it->second.dynamic)
      type_error(ctx, fmt::format("{}: {} is not declared dynamic", goal->name, key_of(head)));
    if (key == "assertz/1") {
      Clause cl;
      cl.head = copy_term(head);
      cl.body = copy_term(body);
      cl.file = ctx ? ctx->file : "<goal>";
      cl.line = ctx ? ctx->line : 0;
      it->second.clauses.push_back(std::make_shared<Clause>(cl));
      return k();
    }
    auto& cls = it->second.clauses;
    for (std::size_t i = 0; i < cls.size(); ++i) {
      std::size_t m = mark();
      Term both = copy_term(make_compound(":-", {cls[i]->head, cls[i]->body}));
      if (unify_rec(head, both->args[0]) && unify_rec(body, both->args[1])) {
        cls.erase(cls.begin() + static_cast<std::ptrdiff_t>(i));
        Res r = k();
        if (r.sig != Sig::stop) undo_to(m);
        return r;
      }
      undo_to(m);
    }
    return Res{Sig::fail, 0};
  }
  if (key == "format/1" || key == "format/2" || key == "format_atom/3") {
    Term f = deref(a[0]);
    if (f->kind != Kind::atom && f->kind != Kind::string) type_error(ctx, goal->name + ": the format must be an atom or a string, got " + to_string(f));
    std::vector<Term> args;
    if (a.size() >= 2 && !list_items(a[1], args)) args = {a[1]};
    std::string out;
    std::size_t ai = 0;
    for (std::size_t i = 0; i < f->name.size(); ++i) {
      char c = f->name[i];
      if (c == '~' && i + 1 < f->name.size()) {
        char d = f->name[++i];
        if (d == 'n') out += '\n';
        else if (d == '~') out += '~';
        else if (ai < args.size()) {
          Term x = deref(args[ai++]);
          out += x->kind == Kind::atom || x->kind == Kind::string ? x->name : to_string(x);
        }
      } else {
        out += c;
      }
    }
    // format_atom(+Format, +Args, -Atom): the same text as an atom (the knowledge base's
    // notes on what it skipped and why, docs/segbrain.md §1).
    if (key == "format_atom/3") return det_unify(a[2], make_atom(out));
    if (log_) log_(out);
    return k();
  }
  if (key == "param/2") {
    Term n = deref(a[0]);
    if (n->kind == Kind::atom) {
      auto it = params_.find(n->name);
      if (it != params_.end()) return det_unify(a[1], it->second);
    }
    auto pit = preds_.find("param_default/2");
    if (pit == preds_.end()) return Res{Sig::fail, 0};
    return call_user(make_compound("param_default", {a[0], a[1]}), pit->second, depth, ctx, k);
  }
  if (key == "msort/2") {
    std::vector<Term> items;
    if (!list_items(a[0], items)) type_error(ctx, "msort/2: expected a list");
    std::stable_sort(items.begin(), items.end(), [](const Term& x, const Term& y) { return compare_terms(x, y) < 0; });
    return det_unify(a[1], make_list(items));
  }
  if (key == "sum_list/2" || key == "min_list/2" || key == "max_list/2") {
    std::vector<double> v = number_list(a[0], goal->name.c_str());
    if (v.empty() && key != "sum_list/2") return Res{Sig::fail, 0};
    double r = key == "sum_list/2" ? 0 : v[0];
    for (double x : v) r = key == "sum_list/2" ? r + x : key == "min_list/2" ? std::min(r, x) : std::max(r, x);
    bool all_int = std::all_of(v.begin(), v.end(), [](double x) { return x == std::floor(x) && std::fabs(x) < 9e15; });
    std::vector<Term> items;
    list_items(a[0], items);
    bool ints = all_int && std::all_of(items.begin(), items.end(), [](const Term& x) { return deref(x)->kind == Kind::integer; });
    return det_unify(a[1], make_num(r, ints, static_cast<std::int64_t>(r)));
  }
  if (key == "length/2") {
    std::vector<Term> items;
    if (list_items(a[0], items)) return det_unify(a[1], make_int(static_cast<std::int64_t>(items.size())));
    Term n = deref(a[1]);
    if (n->kind != Kind::integer || n->ival < 0) type_error(ctx, "length/2: needs a list or a length");
    std::vector<Term> fresh;
    for (std::int64_t i = 0; i < n->ival; ++i) fresh.push_back(make_var());
    return det_unify(a[0], make_list(fresh));
  }
  handled = false;
  return Res{Sig::fail, 0};
}

}  // namespace fest::segbrain

// The PaT-Lisp evaluator: expression trees, the built-in functions, printing and
// `format` (docs/patnet.md "Language").

#include <cmath>
#include <cstring>

#include "core/error.hpp"
#include "patnet/machine.hpp"
#include "patnet/syms.hpp"

namespace fest::patnet {

namespace {
struct ReturnSignal {
  Value v;
};
// Arguments of one call, on the stack when few.
struct Args {
  Value small[3];
  std::vector<Value> big;
  std::size_t n = 0;
  Value* data() { return n <= 3 ? small : big.data(); }
};
}  // namespace

std::string Machine::where(SrcPos pos) const {
  if (pos.line == 0 || files_.empty()) return "<eval>";
  return fmt::format("{}:{}:{}", files_[static_cast<std::size_t>(pos.file)], pos.line, pos.col);
}

void Machine::error(SrcPos pos, std::string msg) const { throw LispError{std::move(msg), pos}; }

bool Machine::lookup_lexical(const std::shared_ptr<Frame>& env, int sym, Value** out) const {
  for (Frame* f = env.get(); f != nullptr; f = f->parent.get())
    for (auto& [s, v] : f->vars)
      if (s == sym) {
        *out = &v;
        return true;
      }
  return false;
}

Value Machine::val_get(const Expr* e, Instance* self) {
  if (self == nullptr) error(e->pos, fmt::format("(val {}) outside a net", names_[e->sym]));
  if (e->cache_cls == self->cls) {
    if (e->cache_slot >= 0) return self->locals[static_cast<std::size_t>(e->cache_slot)];
    return *e->cache_cv;
  }
  auto it = self->cls->local_slot.find(e->sym);
  e->cache_cls = self->cls;
  if (it != self->cls->local_slot.end()) {
    e->cache_slot = it->second;
    return self->locals[static_cast<std::size_t>(it->second)];
  }
  Value* cv = self->cls->find_classvar(e->sym);
  if (cv == nullptr) {
    e->cache_cls = nullptr;
    error(e->pos, fmt::format("{} is neither a local nor a class variable of {}", names_[e->sym], self->cls->print_name));
  }
  e->cache_slot = -1;
  e->cache_cv = cv;
  return *cv;
}

void Machine::val_set(const Expr* e, Instance* self, Value v) {
  val_get(e, self);  // resolves (and checks) the place
  if (e->cache_slot >= 0) self->locals[static_cast<std::size_t>(e->cache_slot)] = std::move(v);
  else *e->cache_cv = std::move(v);
}

Value Machine::eval(const Expr* e, Instance* self, const std::shared_ptr<Frame>& env) {
  if (++steps_ > opt_.max_steps)
    throw LimitError{fmt::format("code ran more than {} evaluation steps in one action, condition or monitor "
                               "without yielding ({})", opt_.max_steps, where(e->pos))};
  switch (e->op) {
    case Op::constant: return e->k;
    case Op::self: return self != nullptr ? Value::instance(self) : Value::nil();
    case Op::var: {
      Value* v = nullptr;
      if (lookup_lexical(env, e->sym, &v)) return *v;
      if (bound_[static_cast<std::size_t>(e->sym)]) return globals_[static_cast<std::size_t>(e->sym)];
      error(e->pos, fmt::format("unbound variable {}", names_[e->sym]));
    }
    case Op::setvar: {
      Value x = eval(e->kids[0], self, env);
      Value* v = nullptr;
      if (lookup_lexical(env, e->sym, &v)) {
        *v = x;
      } else {
        if (x.tag == Tag::instance && x.u.inst->var.empty()) {
          std::string n = names_[e->sym];
          for (char& ch : n) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
          x.u.inst->var = n;
        }
        globals_[static_cast<std::size_t>(e->sym)] = x;
        bound_[static_cast<std::size_t>(e->sym)] = 1;
      }
      return x;
    }
    case Op::val_get: return val_get(e, self);
    case Op::val_set: {
      Value x = eval(e->kids[0], self, env);
      val_set(e, self, x);
      return x;
    }
    case Op::if_:
      return eval(e->kids[0], self, env).truthy() ? eval(e->kids[1], self, env) : eval(e->kids[2], self, env);
    case Op::and_: {
      Value r = Value::t();
      for (const Expr* k : e->kids) {
        r = eval(k, self, env);
        if (!r.truthy()) return r;
      }
      return r;
    }
    case Op::or_: {
      for (const Expr* k : e->kids) {
        Value r = eval(k, self, env);
        if (r.truthy()) return r;
      }
      return Value::nil();
    }
    case Op::progn: {
      Value r;
      for (const Expr* k : e->kids) r = eval(k, self, env);
      return r;
    }
    case Op::cond: {
      for (std::size_t i = 0; i + 1 < e->kids.size(); i += 2) {
        Value t = eval(e->kids[i], self, env);
        if (t.truthy()) return e->kids[i + 1] != nullptr ? eval(e->kids[i + 1], self, env) : t;
      }
      return Value::nil();
    }
    case Op::let:
    case Op::letstar: {
      auto f = std::make_shared<Frame>();
      f->parent = env;
      for (std::size_t i = 0; i < e->syms.size(); ++i) {
        Value x = eval(e->kids[i], self, e->op == Op::let ? env : f);
        f->vars.emplace_back(e->syms[i], std::move(x));
      }
      return eval(e->kids.back(), self, f);
    }
    case Op::lambda: {
      Value v;
      v.tag = Tag::closure;
      auto c = std::make_shared<Closure>();
      c->fn = e->fn;
      c->env = env;
      c->self = self;
      v.obj = std::move(c);
      return v;
    }
    case Op::funcref: {
      const Function* fn = user_fns_[static_cast<std::size_t>(e->sym)];
      if (fn == nullptr) {
        for (int b = 0; b < B_COUNT; ++b)
          if (sy_->builtin_sym[b] == e->sym) {
            Value v;
            v.tag = Tag::builtin;
            v.u.builtin = b;
            return v;
          }
        error(e->pos, fmt::format("undefined function {}", names_[e->sym]));
      }
      Value v;
      v.tag = Tag::closure;
      auto c = std::make_shared<Closure>();
      c->fn = fn;
      c->self = self;
      v.obj = std::move(c);
      return v;
    }
    case Op::call_builtin:
    case Op::call_user:
    case Op::send: {
      Args a;
      a.n = e->kids.size();
      if (a.n > 3) a.big.resize(a.n);
      Value* p = a.data();
      for (std::size_t i = 0; i < a.n; ++i) p[i] = eval(e->kids[i], self, env);
      if (e->op == Op::call_builtin) return call_builtin(e->sym, p, a.n, e->pos, self);
      if (e->op == Op::send) return send(self, p[0], e->sym, p + 1, a.n - 1, e->pos);
      const Function* fn = user_fns_[static_cast<std::size_t>(e->sym)];
      if (fn == nullptr) error(e->pos, fmt::format("undefined function {}", names_[e->sym]));
      return call_function(fn, self, nullptr, p, a.n, e->pos);
    }
    case Op::dolist:
    case Op::dotimes: {
      Value src = eval(e->kids[0], self, env);
      auto f = std::make_shared<Frame>();
      f->parent = env;
      f->vars.emplace_back(e->syms[0], Value::nil());
      try {
        if (e->op == Op::dolist) {
          for (Value l = src; l.tag == Tag::cons; l = cons_of(l)->cdr) {
            f->vars[0].second = cons_of(l)->car;
            eval(e->kids[2], self, f);
          }
        } else {
          if (src.tag != Tag::integer) error(e->pos, "DOTIMES needs an integer count");
          for (std::int64_t i = 0; i < src.u.i; ++i) {
            f->vars[0].second = Value::integer(i);
            eval(e->kids[2], self, f);
          }
        }
      } catch (ReturnSignal& r) {
        return r.v;
      }
      return eval(e->kids[1], self, f);
    }
    case Op::return_: throw ReturnSignal{eval(e->kids[0], self, env)};
  }
  return Value::nil();
}

Value Machine::call_function(const Function* fn, Instance* self, const std::shared_ptr<Frame>& env, const Value* args,
                             std::size_t n, SrcPos pos) {
  const LambdaList& ll = fn->params;
  const std::string& fname = fn->name >= 0 ? names_[static_cast<std::size_t>(fn->name)] : names_[0];
  if (n < ll.required.size() || (ll.key.empty() && ll.rest < 0 && n > ll.required.size() + ll.optional.size()))
    error(pos, fmt::format("{} takes {}{} arguments, got {}", fname, ll.required.size(),
                           ll.optional.empty() && ll.key.empty() && ll.rest < 0 ? "" : " or more", n));
  // The depth limit alone does not keep the recursion on the stack: eval() nests several
  // C++ frames per call, and a sanitizer build or a small thread stack runs out first.
  const char* frame = stack_position();
  if (depth_ == 0) stack_.arm(frame);
  if (++depth_ > opt_.max_depth) {
    depth_ = 0;
    throw LimitError{fmt::format("calls nested deeper than {} ({})", opt_.max_depth, where(pos))};
  }
  if (stack_.exhausted(frame)) {
    const int depth = depth_;
    depth_ = 0;
    throw LimitError{fmt::format("calls nested deeper than the stack allows ({} KiB at depth {}) ({})",
                                 stack_.budget_bytes() >> 10, depth, where(pos))};
  }
  std::shared_ptr<Frame> f = env;
  if (!ll.required.empty() || !ll.optional.empty() || !ll.key.empty() || ll.rest >= 0) {
    f = std::make_shared<Frame>();
    f->parent = env;
    std::size_t i = 0;
    for (int r : ll.required) f->vars.emplace_back(r, args[i++]);
    for (auto& [o, def] : ll.optional) {
      if (i < n) f->vars.emplace_back(o, args[i++]);
      else f->vars.emplace_back(o, def != nullptr ? eval(def, self, f) : Value::nil());
    }
    if (ll.rest >= 0) {
      Value l;
      for (std::size_t j = n; j > i; --j) l = Value::cons(args[j - 1], l);
      f->vars.emplace_back(ll.rest, l);
    }
    if (!ll.key.empty()) {
      if ((n - i) % 2 != 0) error(pos, fmt::format("{}: keyword arguments come in pairs", fname));
      for (std::size_t j = i; j < n; j += 2)
        if (args[j].tag != Tag::symbol || names_[static_cast<std::size_t>(args[j].u.sym)][0] != ':')
          error(pos, fmt::format("{}: expected a keyword, got {}", fname, print(args[j], true)));
      for (auto& [k, def] : ll.key) {
        const int kw = intern(":" + names_[static_cast<std::size_t>(k)]);
        bool found = false;
        for (std::size_t j = i; j < n; j += 2)
          if (args[j].u.sym == kw) {
            f->vars.emplace_back(k, args[j + 1]);
            found = true;
            break;
          }
        if (!found) f->vars.emplace_back(k, def != nullptr ? eval(def, self, f) : Value::nil());
      }
    }
  }
  try {
    Value r = eval(fn->body, self, f);
    --depth_;
    return r;
  } catch (const ReturnSignal&) {  // unreachable after the compiler's check; never let it escape
    --depth_;
    error(pos, "RETURN outside a DOLIST or DOTIMES body");
  }
}

Value Machine::apply(const Value& f, const Value* args, std::size_t n, SrcPos pos) {
  if (f.tag == Tag::closure) {
    const Closure* c = closure_of(f);
    return call_function(c->fn, c->self, c->env, args, n, pos);
  }
  if (f.tag == Tag::builtin) return call_builtin(f.u.builtin, args, n, pos, nullptr);
  if (f.tag == Tag::symbol && user_fns_[static_cast<std::size_t>(f.u.sym)] != nullptr)
    return call_function(user_fns_[static_cast<std::size_t>(f.u.sym)], nullptr, nullptr, args, n, pos);
  error(pos, fmt::format("{} is not a function", print(f, true)));
}

namespace {

bool eql(const Value& a, const Value& b) {
  if (a.tag != b.tag) return false;
  switch (a.tag) {
    case Tag::nil:
    case Tag::t:
    case Tag::semclass: return true;
    case Tag::integer: return a.u.i == b.u.i;
    case Tag::real: return a.u.d == b.u.d;
    case Tag::symbol: return a.u.sym == b.u.sym;
    case Tag::builtin: return a.u.builtin == b.u.builtin;
    case Tag::instance: return a.u.inst == b.u.inst;
    case Tag::netclass: return a.u.cls == b.u.cls;
    case Tag::semaphore: return a.u.sem == b.u.sem;
    case Tag::motion: return a.u.motion == b.u.motion;
    default: return a.obj == b.obj;
  }
}

bool equal(const Value& a0, const Value& b0) {
  const Value* a = &a0;
  const Value* b = &b0;
  // along the cdr chain in a loop, into the cars by recursion
  while (a->tag == Tag::cons && b->tag == Tag::cons) {
    if (!equal(cons_of(*a)->car, cons_of(*b)->car)) return false;
    a = &cons_of(*a)->cdr;
    b = &cons_of(*b)->cdr;
  }
  if (a->tag == Tag::string && b->tag == Tag::string) return str_of(*a) == str_of(*b);
  return eql(*a, *b);
}

}  // namespace

Value Machine::call_builtin(int id, const Value* a, std::size_t n, SrcPos pos, Instance* self) {
  auto arity = [&](std::size_t lo, std::size_t hi) {
    if (n < lo || n > hi)
      error(pos, fmt::format("{} takes {} arguments, got {}", builtin_names[id],
                             lo == hi ? std::to_string(lo) : fmt::format("{} to {}", lo, hi), n));
  };
  auto num = [&](std::size_t i) -> const Value& {
    if (!a[i].is_number()) error(pos, fmt::format("{}: {} is not a number", builtin_names[id], print(a[i], true)));
    return a[i];
  };
  auto real = [&](std::size_t i) { return num(i).number(); };
  auto list_arg = [&](std::size_t i) -> const Value& {
    if (a[i].tag != Tag::cons && a[i].tag != Tag::nil)
      error(pos, fmt::format("{}: {} is not a list", builtin_names[id], print(a[i], true)));
    return a[i];
  };
  constexpr std::size_t any = static_cast<std::size_t>(-1);
  switch (id) {
    case B_ADD:
    case B_MUL: {
      bool is_int = true;
      std::int64_t ir = id == B_ADD ? 0 : 1;
      double dr = static_cast<double>(ir);
      for (std::size_t i = 0; i < n; ++i) {
        const Value& v = num(i);
        if (is_int && v.tag == Tag::integer) {
          std::int64_t r;
          const bool over = id == B_ADD ? __builtin_add_overflow(ir, v.u.i, &r) : __builtin_mul_overflow(ir, v.u.i, &r);
          if (!over) {
            ir = r;
            continue;
          }
        }
        if (is_int) {
          is_int = false;
          dr = static_cast<double>(ir);
        }
        dr = id == B_ADD ? dr + v.number() : dr * v.number();
      }
      return is_int ? Value::integer(ir) : Value::real(dr);
    }
    case B_SUB: {
      arity(1, any);
      if (n == 1) return a[0].tag == Tag::integer && a[0].u.i != INT64_MIN ? Value::integer(-a[0].u.i) : Value::real(-real(0));
      bool is_int = num(0).tag == Tag::integer;
      std::int64_t ir = is_int ? a[0].u.i : 0;
      double dr = a[0].number();
      for (std::size_t i = 1; i < n; ++i) {
        const Value& v = num(i);
        std::int64_t r;
        if (is_int && v.tag == Tag::integer && !__builtin_sub_overflow(ir, v.u.i, &r)) {
          ir = r;
          dr = static_cast<double>(r);
          continue;
        }
        if (is_int) dr = static_cast<double>(ir);
        is_int = false;
        dr -= v.number();
      }
      return is_int ? Value::integer(ir) : Value::real(dr);
    }
    case B_DIV: {
      arity(1, any);
      if (n == 1) {
        if (real(0) == 0.0) error(pos, "division by zero");
        return Value::real(1.0 / real(0));
      }
      Value r = num(0);
      for (std::size_t i = 1; i < n; ++i) {
        const Value& v = num(i);
        if (v.number() == 0.0) error(pos, "division by zero");
        // Integers divide exactly to an integer; otherwise the quotient is a float.
        if (r.tag == Tag::integer && v.tag == Tag::integer && r.u.i % v.u.i == 0 && !(r.u.i == INT64_MIN && v.u.i == -1))
          r = Value::integer(r.u.i / v.u.i);
        else
          r = Value::real(r.number() / v.number());
      }
      return r;
    }
    case B_INC:
    case B_DEC: {
      arity(1, 1);
      const Value& v = num(0);
      std::int64_t r;
      if (v.tag == Tag::integer && !(id == B_INC ? __builtin_add_overflow(v.u.i, 1, &r) : __builtin_sub_overflow(v.u.i, 1, &r)))
        return Value::integer(r);
      return Value::real(v.number() + (id == B_INC ? 1.0 : -1.0));
    }
    case B_NUMEQ: case B_NUMNE: case B_LT: case B_GT: case B_LE: case B_GE: {
      arity(1, any);
      for (std::size_t i = 0; i < n; ++i) num(i);
      if (id == B_NUMNE) {
        for (std::size_t i = 0; i < n; ++i)
          for (std::size_t j = i + 1; j < n; ++j)
            if (a[i].number() == a[j].number()) return Value::nil();
        return Value::t();
      }
      for (std::size_t i = 0; i + 1 < n; ++i) {
        bool ok;
        if (a[i].tag == Tag::integer && a[i + 1].tag == Tag::integer) {
          const std::int64_t x = a[i].u.i, y = a[i + 1].u.i;
          ok = id == B_NUMEQ ? x == y : id == B_LT ? x < y : id == B_GT ? x > y : id == B_LE ? x <= y : x >= y;
        } else {
          const double x = a[i].number(), y = a[i + 1].number();
          ok = id == B_NUMEQ ? x == y : id == B_LT ? x < y : id == B_GT ? x > y : id == B_LE ? x <= y : x >= y;
        }
        if (!ok) return Value::nil();
      }
      return Value::t();
    }
    case B_MIN:
    case B_MAX: {
      arity(1, any);
      Value r = num(0);
      for (std::size_t i = 1; i < n; ++i)
        if (id == B_MIN ? real(i) < r.number() : real(i) > r.number()) r = a[i];
      return r;
    }
    case B_ABS:
      arity(1, 1);
      if (num(0).tag == Tag::integer && a[0].u.i != INT64_MIN) return Value::integer(a[0].u.i < 0 ? -a[0].u.i : a[0].u.i);
      return Value::real(std::fabs(real(0)));
    case B_SQRT: arity(1, 1); if (real(0) < 0) error(pos, "SQRT of a negative number"); return Value::real(std::sqrt(real(0)));
    case B_EXP: arity(1, 1); return Value::real(std::exp(real(0)));
    case B_LOG: arity(1, 2); if (real(0) <= 0) error(pos, "LOG of a number <= 0");
      return Value::real(n == 2 ? std::log(real(0)) / std::log(real(1)) : std::log(real(0)));
    case B_SIN: arity(1, 1); return Value::real(std::sin(real(0)));
    case B_COS: arity(1, 1); return Value::real(std::cos(real(0)));
    case B_TAN: arity(1, 1); return Value::real(std::tan(real(0)));
    case B_ATAN: arity(1, 2); return Value::real(n == 2 ? std::atan2(real(0), real(1)) : std::atan(real(0)));
    case B_EXPT: {
      arity(2, 2);
      if (num(0).tag == Tag::integer && num(1).tag == Tag::integer && a[1].u.i >= 0) {
        // Exponentiation by squaring: O(log e) steps, whatever the exponent.
        std::int64_t r = 1, b = a[0].u.i;
        bool over = false;
        for (std::int64_t e = a[1].u.i; e > 0 && !over; e >>= 1) {
          if (e & 1) over = __builtin_mul_overflow(r, b, &r);
          if ((e >> 1) > 0 && !over) over = __builtin_mul_overflow(b, b, &b);
        }
        if (!over) return Value::integer(r);
      }
      return Value::real(std::pow(real(0), real(1)));
    }
    case B_FLOOR:
    case B_ROUND: {
      arity(1, 2);
      double x = real(0);
      if (n == 2) {
        if (real(1) == 0.0) error(pos, "division by zero");
        x /= real(1);
      }
      if (n == 1 && a[0].tag == Tag::integer) return a[0];
      // ROUND rounds halves to even, as Common Lisp does.
      const double r = id == B_FLOOR ? std::floor(x) : std::nearbyint(x);
      if (!(std::fabs(r) < 9.2e18)) error(pos, fmt::format("{}: result out of range", builtin_names[id]));
      return Value::integer(static_cast<std::int64_t>(r));
    }
    case B_MOD: {
      arity(2, 2);
      if (num(0).tag == Tag::integer && num(1).tag == Tag::integer) {
        if (a[1].u.i == 0) error(pos, "division by zero");
        if (a[1].u.i == -1) return Value::integer(0);
        std::int64_t m = a[0].u.i % a[1].u.i;
        if (m != 0 && ((m < 0) != (a[1].u.i < 0))) m += a[1].u.i;
        return Value::integer(m);
      }
      if (real(1) == 0.0) error(pos, "division by zero");
      return Value::real(real(0) - real(1) * std::floor(real(0) / real(1)));
    }
    case B_RANDOM: {
      arity(1, 1);
      if (num(0).tag == Tag::integer) {
        if (a[0].u.i <= 0) error(pos, "RANDOM needs a positive limit");
        // Uniform on [0, n) by rejection (exact, unlike a bare modulo).
        const auto lim = static_cast<std::uint64_t>(a[0].u.i);
        const std::uint64_t cut = ~std::uint64_t{0} - (~std::uint64_t{0} % lim);
        std::uint64_t x;
        do x = rng_.next(); while (x >= cut);
        return Value::integer(static_cast<std::int64_t>(x % lim));
      }
      if (!(a[0].u.d > 0)) error(pos, "RANDOM needs a positive limit");
      return Value::real(rng_.uniform() * a[0].u.d);
    }
    case B_NOT:
    case B_NULL: arity(1, 1); return Value::boolean(a[0].is_nil());
    case B_EQ:
    case B_EQL: arity(2, 2); return Value::boolean(eql(a[0], a[1]));
    case B_EQUAL: arity(2, 2); return Value::boolean(equal(a[0], a[1]));
    case B_NUMBERP: arity(1, 1); return Value::boolean(a[0].is_number());
    case B_LIST: {
      Value l;
      for (std::size_t i = n; i > 0; --i) l = Value::cons(a[i - 1], l);
      return l;
    }
    case B_CONS: arity(2, 2); return Value::cons(a[0], a[1]);
    case B_CAR: arity(1, 1); list_arg(0); return a[0].tag == Tag::cons ? cons_of(a[0])->car : Value::nil();
    case B_CDR: arity(1, 1); list_arg(0); return a[0].tag == Tag::cons ? cons_of(a[0])->cdr : Value::nil();
    case B_CADR: {
      arity(1, 1);
      list_arg(0);
      if (a[0].tag != Tag::cons) return Value::nil();
      const Value& d = cons_of(a[0])->cdr;
      return d.tag == Tag::cons ? cons_of(d)->car : Value::nil();
    }
    case B_NTH: {
      arity(2, 2);
      if (num(0).tag != Tag::integer || a[0].u.i < 0) error(pos, "NTH needs a non-negative integer index");
      Value l = list_arg(1);
      for (std::int64_t i = 0; i < a[0].u.i && l.tag == Tag::cons; ++i) l = cons_of(l)->cdr;
      return l.tag == Tag::cons ? cons_of(l)->car : Value::nil();
    }
    case B_LENGTH: {
      arity(1, 1);
      if (a[0].tag == Tag::string) return Value::integer(static_cast<std::int64_t>(str_of(a[0]).size()));
      std::int64_t k = 0;
      for (Value l = list_arg(0); l.tag == Tag::cons; l = cons_of(l)->cdr) ++k;
      return Value::integer(k);
    }
    case B_APPEND: {
      if (n == 0) return Value::nil();
      Value r = a[n - 1];
      for (std::size_t i = n - 1; i > 0; --i) {
        std::vector<Value> items;
        for (Value l = list_arg(i - 1); l.tag == Tag::cons; l = cons_of(l)->cdr) items.push_back(cons_of(l)->car);
        for (auto it = items.rbegin(); it != items.rend(); ++it) r = Value::cons(*it, r);
      }
      return r;
    }
    case B_REVERSE: {
      arity(1, 1);
      Value r;
      for (Value l = list_arg(0); l.tag == Tag::cons; l = cons_of(l)->cdr) r = Value::cons(cons_of(l)->car, r);
      return r;
    }
    case B_MEMBER: {
      arity(2, 2);
      for (Value l = list_arg(1); l.tag == Tag::cons; l = cons_of(l)->cdr)
        if (eql(cons_of(l)->car, a[0])) return l;
      return Value::nil();
    }
    case B_ASSOC: {
      arity(2, 2);
      for (Value l = list_arg(1); l.tag == Tag::cons; l = cons_of(l)->cdr) {
        const Value& p = cons_of(l)->car;
        if (p.tag == Tag::cons && equal(cons_of(p)->car, a[0])) return p;
      }
      return Value::nil();
    }
    case B_FUNCALL: arity(1, any); return apply(a[0], a + 1, n - 1, pos);
    case B_APPLY: {
      arity(2, any);
      std::vector<Value> v(a + 1, a + n - 1);
      for (Value l = list_arg(n - 1); l.tag == Tag::cons; l = cons_of(l)->cdr) v.push_back(cons_of(l)->car);
      return apply(a[0], v.data(), v.size(), pos);
    }
    case B_FORMAT: {
      arity(2, any);
      if (a[1].tag != Tag::string) error(pos, "FORMAT needs a control string");
      std::string out;
      format_into(out, a + 1, n - 1, pos);
      if (a[0].is_nil()) return Value::string(out);
      if (a[0].tag != Tag::t) error(pos, "FORMAT destination must be T or NIL");
      Instance* who = self != nullptr ? self : current_;
      std::string& buf = who != nullptr ? who->print_buf : top_print_;
      buf += out;
      flush_print(who, false);
      return Value::nil();
    }
    case B_PRINT:
    case B_PRINC: {
      arity(1, 1);
      Instance* who = self != nullptr ? self : current_;
      std::string& buf = who != nullptr ? who->print_buf : top_print_;
      buf += print(a[0], id == B_PRINT);
      if (id == B_PRINT) buf += '\n';
      flush_print(who, false);
      return a[0];
    }
    case B_MOTION_TIME: arity(0, 0); return Value::real(time_of(cycle_));
    case B_MOTION_FIND: {
      arity(1, 1);
      if (a[0].tag != Tag::string && a[0].tag != Tag::symbol) error(pos, "MOTION-FIND needs a name");
      const std::string& nm = a[0].tag == Tag::string ? str_of(a[0]) : names_[static_cast<std::size_t>(a[0].u.sym)];
      for (auto& m : motions_)
        if (m->name == nm) return Value::motion(m.get());
      return Value::nil();
    }
    default: break;
  }
  error(pos, "unknown built-in");
}

void Machine::format_into(std::string& out, const Value* a, std::size_t n, SrcPos pos) {
  const std::string& f = str_of(a[0]);
  std::size_t arg = 1;
  auto next = [&]() -> const Value& {
    if (arg >= n) error(pos, "FORMAT: more directives than arguments");
    return a[arg++];
  };
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (f[i] != '~') {
      out += f[i];
      continue;
    }
    if (++i >= f.size()) error(pos, "FORMAT: '~' at the end of the control string");
    switch (std::toupper(static_cast<unsigned char>(f[i]))) {
      case 'A': out += print(next(), false); break;
      case 'S': out += print(next(), true); break;
      case 'D': {
        const Value& v = next();
        out += v.tag == Tag::integer ? std::to_string(v.u.i) : print(v, false);
        break;
      }
      case 'F': {
        const Value& v = next();
        if (!v.is_number()) error(pos, "FORMAT ~f needs a number");
        out += print(Value::real(v.number()), false);
        break;
      }
      case '%': out += '\n'; break;
      case '&': if (!out.empty() && out.back() != '\n') out += '\n'; break;
      case '~': out += '~'; break;
      default: error(pos, fmt::format("FORMAT: unsupported directive ~{}", f[i]));
    }
  }
}

std::string Machine::print(const Value& v, bool escape) const {
  thread_local int depth = 0;
  struct Guard {
    int& d;
    explicit Guard(int& x) : d(++x) {}
    ~Guard() { --d; }
  } guard(depth);
  if (depth > 1000) return "...";  // lists nested in their cars deeper than this
  switch (v.tag) {
    case Tag::nil: return "NIL";
    case Tag::t: return "T";
    case Tag::integer: return std::to_string(v.u.i);
    case Tag::real: {
      std::string s = fmt::format("{}", v.u.d);
      if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
      return s;
    }
    case Tag::string: {
      if (!escape) return str_of(v);
      std::string s = "\"";
      for (char c : str_of(v)) {
        if (c == '"' || c == '\\') s += '\\';
        s += c;
      }
      return s + "\"";
    }
    case Tag::symbol: return names_[static_cast<std::size_t>(v.u.sym)];
    case Tag::cons: {
      std::string s = "(";
      Value l = v;
      bool first = true;
      std::size_t count = 0;
      while (l.tag == Tag::cons) {
        if (!first) s += ' ';
        first = false;
        if (++count > 100000) return s + "...)";
        s += print(cons_of(l)->car, escape);
        l = cons_of(l)->cdr;
      }
      if (!l.is_nil()) s += " . " + print(l, escape);
      return s + ")";
    }
    case Tag::closure: return "#<closure>";
    case Tag::builtin: return fmt::format("#<builtin {}>", builtin_names[v.u.builtin]);
    case Tag::instance: return fmt::format("#<net {}>", v.u.inst->label);
    case Tag::netclass: return fmt::format("#<net-class {}>", v.u.cls->print_name);
    case Tag::semclass: return "#<class semaphore>";
    case Tag::semaphore: return fmt::format("#<semaphore {}>", v.u.sem->id);
    case Tag::motion: return fmt::format("#<motion {}>", v.u.motion->name);
  }
  return "?";
}

}  // namespace fest::patnet

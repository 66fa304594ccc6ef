// Loading PaT-Lisp: top-level forms, the compiler from data to expression trees, and
// defnet (docs/patnet.md "defnet grammar"): classes, their C3 precedence lists and the
// per-class resolution of actions, conditions and arc targets, with the static checks.

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include "core/error.hpp"
#include "patnet/machine.hpp"
#include "patnet/syms.hpp"

namespace fest::patnet {

const char* const builtin_names[B_COUNT] = {
    "+", "-", "*", "/", "1+", "1-", "=", "/=", "<", ">", "<=", ">=", "MIN", "MAX", "ABS", "SQRT", "EXPT", "EXP", "LOG",
    "SIN", "COS", "TAN", "ATAN", "FLOOR", "ROUND", "MOD", "RANDOM", "NOT", "NULL", "EQ", "EQL", "EQUAL", "LIST", "CONS",
    "CAR", "CDR", "CADR", "NTH", "LENGTH", "APPEND", "REVERSE", "MEMBER", "ASSOC", "FUNCALL", "APPLY", "FORMAT",
    "PRINT", "PRINC", "MOTION-TIME", "MOTION-FIND", "NUMBERP"};

std::string Diagnostic::text() const {
  if (pos.line == 0) return fmt::format("{} ({})", message, file);
  return fmt::format("{} ({}:{}:{})", message, file, pos.line, pos.col);
}

Machine::Machine(RunOptions opt, TraceSink* sink) : opt_(opt), sink_(sink), rng_(opt.seed), sy_(new Syms) {
  Syms& s = *sy_;
  s.quote = intern("QUOTE"); s.function = intern("FUNCTION"); s.lambda = intern("LAMBDA"); s.if_ = intern("IF");
  s.cond = intern("COND"); s.when = intern("WHEN"); s.unless = intern("UNLESS"); s.and_ = intern("AND");
  s.or_ = intern("OR"); s.progn = intern("PROGN"); s.let = intern("LET"); s.letstar = intern("LET*");
  s.setq = intern("SETQ"); s.setf = intern("SETF"); s.defun = intern("DEFUN"); s.dolist = intern("DOLIST");
  s.dotimes = intern("DOTIMES"); s.return_ = intern("RETURN"); s.val = intern("VAL"); s.var = intern("VAR");
  s.send = intern("SEND"); s.self = intern("SELF"); s.t = intern("T"); s.nil = intern("NIL");
  s.defnet = intern("DEFNET"); s.definit = intern("DEFINIT"); s.defaction = intern("DEFACTION");
  s.defcond = intern("DEFCOND"); s.defnode = intern("DEFNODE"); s.def_probnode = intern("DEF-PROBNODE");
  s.def_weightnode = intern("DEF-WEIGHTNODE"); s.def_randnode = intern("DEF-RANDNODE");
  s.defmonitor = intern("DEFMONITOR"); s.list = intern("LIST"); s.exit = intern("EXIT");
  s.k_noop = intern(":NO-OP"); s.k_default = intern(":DEFAULT"); s.k_locals = intern(":LOCALS");
  s.k_classvars = intern(":CLASS-VARS"); s.k_parents = intern(":PARENTS"); s.k_start = intern(":START");
  s.k_new = intern(":NEW"); s.k_exit = intern(":EXIT"); s.k_status = intern(":STATUS");
  s.k_add_dependent = intern(":ADD-DEPENDENT"); s.k_wait_fsm = intern(":WAIT-FSM"); s.k_wait_time = intern(":WAIT-TIME");
  s.k_wait_condition = intern(":WAIT-CONDITION"); s.k_wait_motion = intern(":WAIT-MOTION");
  s.k_wait_semaphore = intern(":WAIT-SEMAPHORE"); s.k_signal_semaphore = intern(":SIGNAL-SEMAPHORE");
  s.k_state = intern(":STATE"); s.k_priority = intern(":PRIORITY"); s.finished = intern("FINISHED");
  s.failed = intern("FAILED"); s.idle = intern("IDLE"); s.running = intern("RUNNING"); s.waiting = intern("WAITING");
  s.semaphore = intern("SEMAPHORE"); s.amp_optional = intern("&OPTIONAL"); s.amp_key = intern("&KEY");
  s.amp_rest = intern("&REST");
  for (int b = 0; b < B_COUNT; ++b) s.builtin_sym[b] = intern(builtin_names[b]);
  Value semclass;
  semclass.tag = Tag::semclass;
  globals_[static_cast<std::size_t>(s.semaphore)] = semclass;
  bound_[static_cast<std::size_t>(s.semaphore)] = 1;
}

Machine::~Machine() {
  // Values inside instances may hold closures over frames; clear in a safe order.
  for (auto& i : insts_) {
    i->locals.clear();
    i->waits.clear();
  }
  globals_.clear();
}

int Machine::intern(std::string_view upper_name) {
  auto it = symtab_.find(std::string(upper_name));
  if (it != symtab_.end()) return it->second;
  const int id = static_cast<int>(names_.size());
  names_.emplace_back(upper_name);
  symtab_.emplace(std::string(upper_name), id);
  globals_.emplace_back();
  bound_.push_back(0);
  user_fns_.push_back(nullptr);
  return id;
}

Value Machine::global(std::string_view name) const {
  auto it = symtab_.find(upcase(name));
  if (it == symtab_.end() || !bound_[static_cast<std::size_t>(it->second)]) return Value::nil();
  return globals_[static_cast<std::size_t>(it->second)];
}

bool Machine::has_errors() const {
  return std::any_of(diags_.begin(), diags_.end(), [](const Diagnostic& d) { return d.error; });
}

void Machine::add_diag(bool error, std::string msg, SrcPos pos) {
  Diagnostic d;
  d.error = error;
  d.message = std::move(msg);
  d.pos = pos;
  d.file = files_.empty() ? std::string("-") : files_[static_cast<std::size_t>(pos.file)];
  diags_.push_back(std::move(d));
}

namespace {
[[noreturn]] void cfail(SrcPos pos, std::string msg) { throw LispError{std::move(msg), pos}; }
}  // namespace

void Machine::load(std::string_view text, const std::string& file_name, bool execute) {
  const int file = static_cast<int>(files_.size());
  files_.push_back(file_name);
  std::vector<Datum> forms;
  try {
    forms = read_all(text, file);
  } catch (const ReadError& e) {
    add_diag(true, e.message, e.pos);
    if (execute) throw bad_input("{}", diags_.back().text());
    return;
  }
  std::vector<const Datum*> to_run;
  const std::size_t before = diags_.size();
  for (const Datum& d : forms) top_level(d, execute, to_run);
  if (!execute) return;
  for (std::size_t i = before; i < diags_.size(); ++i)
    if (diags_[i].error) throw bad_input("{}", diags_[i].text());
  for (const Datum* d : to_run) {
    Expr* e = compile(*d);
    try {
      steps_ = 0;
      depth_ = 0;
      current_ = nullptr;
      eval(e, nullptr, nullptr);
    } catch (const LispError& err) {
      throw bad_input("{} (while loading: {})", err.message, where(err.pos));
    }
  }
}

void Machine::top_level(const Datum& d, bool execute, std::vector<const Datum*>& to_run) {
  loop_depth_ = 0;
  try {
    if (d.is_list() && !d.items.empty() && d.items[0].kind == Datum::Kind::symbol) {
      const int head = intern(d.items[0].text);
      if (head == sy_->defnet) {
        define_net(d);
        return;
      }
      if (head == sy_->defun) {
        if (d.items.size() < 3 || d.items[1].kind != Datum::Kind::symbol) cfail(d.pos, "defun needs a name and a parameter list");
        const int name = intern(d.items[1].text);
        for (int b = 0; b < B_COUNT; ++b)
          if (sy_->builtin_sym[b] == name) cfail(d.items[1].pos, fmt::format("defun redefines the built-in function {}", d.items[1].text));
        auto fn = std::make_unique<Function>();
        fn->name = name;
        fn->pos = d.pos;
        Datum lambda;
        lambda.kind = Datum::Kind::list;
        lambda.pos = d.pos;
        // Compile as (lambda params body...) to share the lambda-list parser.
        Datum lam_head;
        lam_head.kind = Datum::Kind::symbol;
        lam_head.text = "LAMBDA";
        lam_head.pos = d.pos;
        lambda.items.push_back(lam_head);
        for (std::size_t i = 2; i < d.items.size(); ++i) lambda.items.push_back(d.items[i]);
        Expr* e = compile(lambda);
        *fn = *e->fn;
        fn->name = name;
        if (user_fns_[static_cast<std::size_t>(name)] != nullptr)
          add_diag(false, fmt::format("function {} is defined again; the later definition wins", d.items[1].text), d.pos);
        user_fns_[static_cast<std::size_t>(name)] = fn.get();
        funcs_.push_back(std::move(fn));
        return;
      }
    }
    compile(d);  // checks it; compiled again when it runs
    if (execute) to_run.push_back(&d);
  } catch (const LispError& e) {
    add_diag(true, e.message, e.pos);
  }
}

// ---- compiler ----------------------------------------------------------------------

namespace {

Expr* new_expr(std::vector<std::unique_ptr<Expr>>& store, Op op, SrcPos pos) {
  store.push_back(std::make_unique<Expr>());
  Expr* e = store.back().get();
  e->op = op;
  e->pos = pos;
  return e;
}

}  // namespace

Expr* Machine::compile(const Datum& d) {
  const Syms& s = *sy_;
  switch (d.kind) {
    case Datum::Kind::integer: {
      Expr* e = new_expr(exprs_, Op::constant, d.pos);
      e->k = Value::integer(d.i);
      return e;
    }
    case Datum::Kind::real: {
      Expr* e = new_expr(exprs_, Op::constant, d.pos);
      e->k = Value::real(d.d);
      return e;
    }
    case Datum::Kind::string: {
      Expr* e = new_expr(exprs_, Op::constant, d.pos);
      e->k = Value::string(d.text);
      return e;
    }
    case Datum::Kind::symbol: {
      const int sym = intern(d.text);
      if (sym == s.t) {
        Expr* e = new_expr(exprs_, Op::constant, d.pos);
        e->k = Value::t();
        return e;
      }
      if (sym == s.nil) return new_expr(exprs_, Op::constant, d.pos);
      if (d.text[0] == ':') {
        Expr* e = new_expr(exprs_, Op::constant, d.pos);
        e->k = Value::symbol(sym);
        return e;
      }
      if (sym == s.self) return new_expr(exprs_, Op::self, d.pos);
      Expr* e = new_expr(exprs_, Op::var, d.pos);
      e->sym = sym;
      return e;
    }
    case Datum::Kind::list:
      break;
  }
  if (d.items.empty()) return new_expr(exprs_, Op::constant, d.pos);
  const Datum& h = d.items[0];
  const std::size_t n = d.items.size();
  auto body = [&](std::size_t from, SrcPos pos) {
    Expr* e = new_expr(exprs_, Op::progn, pos);
    for (std::size_t i = from; i < n; ++i) e->kids.push_back(compile(d.items[i]));
    return e;
  };
  auto need = [&](bool ok, const char* what) {
    if (!ok) cfail(d.pos, fmt::format("malformed {}: {}", upcase(h.text), what));
  };
  if (h.kind == Datum::Kind::list) {
    // ((lambda (x) ...) args): funcall of the lambda.
    Expr* e = new_expr(exprs_, Op::call_builtin, d.pos);
    e->sym = B_FUNCALL;
    for (const Datum& a : d.items) e->kids.push_back(compile(a));
    return e;
  }
  if (h.kind != Datum::Kind::symbol) cfail(h.pos, "a list must start with a function name or a special form");
  const int head = intern(h.text);

  if (head == s.quote) {
    need(n == 2, "(quote x)");
    Expr* e = new_expr(exprs_, Op::constant, d.pos);
    // data -> value
    struct Q {
      Machine& m;
      Value operator()(const Datum& x) {
        switch (x.kind) {
          case Datum::Kind::integer: return Value::integer(x.i);
          case Datum::Kind::real: return Value::real(x.d);
          case Datum::Kind::string: return Value::string(x.text);
          case Datum::Kind::symbol: {
            const int sym = m.intern(x.text);
            if (sym == m.sy_->nil) return Value::nil();
            if (sym == m.sy_->t) return Value::t();
            return Value::symbol(sym);
          }
          case Datum::Kind::list: {
            Value r;
            for (auto it = x.items.rbegin(); it != x.items.rend(); ++it) r = Value::cons((*this)(*it), r);
            return r;
          }
        }
        return Value::nil();
      }
    };
    e->k = Q{*this}(d.items[1]);
    return e;
  }
  if (head == s.function) {
    need(n == 2, "(function name) or #'name");
    const Datum& f = d.items[1];
    if (f.is_list()) return compile(f);
    need(f.kind == Datum::Kind::symbol, "a function name");
    Expr* e = new_expr(exprs_, Op::funcref, d.pos);
    e->sym = intern(f.text);
    bool builtin = false;
    for (int b = 0; b < B_COUNT; ++b)
      if (s.builtin_sym[b] == e->sym) builtin = true;
    if (!builtin) calls_.emplace_back(e->sym, f.pos);
    return e;
  }
  if (head == s.lambda) {
    need(n >= 2 && d.items[1].is_list(), "(lambda (params) body...)");
    auto fn = std::make_unique<Function>();
    fn->pos = d.pos;
    fn->name = s.lambda;
    int mode = 0;  // 0 required, 1 optional, 2 key
    for (const Datum& p : d.items[1].items) {
      if (p.kind == Datum::Kind::symbol) {
        const int ps = intern(p.text);
        if (ps == s.amp_optional) { mode = 1; continue; }
        if (ps == s.amp_key) { mode = 2; continue; }
        if (ps == s.amp_rest) { mode = 3; continue; }
        if (p.text[0] == ':' || ps == s.t || ps == s.nil) cfail(p.pos, fmt::format("{} cannot be a parameter", p.text));
        if (mode == 0) fn->params.required.push_back(ps);
        else if (mode == 1) fn->params.optional.emplace_back(ps, nullptr);
        else if (mode == 2) fn->params.key.emplace_back(ps, nullptr);
        else fn->params.rest = ps;
      } else if (p.is_list() && p.items.size() >= 1 && p.items.size() <= 2 && p.items[0].kind == Datum::Kind::symbol &&
                 (mode == 1 || mode == 2)) {
        const int ps = intern(p.items[0].text);
        Expr* def = p.items.size() == 2 ? compile(p.items[1]) : nullptr;
        if (mode == 1) fn->params.optional.emplace_back(ps, def);
        else fn->params.key.emplace_back(ps, def);
      } else {
        cfail(p.pos, "malformed parameter list");
      }
    }
    {
      // RETURN leaves the innermost loop of its own function only
      const int saved = loop_depth_;
      loop_depth_ = 0;
      fn->body = body(2, d.pos);
      loop_depth_ = saved;
    }
    Expr* e = new_expr(exprs_, Op::lambda, d.pos);
    e->fn = fn.get();
    funcs_.push_back(std::move(fn));
    return e;
  }
  if (head == s.if_) {
    need(n == 3 || n == 4, "(if test then [else])");
    Expr* e = new_expr(exprs_, Op::if_, d.pos);
    e->kids = {compile(d.items[1]), compile(d.items[2]), n == 4 ? compile(d.items[3]) : new_expr(exprs_, Op::constant, d.pos)};
    return e;
  }
  if (head == s.when || head == s.unless) {
    need(n >= 2, "(when test body...)");
    Expr* e = new_expr(exprs_, Op::if_, d.pos);
    Expr* b = body(2, d.pos);
    Expr* none = new_expr(exprs_, Op::constant, d.pos);
    e->kids = {compile(d.items[1]), head == s.when ? b : none, head == s.when ? none : b};
    return e;
  }
  if (head == s.cond) {
    Expr* e = new_expr(exprs_, Op::cond, d.pos);
    for (std::size_t i = 1; i < n; ++i) {
      const Datum& c = d.items[i];
      if (!c.is_list() || c.items.empty()) cfail(c.pos, "a COND clause must be (test body...)");
      e->kids.push_back(compile(c.items[0]));
      if (c.items.size() == 1) {
        e->kids.push_back(nullptr);
      } else {
        Expr* b = new_expr(exprs_, Op::progn, c.pos);
        for (std::size_t j = 1; j < c.items.size(); ++j) b->kids.push_back(compile(c.items[j]));
        e->kids.push_back(b);
      }
    }
    return e;
  }
  if (head == s.and_ || head == s.or_ || head == s.progn) {
    Expr* e = body(1, d.pos);
    e->op = head == s.and_ ? Op::and_ : head == s.or_ ? Op::or_ : Op::progn;
    return e;
  }
  if (head == s.let || head == s.letstar) {
    need(n >= 2 && d.items[1].is_list(), "(let ((var init)...) body...)");
    Expr* e = new_expr(exprs_, head == s.let ? Op::let : Op::letstar, d.pos);
    for (const Datum& b : d.items[1].items) {
      if (b.kind == Datum::Kind::symbol) {
        e->syms.push_back(intern(b.text));
        e->kids.push_back(new_expr(exprs_, Op::constant, b.pos));
      } else if (b.is_list() && !b.items.empty() && b.items.size() <= 2 && b.items[0].kind == Datum::Kind::symbol) {
        e->syms.push_back(intern(b.items[0].text));
        e->kids.push_back(b.items.size() == 2 ? compile(b.items[1]) : new_expr(exprs_, Op::constant, b.pos));
      } else {
        cfail(b.pos, "a LET binding must be var or (var init)");
      }
    }
    e->kids.push_back(body(2, d.pos));
    return e;
  }
  if (head == s.setq || head == s.setf) {
    need(n >= 3 && n % 2 == 1, "(setf place value ...)");
    Expr* seq = new_expr(exprs_, Op::progn, d.pos);
    for (std::size_t i = 1; i + 1 < n; i += 2) {
      const Datum& place = d.items[i];
      if (place.kind == Datum::Kind::symbol && place.text[0] != ':' && intern(place.text) != s.t &&
          intern(place.text) != s.nil && intern(place.text) != s.self) {
        Expr* e = new_expr(exprs_, Op::setvar, place.pos);
        e->sym = intern(place.text);
        e->kids.push_back(compile(d.items[i + 1]));
        seq->kids.push_back(e);
      } else if (head == s.setf && place.is_list() && place.items.size() == 2 &&
                 (place.items[0].is_symbol("VAL") || place.items[0].is_symbol("VAR")) &&
                 place.items[1].kind == Datum::Kind::symbol) {
        Expr* e = new_expr(exprs_, Op::val_set, place.pos);
        e->sym = intern(place.items[1].text);
        e->kids.push_back(compile(d.items[i + 1]));
        seq->kids.push_back(e);
      } else {
        cfail(place.pos, "SETF places are variables and (val x)");
      }
    }
    return seq->kids.size() == 1 ? seq->kids[0] : seq;
  }
  if (head == s.val || head == s.var) {
    need((n == 2 || n == 3) && d.items[1].kind == Datum::Kind::symbol, "(val name [value])");
    Expr* e = new_expr(exprs_, n == 2 ? Op::val_get : Op::val_set, d.pos);
    e->sym = intern(d.items[1].text);
    if (n == 3) e->kids.push_back(compile(d.items[2]));
    return e;
  }
  if (head == s.send) {
    need(n >= 3 && d.items[2].kind == Datum::Kind::symbol && d.items[2].text[0] == ':', "(send object :message args...)");
    Expr* e = new_expr(exprs_, Op::send, d.pos);
    e->sym = intern(d.items[2].text);
    const Syms& y = s;
    const int m = e->sym;
    if (m != y.k_new && m != y.k_exit && m != y.k_status && m != y.k_add_dependent && m != y.k_wait_fsm &&
        m != y.k_wait_time && m != y.k_wait_condition && m != y.k_wait_motion && m != y.k_wait_semaphore &&
        m != y.k_signal_semaphore)
      cfail(d.items[2].pos, fmt::format("unknown message {}", d.items[2].text));
    e->kids.push_back(compile(d.items[1]));
    for (std::size_t i = 3; i < n; ++i) e->kids.push_back(compile(d.items[i]));
    return e;
  }
  if (head == s.dolist || head == s.dotimes) {
    need(n >= 2 && d.items[1].is_list() && d.items[1].items.size() >= 2 && d.items[1].items.size() <= 3 &&
             d.items[1].items[0].kind == Datum::Kind::symbol,
         "(dolist (var list [result]) body...)");
    Expr* e = new_expr(exprs_, head == s.dolist ? Op::dolist : Op::dotimes, d.pos);
    e->syms.push_back(intern(d.items[1].items[0].text));
    e->kids.push_back(compile(d.items[1].items[1]));
    e->kids.push_back(d.items[1].items.size() == 3 ? compile(d.items[1].items[2]) : new_expr(exprs_, Op::constant, d.pos));
    ++loop_depth_;
    try {
      e->kids.push_back(body(2, d.pos));
    } catch (...) {
      --loop_depth_;
      throw;
    }
    --loop_depth_;
    return e;
  }
  if (head == s.return_) {
    need(n <= 2, "(return [value])");
    if (loop_depth_ == 0) cfail(d.pos, "RETURN outside a DOLIST or DOTIMES body");
    Expr* e = new_expr(exprs_, Op::return_, d.pos);
    e->kids.push_back(n == 2 ? compile(d.items[1]) : new_expr(exprs_, Op::constant, d.pos));
    return e;
  }
  if (head == s.defnet || head == s.defun || head == s.definit || head == s.defaction || head == s.defcond ||
      head == s.defnode || head == s.def_probnode || head == s.def_weightnode || head == s.def_randnode ||
      head == s.defmonitor)
    cfail(d.pos, fmt::format("{} is allowed only at {}", h.text,
                             head == s.defnet || head == s.defun ? "top level" : "the top of a DEFNET"));
  if (h.text[0] == ':') cfail(h.pos, fmt::format("{} is a keyword, not a function", h.text));
  for (int b = 0; b < B_COUNT; ++b) {
    if (s.builtin_sym[b] == head) {
      Expr* e = new_expr(exprs_, Op::call_builtin, d.pos);
      e->sym = b;
      for (std::size_t i = 1; i < n; ++i) e->kids.push_back(compile(d.items[i]));
      return e;
    }
  }
  Expr* e = new_expr(exprs_, Op::call_user, d.pos);
  e->sym = head;
  calls_.emplace_back(head, h.pos);
  for (std::size_t i = 1; i < n; ++i) e->kids.push_back(compile(d.items[i]));
  return e;
}

// ---- defnet ------------------------------------------------------------------------

namespace {

// C3 linearization of a class's parents (Barrett et al. 1996), as Dylan and Python use.
bool c3(NetClass* c, std::vector<NetClass*>& out) {
  std::vector<std::vector<NetClass*>> seqs;
  for (NetClass* p : c->parents) seqs.push_back(p->cpl);
  seqs.push_back(c->parents);
  out = {c};
  for (;;) {
    seqs.erase(std::remove_if(seqs.begin(), seqs.end(), [](const auto& s) { return s.empty(); }), seqs.end());
    if (seqs.empty()) return true;
    NetClass* pick = nullptr;
    for (const auto& s : seqs) {
      NetClass* cand = s.front();
      bool in_tail = false;
      for (const auto& t : seqs)
        if (std::find(t.begin() + 1, t.end(), cand) != t.end()) in_tail = true;
      if (!in_tail) {
        pick = cand;
        break;
      }
    }
    if (pick == nullptr) return false;
    out.push_back(pick);
    for (auto& s : seqs)
      if (!s.empty() && s.front() == pick) s.erase(s.begin());
  }
}

}  // namespace

void Machine::define_net(const Datum& d) {
  const Syms& s = *sy_;
  if (d.items.size() < 2 || d.items[1].kind != Datum::Kind::symbol) cfail(d.pos, "DEFNET needs a class name");
  const int name = intern(d.items[1].text);
  for (NetClass* c : class_order_)
    if (c->name == name) cfail(d.items[1].pos, fmt::format("net class {} is defined twice", d.items[1].text));
  auto owned = std::make_unique<NetClass>();
  NetClass& c = *owned;
  c.name = name;
  c.pos = d.pos;
  c.print_name = d.items[1].text;
  for (char& ch : c.print_name) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));

  auto symbol_list = [&](const Datum& v, const char* what) {
    // '(a b), (list a b), (a b) or a single symbol
    const Datum* l = &v;
    if (v.is_list() && v.items.size() == 2 && v.items[0].is_symbol("QUOTE")) l = &v.items[1];
    std::vector<std::pair<int, SrcPos>> r;
    if (l->kind == Datum::Kind::symbol) {
      if (intern(l->text) != s.nil) r.emplace_back(intern(l->text), l->pos);
      return r;
    }
    if (!l->is_list()) cfail(v.pos, fmt::format("{} must be a list of names", what));
    std::size_t from = 0;
    if (!l->items.empty() && l->items[0].is_symbol("LIST")) from = 1;
    for (std::size_t i = from; i < l->items.size(); ++i) {
      const Datum& x = l->items[i];
      if (x.kind == Datum::Kind::symbol) r.emplace_back(intern(x.text), x.pos);
      else if (x.is_list() && !x.items.empty() && x.items[0].kind == Datum::Kind::symbol)  // (name init)
        r.emplace_back(intern(x.items[0].text), x.items[0].pos);
      else cfail(x.pos, fmt::format("{} must be a list of names", what));
    }
    return r;
  };

  std::size_t i = 2;
  std::vector<const Datum*> classvar_inits;
  while (i < d.items.size() && d.items[i].kind == Datum::Kind::symbol && d.items[i].text[0] == ':') {
    const Datum& key = d.items[i];
    if (i + 1 >= d.items.size()) cfail(key.pos, fmt::format("{} needs a value", key.text));
    const Datum& v = d.items[i + 1];
    const int k = intern(key.text);
    if (k == s.k_locals) {
      for (auto& [sym, pos] : symbol_list(v, ":locals")) c.own_locals.push_back(sym);
    } else if (k == s.k_classvars) {
      for (auto& [sym, pos] : symbol_list(v, ":class-vars")) c.own_classvars.push_back(sym);
    } else if (k == s.k_parents) {
      for (auto& [sym, pos] : symbol_list(v, ":parents")) {
        NetClass* p = nullptr;
        for (NetClass* q : class_order_)
          if (q->name == sym) p = q;
        if (p == nullptr) cfail(pos, fmt::format("parent {} is not a net class defined before {}", names_[sym], d.items[1].text));
        c.parents.push_back(p);
      }
    } else if (k == s.k_start) {
      if (v.kind != Datum::Kind::symbol) cfail(v.pos, ":start needs a node name");
      c.start_sym = intern(v.text);
      c.start_pos = v.pos;
    } else {
      cfail(key.pos, fmt::format("unknown DEFNET option {} (known: :locals :class-vars :parents :start)", key.text));
    }
    i += 2;
  }
  c.classvar_values.assign(c.own_classvars.size(), Value::nil());

  auto named_code = [&](const Datum& f, const char* kind, std::map<int, Function*>& into) {
    if (f.items.size() < 2 || f.items[1].kind != Datum::Kind::symbol) cfail(f.pos, fmt::format("{} needs a name", kind));
    const Datum& nm = f.items[1];
    if (nm.text[0] != ':') {
      add_diag(true, fmt::format("{} name {} must start with ':'", kind, nm.text), nm.pos);
      return;
    }
    auto fn = std::make_unique<Function>();
    fn->name = intern(nm.text);
    fn->pos = f.pos;
    fn->body = new_expr(exprs_, Op::progn, f.pos);
    for (std::size_t j = 2; j < f.items.size(); ++j) fn->body->kids.push_back(compile(f.items[j]));
    if (into.count(fn->name)) add_diag(true, fmt::format("{} {} is defined twice in {}", kind, nm.text, d.items[1].text), nm.pos);
    into[fn->name] = fn.get();
    funcs_.push_back(std::move(fn));
  };
  auto keyword_or_diag = [&](const Datum& x, const char* kind) -> int {
    if (x.kind != Datum::Kind::symbol) cfail(x.pos, fmt::format("{} must be a name", kind));
    if (x.text[0] != ':') {
      add_diag(true, fmt::format("{} name {} must start with ':'", kind, x.text), x.pos);
      return -1;
    }
    return intern(x.text);
  };

  for (; i < d.items.size(); ++i) {
    const Datum& f = d.items[i];
    try {
      if (!f.is_list() || f.items.empty() || f.items[0].kind != Datum::Kind::symbol)
        cfail(f.pos, "DEFNET body forms are (definit ...), (defaction ...), (defcond ...), (defnode ...), "
                     "(def-probnode ...), (def-weightnode ...), (def-randnode ...), (defmonitor ...)");
      const int h = intern(f.items[0].text);
      if (h == s.definit) {
        if (f.items.size() < 2 || !f.items[1].is_list()) cfail(f.pos, "DEFINIT needs a parameter list");
        if (c.init != nullptr) add_diag(true, "DEFINIT appears twice", f.pos);
        Datum lam = f;
        lam.items[0].text = "LAMBDA";
        Expr* e = compile(lam);
        c.init = const_cast<Function*>(e->fn);
      } else if (h == s.defaction) {
        named_code(f, "action", c.actions);
      } else if (h == s.defcond) {
        named_code(f, "condition", c.conds);
      } else if (h == s.defnode || h == s.def_probnode || h == s.def_weightnode || h == s.def_randnode) {
        if (f.items.size() < 3 || f.items[1].kind != Datum::Kind::symbol)
          cfail(f.pos, fmt::format("{} needs a node name and an action", f.items[0].text));
        NodeDef node;
        node.name = intern(f.items[1].text);
        node.pos = f.items[1].pos;
        node.kind = h == s.defnode ? NodeKind::plain : h == s.def_probnode ? NodeKind::prob
                  : h == s.def_weightnode ? NodeKind::weight : NodeKind::rand;
        if (node.name == s.exit) cfail(node.pos, "EXIT is the exit state and cannot be a node name");
        node.action_pos = f.items[2].pos;
        const int act = keyword_or_diag(f.items[2], "action");
        node.action = act == s.k_noop ? -1 : act;
        if (act == -1) node.action = -2;  // already reported
        for (std::size_t j = 3; j < f.items.size(); ++j) {
          const Datum& a = f.items[j];
          Arc arc;
          arc.pos = a.pos;
          if (node.kind == NodeKind::rand) {
            if (a.kind != Datum::Kind::symbol) cfail(a.pos, "DEF-RANDNODE arcs are target names");
            arc.target = intern(a.text);
          } else {
            if (!a.is_list() || a.items.size() != 2 || a.items[1].kind != Datum::Kind::symbol)
              cfail(a.pos, node.kind == NodeKind::plain ? "an arc is (:condition target)" : "an arc is (number target)");
            arc.target = intern(a.items[1].text);
            if (node.kind == NodeKind::plain) {
              const int cs = keyword_or_diag(a.items[0], "condition");
              arc.cond = cs;
              arc.is_default = cs == s.k_default;
            } else {
              const Datum& p = a.items[0];
              if (p.kind != Datum::Kind::integer && p.kind != Datum::Kind::real)
                cfail(p.pos, "a probability or weight must be a number");
              arc.prob = p.kind == Datum::Kind::integer ? static_cast<double>(p.i) : p.d;
              if (node.kind == NodeKind::prob && (arc.prob < 0.0 || arc.prob > 1.0))
                add_diag(true, fmt::format("probability {} is outside [0, 1]", arc.prob), p.pos);
              if (node.kind == NodeKind::weight && arc.prob < 0.0)
                add_diag(true, fmt::format("weight {} is negative", arc.prob), p.pos);
            }
          }
          node.arcs.push_back(arc);
        }
        if (node.kind == NodeKind::prob) {
          double sum = 0;
          for (const Arc& a : node.arcs) sum += a.prob;
          if (sum > 1.0 + 1e-9) add_diag(true, fmt::format("probabilities of node {} sum to {} > 1", f.items[1].text, sum), node.pos);
        } else if (node.kind == NodeKind::weight) {
          double sum = 0;
          for (const Arc& a : node.arcs) sum += std::max(0.0, a.prob);
          if (!(sum > 0.0)) add_diag(true, fmt::format("weights of node {} sum to 0", f.items[1].text), node.pos);
          else for (Arc& a : node.arcs) a.prob /= sum;
        } else if (node.kind == NodeKind::rand) {
          if (node.arcs.empty()) cfail(f.pos, "DEF-RANDNODE needs at least one target");
          for (Arc& a : node.arcs) a.prob = 1.0 / static_cast<double>(node.arcs.size());
        }
        for (const NodeDef& o : c.own_nodes)
          if (o.name == node.name) add_diag(true, fmt::format("node {} is defined twice in {}", f.items[1].text, d.items[1].text), node.pos);
        c.own_nodes.push_back(std::move(node));
      } else if (h == s.defmonitor) {
        if (f.items.size() != 4 || f.items[1].kind != Datum::Kind::symbol)
          cfail(f.pos, "DEFMONITOR is (defmonitor name :condition :action)");
        MonitorDef m;
        m.name = intern(f.items[1].text);
        m.pos = f.pos;
        m.cond = keyword_or_diag(f.items[2], "condition");
        m.action = keyword_or_diag(f.items[3], "action");
        c.own_monitors.push_back(m);
      } else {
        cfail(f.items[0].pos, fmt::format("unknown DEFNET form {}", f.items[0].text));
      }
    } catch (const LispError& e) {
      add_diag(true, e.message, e.pos);
    }
  }
  if (!c3(&c, c.cpl)) cfail(d.pos, fmt::format("the parents of {} have no consistent precedence order (C3)", d.items[1].text));
  NetClass* cp = owned.get();
  class_store_.push_back(std::move(owned));
  class_order_.push_back(cp);
  globals_[static_cast<std::size_t>(name)] = Value::netclass(cp);
  bound_[static_cast<std::size_t>(name)] = 1;
  finalize_class(*cp);
}

const Function* NetClass::find_action(int n) const {
  for (const NetClass* k : cpl) {
    auto it = k->actions.find(n);
    if (it != k->actions.end()) return it->second;
  }
  return nullptr;
}
const Function* NetClass::find_cond(int n) const {
  for (const NetClass* k : cpl) {
    auto it = k->conds.find(n);
    if (it != k->conds.end()) return it->second;
  }
  return nullptr;
}
Value* NetClass::find_classvar(int n) {
  for (NetClass* k : cpl)
    for (std::size_t j = 0; j < k->own_classvars.size(); ++j)
      if (k->own_classvars[j] == n) return &k->classvar_values[j];
  return nullptr;
}

void Machine::finalize_class(NetClass& c) {
  const Syms& s = *sy_;
  // Locals: union over the precedence list, most general first.
  for (auto it = c.cpl.rbegin(); it != c.cpl.rend(); ++it)
    for (int l : (*it)->own_locals)
      if (!c.local_slot.count(l)) {
        c.local_slot.emplace(l, static_cast<int>(c.local_names.size()));
        c.local_names.push_back(l);
      }
  // Overrides (warnings): own names that a parent defines too.
  for (std::size_t k = 1; k < c.cpl.size(); ++k) {
    const NetClass* p = c.cpl[k];
    for (auto& [n, fn] : c.actions)
      if (p->actions.count(n)) add_diag(false, fmt::format("action {} overrides the one of {}", names_[n], p->print_name), fn->pos);
    for (auto& [n, fn] : c.conds)
      if (p->conds.count(n)) add_diag(false, fmt::format("condition {} overrides the one of {}", names_[n], p->print_name), fn->pos);
    for (const NodeDef& nd : c.own_nodes)
      for (const NodeDef& pn : p->own_nodes)
        if (pn.name == nd.name) add_diag(false, fmt::format("node {} overrides the one of {}", names_[nd.name], p->print_name), nd.pos);
  }
  // Nodes: most general first, overridden by more specific classes.
  for (auto it = c.cpl.rbegin(); it != c.cpl.rend(); ++it)
    for (const NodeDef& nd : (*it)->own_nodes) {
      NodeDef copy = nd;
      copy.owner = *it;
      c.nodes[nd.name] = copy;
    }
  {
    int k = 0;
    for (auto& [nname, nd] : c.nodes) nd.index = k++;
  }
  for (auto& [nname, nd] : c.nodes) {
    const bool own = nd.owner == &c;  // report problems once, in the class that wrote them
    if (nd.action >= 0) {
      nd.action_fn = c.find_action(nd.action);
      if (nd.action_fn == nullptr && own)
        add_diag(true, fmt::format("node {} uses undefined action {}", names_[nname], names_[nd.action]), nd.action_pos);
    }
    for (Arc& a : nd.arcs) {
      if (nd.kind == NodeKind::plain && !a.is_default && a.cond >= 0) {
        a.cond_fn = c.find_cond(a.cond);
        if (a.cond_fn == nullptr && own)
          add_diag(true, fmt::format("node {} uses undefined condition {}", names_[nname], names_[a.cond]), a.pos);
      }
      if (a.target == s.exit) {
        a.to = nullptr;
      } else {
        auto t = c.nodes.find(a.target);
        if (t == c.nodes.end()) {
          if (own) add_diag(true, fmt::format("node {} has an arc to undefined node {}", names_[nname], names_[a.target]), a.pos);
        } else {
          a.to = &t->second;
        }
      }
    }
  }
  // Start node.
  if (c.start_sym >= 0) {
    auto t = c.nodes.find(c.start_sym);
    if (t == c.nodes.end()) add_diag(true, fmt::format(":start names undefined node {}", names_[c.start_sym]), c.start_pos);
    else c.start = &t->second;
  } else if (!c.own_nodes.empty()) {
    c.start = &c.nodes[c.own_nodes.front().name];
  } else {
    for (std::size_t k = 1; k < c.cpl.size() && c.start == nullptr; ++k) {
      const NetClass* p = c.cpl[k];
      if (p->start != nullptr) c.start = &c.nodes[p->start->name];
    }
  }
  // Monitors: parents' first, each in definition order.
  for (auto it = c.cpl.rbegin(); it != c.cpl.rend(); ++it)
    for (MonitorDef m : (*it)->own_monitors) {
      if (m.cond >= 0) {
        m.cond_fn = c.find_cond(m.cond);
        if (m.cond_fn == nullptr && m.cond != s.k_default && *it == &c)
          add_diag(true, fmt::format("monitor {} uses undefined condition {}", names_[m.name], names_[m.cond]), m.pos);
      }
      if (m.action >= 0 && m.action != s.k_noop) {
        m.action_fn = c.find_action(m.action);
        if (m.action_fn == nullptr && *it == &c)
          add_diag(true, fmt::format("monitor {} uses undefined action {}", names_[m.name], names_[m.action]), m.pos);
      }
      c.monitors.push_back(m);
    }
  for (const NetClass* k : c.cpl)
    if (k->init != nullptr) {
      c.initializer = k->init;
      break;
    }
  // Loops that can never end (warnings): following nodes whose action is :no-op and whose
  // first arc is :default leads back to where it started, so nothing in the loop can wait,
  // exit or test anything. The net then spins until --max-cycles (unless a monitor acts).
  if (c.monitors.empty()) {
    auto forced = [&](const NodeDef* nd) -> const NodeDef* {
      if (nd->kind != NodeKind::plain || nd->action >= 0 || nd->action == -2 || nd->arcs.empty() || !nd->arcs[0].is_default)
        return nullptr;
      return nd->arcs[0].to;
    };
    std::set<int> reported;
    for (const NodeDef& own : c.own_nodes) {
      const NodeDef* start = &c.nodes.at(own.name);
      const NodeDef* nd = start;
      std::string path = names_[start->name];
      for (std::size_t k = 0; k <= c.nodes.size(); ++k) {
        nd = forced(nd);
        if (nd == nullptr) break;
        path += " -> " + names_[nd->name];
        if (nd == start) {
          if (!reported.count(start->name)) {
            add_diag(false, fmt::format("the loop {} never ends: :no-op actions and :default arcs only", path), own.pos);
            const NodeDef* x = start;
            do {
              reported.insert(x->name);
              x = forced(x);
            } while (x != start);
          }
          break;
        }
      }
    }
  }
  // Unreachable own nodes (warnings), from the start node along all arcs.
  if (c.start != nullptr) {
    std::set<int> seen{c.start->name};
    std::vector<const NodeDef*> todo{c.start};
    while (!todo.empty()) {
      const NodeDef* nd = todo.back();
      todo.pop_back();
      for (const Arc& a : nd->arcs)
        if (a.to != nullptr && seen.insert(a.to->name).second) todo.push_back(a.to);
    }
    for (const NodeDef& nd : c.own_nodes)
      if (!seen.count(nd.name))
        add_diag(false, fmt::format("node {} of {} is unreachable from its start node {}", names_[nd.name], c.print_name,
                                    names_[c.start->name]), nd.pos);
  }
}

void Machine::finish_checks() {
  std::set<std::pair<int, std::pair<int, int>>> reported;
  for (auto& [sym, pos] : calls_)
    if (user_fns_[static_cast<std::size_t>(sym)] == nullptr && reported.insert({sym, {pos.line, pos.col}}).second)
      add_diag(true, fmt::format("undefined function {}", names_[sym]), pos);
  // In source order, whatever order the checks ran in.
  std::stable_sort(diags_.begin(), diags_.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return std::tie(a.pos.file, a.pos.line, a.pos.col) < std::tie(b.pos.file, b.pos.line, b.pos.col);
  });
}

}  // namespace fest::patnet

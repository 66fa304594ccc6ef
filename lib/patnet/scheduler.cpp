// The net operating system (docs/patnet.md "Scheduler"): messages to nets and
// semaphores, instance creation, waits, and the fixed cycle that time-slices every
// instance in creation order.

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "patnet/machine.hpp"
#include "patnet/syms.hpp"

namespace fest::patnet {

const char* status_name(Status s) {
  switch (s) {
    case Status::idle: return "idle";
    case Status::running: return "running";
    case Status::waiting: return "waiting";
    case Status::finished: return "finished";
    case Status::failed: return "failed";
  }
  return "?";
}

const char* wait_kind_name(Wait::Kind k) {
  switch (k) {
    case Wait::Kind::fsm: return "fsm";
    case Wait::Kind::state: return "state";
    case Wait::Kind::time: return "time";
    case Wait::Kind::condition: return "condition";
    case Wait::Kind::motion: return "motion";
    case Wait::Kind::semaphore: return "semaphore";
  }
  return "?";
}

namespace {
bool done(const Instance& i) { return i.status == Status::finished || i.status == Status::failed; }
// Motion time is t0 + k dt in floating point; a wait for time T is met once t_k is within
// this much of T, so that "now + 3.0 s" at 30 fps is exactly 90 cycles (docs/patnet.md).
constexpr double time_slack = 1e-9;
}  // namespace

Event Machine::make_event(Event::Kind k, const Instance* inst) const {
  Event e;
  e.kind = k;
  e.inst = inst;
  return e;
}

void Machine::emit_event(Event& e) {
  e.cycle = cycle_;
  e.t = time_of(cycle_);
  if (sink_ != nullptr) sink_->event(e);
}

void Machine::flush_print(Instance* inst, bool all) {
  std::string& buf = inst != nullptr ? inst->print_buf : top_print_;
  std::size_t start = 0;
  for (;;) {
    const std::size_t nl = buf.find('\n', start);
    if (nl == std::string::npos) break;
    Event e = make_event(Event::Kind::print, inst);
    e.text = buf.substr(start, nl - start);
    emit_event(e);
    start = nl + 1;
  }
  buf.erase(0, start);
  if (all && !buf.empty()) {
    Event e = make_event(Event::Kind::print, inst);
    e.text = buf;
    emit_event(e);
    buf.clear();
  }
}

Instance* Machine::create_instance(NetClass* cls, const Value* args, std::size_t n, SrcPos pos) {
  if (cls->start == nullptr) error(pos, fmt::format("net class {} has no nodes to start in", cls->print_name));
  if (static_cast<std::int64_t>(insts_.size()) >= opt_.max_nets)
    throw LimitError{fmt::format("more than {} net instances ({})", opt_.max_nets, where(pos))};
  auto owned = std::make_unique<Instance>();
  Instance* inst = owned.get();
  inst->id = static_cast<int>(insts_.size()) + 1;
  inst->cls = cls;
  inst->locals.assign(cls->local_names.size(), Value::nil());
  inst->entered.assign(cls->nodes.size(), -1);
  inst->created = cycle_;
  inst->label = cls->print_name + "#" + std::to_string(inst->id);
  insts_.push_back(std::move(owned));
  Event e = make_event(Event::Kind::create, inst);
  e.cls = cls->print_name;
  for (std::size_t i = 0; i < n; ++i) e.args.push_back(print(args[i], true));
  emit_event(e);
  if (cls->initializer != nullptr) {
    call_function(cls->initializer, inst, nullptr, args, n, pos);
  } else if (n > 0) {
    error(pos, fmt::format("net class {} has no DEFINIT but was given {} arguments", cls->print_name, n));
  }
  return inst;
}

Value Machine::send(Instance* self, const Value& obj, int msg, const Value* a, std::size_t n, SrcPos pos) {
  (void)self;  // waits attach to the receiver, which the seed always writes as self
  const Syms& s = *sy_;
  const std::string& mname = names_[static_cast<std::size_t>(msg)];
  if (obj.tag == Tag::netclass) {
    if (msg != s.k_new) error(pos, fmt::format("a net class understands :new, not {}", mname));
    return Value::instance(create_instance(obj.u.cls, a, n, pos));
  }
  if (obj.tag == Tag::semclass) {
    if (msg != s.k_new) error(pos, fmt::format("SEMAPHORE understands :new, not {}", mname));
    if (n > 1 || (n == 1 && (a[0].tag != Tag::integer || a[0].u.i < 0)))
      error(pos, "(send semaphore :new [count]) needs a non-negative integer count");
    auto sem = std::make_unique<Semaphore>();
    sem->id = static_cast<int>(sems_.size()) + 1;
    sem->count = n == 1 ? a[0].u.i : 1;
    sems_.push_back(std::move(sem));
    return Value::semaphore(sems_.back().get());
  }
  if (obj.tag != Tag::instance) error(pos, fmt::format("{} sent to {}, which is not a net instance", mname, print(obj, true)));
  Instance& to = *obj.u.inst;
  auto arg_count = [&](std::size_t lo, std::size_t hi) {
    if (n < lo || n > hi) error(pos, fmt::format("{} takes {} to {} arguments, got {}", mname, lo, hi, n));
  };
  if (msg == s.k_exit) {
    arg_count(0, 1);
    Status st = Status::finished;
    if (n == 1 && !a[0].is_nil()) {
      if (a[0].tag == Tag::symbol && a[0].u.sym == s.failed) st = Status::failed;
      else if (!(a[0].tag == Tag::symbol && a[0].u.sym == s.finished))
        error(pos, fmt::format(":exit code must be 'finished or 'failed, not {}", print(a[0], true)));
    }
    finish(to, st, nullptr);
    return Value::nil();
  }
  if (msg == s.k_status) {
    arg_count(0, 0);
    const Status st = to.status;
    return Value::symbol(st == Status::idle ? s.idle : st == Status::running ? s.running : st == Status::waiting ? s.waiting
                         : st == Status::finished ? s.finished : s.failed);
  }
  if (msg == s.k_add_dependent) {
    arg_count(1, 1);
    if (a[0].tag != Tag::instance) error(pos, ":add-dependent needs a net instance");
    to.dependents.push_back(a[0].u.inst);
    if (done(to)) finish(*a[0].u.inst, Status::failed, &to);
    return Value::nil();
  }
  if (msg == s.k_signal_semaphore) {
    arg_count(1, 1);
    if (a[0].tag != Tag::semaphore) error(pos, ":signal-semaphore needs a semaphore");
    ++a[0].u.sem->count;
    return Value::nil();
  }
  Wait w;
  w.posted = cycle_;
  if (msg == s.k_wait_fsm) {
    if (n != 1 && n != 3) error(pos, ":wait-fsm takes an instance and optionally :state node");
    if (a[0].tag == Tag::netclass) error(pos, ":wait-fsm needs a net instance, not the net class");
    if (a[0].tag != Tag::instance) error(pos, fmt::format(":wait-fsm needs a net instance, not {}", print(a[0], true)));
    w.inst = a[0].u.inst;
    w.kind = Wait::Kind::fsm;
    if (n == 3) {
      if (!(a[1].tag == Tag::symbol && a[1].u.sym == s.k_state) || a[2].tag != Tag::symbol)
        error(pos, ":wait-fsm options are :state node-name");
      w.kind = Wait::Kind::state;
      w.state = a[2].u.sym;
      auto node = w.inst->cls->nodes.find(w.state);
      if (node == w.inst->cls->nodes.end())
        error(pos, fmt::format("{} has no node {}", w.inst->cls->print_name, names_[static_cast<std::size_t>(w.state)]));
      w.state_index = node->second.index;
      if (done(*w.inst)) {  // it can never pass through the node now
        finish(to, Status::failed, w.inst);
        return Value::nil();
      }
      w.inst->state_waiters.push_back(&to);
    }
  } else if (msg == s.k_wait_time) {
    arg_count(1, 1);
    if (!a[0].is_number()) error(pos, ":wait-time needs a time in seconds");
    w.kind = Wait::Kind::time;
    w.time = a[0].number();
  } else if (msg == s.k_wait_condition) {
    arg_count(1, 1);
    if (a[0].tag != Tag::closure && a[0].tag != Tag::builtin) error(pos, ":wait-condition needs a function of no arguments");
    w.kind = Wait::Kind::condition;
    w.closure = a[0];
  } else if (msg == s.k_wait_motion) {
    arg_count(1, 1);
    if (a[0].tag != Tag::motion) error(pos, fmt::format(":wait-motion needs a motion (from motion-find), not {}", print(a[0], true)));
    w.kind = Wait::Kind::motion;
    w.motion = a[0].u.motion;
  } else if (msg == s.k_wait_semaphore) {
    if (n != 1 && n != 3) error(pos, ":wait-semaphore takes a semaphore and optionally :priority p");
    if (a[0].tag != Tag::semaphore) error(pos, ":wait-semaphore needs a semaphore");
    double prio = 1.0;
    if (n == 3) {
      if (!(a[1].tag == Tag::symbol && a[1].u.sym == s.k_priority) || !a[2].is_number())
        error(pos, ":wait-semaphore options are :priority number");
      prio = a[2].number();
    }
    w.kind = Wait::Kind::semaphore;
    w.sem = a[0].u.sem;
    Semaphore::Entry en{prio, sem_seq_++, &to};
    auto& q = w.sem->queue;
    auto at = std::find_if(q.begin(), q.end(), [&](const Semaphore::Entry& x) { return x.priority < prio; });
    q.insert(at, en);
  } else {
    error(pos, fmt::format("{} is not understood by a net instance", mname));
  }
  if (!done(to)) to.waits.push_back(std::move(w));
  else if (w.kind == Wait::Kind::semaphore) leave_queues(to);
  return Value::nil();
}

void Machine::leave_queues(Instance& inst) {
  for (auto& sem : sems_) {
    auto& q = sem->queue;
    q.erase(std::remove_if(q.begin(), q.end(), [&](const Semaphore::Entry& e) { return e.inst == &inst; }), q.end());
  }
}

void Machine::finish(Instance& inst, Status st, const Instance* killer) {
  if (done(inst)) return;
  flush_print(&inst, true);
  inst.status = st;
  if (inst.waits.size() > 0) {
    bool sem = false;
    for (const Wait& w : inst.waits) sem |= w.kind == Wait::Kind::semaphore;
    if (sem) leave_queues(inst);
    inst.waits.clear();
  }
  Event e = make_event(killer != nullptr ? Event::Kind::kill : Event::Kind::exit, &inst);
  e.text = status_name(st);
  e.by = killer;
  if (opt_.dump_locals)
    for (std::size_t i = 0; i < inst.locals.size(); ++i)
      e.args.push_back(names_[static_cast<std::size_t>(inst.cls->local_names[i])] + "=" + print(inst.locals[i], true));
  emit_event(e);
  // The exiting net kills its dependents and the nets waiting for it to pass a node
  // (seed App. A 3D1).
  for (Instance* d : inst.dependents) finish(*d, Status::failed, &inst);
  for (Instance* w : inst.state_waiters) {
    if (done(*w)) continue;
    bool pending = false;
    for (const Wait& x : w->waits)
      if (x.kind == Wait::Kind::state && x.inst == &inst) {
        if (inst.entered[static_cast<std::size_t>(x.state_index)] < x.posted) pending = true;
      }
    if (pending) finish(*w, Status::failed, &inst);
  }
}

bool Machine::try_acquire(Instance& inst) {
  for (const Wait& w : inst.waits) {
    if (w.kind != Wait::Kind::semaphore) continue;
    if (w.sem->count <= 0 || w.sem->queue.empty() || w.sem->queue.front().inst != &inst) return false;
  }
  for (const Wait& w : inst.waits) {
    if (w.kind != Wait::Kind::semaphore) continue;
    --w.sem->count;
    w.sem->queue.erase(w.sem->queue.begin());
  }
  return true;
}

bool Machine::waits_satisfied(Instance& inst) {
  const double now = time_of(cycle_);
  for (const Wait& w : inst.waits) {
    switch (w.kind) {
      case Wait::Kind::fsm:
        if (!done(*w.inst)) return false;
        break;
      case Wait::Kind::state: {
        if (w.inst->entered[static_cast<std::size_t>(w.state_index)] < w.posted) return false;
        break;
      }
      case Wait::Kind::time:
        if (now + time_slack < w.time) return false;
        break;
      case Wait::Kind::motion:
        if (!w.motion->done && !(now + time_slack >= w.motion->end)) return false;
        break;
      case Wait::Kind::condition: {
        steps_ = 0;
        depth_ = 0;
        if (!apply(w.closure, nullptr, 0, SrcPos{}).truthy()) return false;
        break;
      }
      case Wait::Kind::semaphore:
        break;
    }
  }
  return try_acquire(inst);
}

bool Machine::run_code(Instance& inst, const Function* fn, Value* result) {
  try {
    steps_ = 0;
    depth_ = 0;
    current_ = &inst;
    Value r = eval(fn->body, &inst, nullptr);
    if (result != nullptr) *result = std::move(r);
  } catch (const LispError& err) {
    runtime_failure(inst, err);
    return false;
  }
  return !done(inst);
}

void Machine::runtime_failure(Instance& inst, const LispError& err) {
  ++errors_;
  Event e = make_event(Event::Kind::error, &inst);
  e.text = fmt::format("{} ({})", err.message, where(err.pos));
  emit_event(e);
  finish(inst, Status::failed, nullptr);
  if (opt_.strict) throw Error(fest::Status::failure, fmt::format("{}: {}", inst.label, e.text));
}

void Machine::enter_node(Instance& inst) {
  inst.entering = false;
  inst.entered[static_cast<std::size_t>(inst.node->index)] = cycle_;
  Event e = make_event(Event::Kind::enter, &inst);
  e.node = names_[static_cast<std::size_t>(inst.node->name)];
  emit_event(e);
  if (inst.node->action_fn != nullptr) run_code(inst, inst.node->action_fn, nullptr);
}

void Machine::choose_arc(Instance& inst) {
  const NodeDef& nd = *inst.node;
  const Arc* taken = nullptr;
  if (nd.kind == NodeKind::plain) {
    for (const Arc& a : nd.arcs) {
      if (a.is_default) {
        taken = &a;
        break;
      }
      Value r;
      if (!run_code(inst, a.cond_fn, &r)) return;
      if (r.truthy()) {
        taken = &a;
        break;
      }
    }
  } else {
    // One uniform draw, cumulative choice; u beyond the sum of probabilities: no arc.
    const double u = rng_.uniform();
    double cum = 0.0;
    for (const Arc& a : nd.arcs) {
      cum += a.prob;
      if (u < cum) {
        taken = &a;
        break;
      }
    }
  }
  if (taken == nullptr) return;
  Event e = make_event(Event::Kind::arc, &inst);
  e.from = names_[static_cast<std::size_t>(nd.name)];
  if (nd.kind == NodeKind::plain) e.cond = names_[static_cast<std::size_t>(taken->cond)];
  else e.prob = taken->prob;
  e.to = names_[static_cast<std::size_t>(taken->target)];
  emit_event(e);
  if (taken->to == nullptr) {
    finish(inst, Status::finished, nullptr);
  } else {
    inst.node = taken->to;
    inst.entering = true;
  }
}

void Machine::step_instance(Instance& inst) {
  current_ = &inst;
  if (inst.status == Status::idle) {
    inst.status = Status::running;
    inst.node = inst.cls->start;
    inst.entering = true;
  }
  // (a) monitors, even while waiting
  for (const MonitorDef& m : inst.cls->monitors) {
    Value r = Value::t();
    if (m.cond_fn != nullptr && !run_code(inst, m.cond_fn, &r)) return;
    if (!r.truthy()) continue;
    Event e = make_event(Event::Kind::monitor, &inst);
    e.name = names_[static_cast<std::size_t>(m.name)];
    emit_event(e);
    if (m.action_fn != nullptr && !run_code(inst, m.action_fn, nullptr)) return;
  }
  if (inst.status == Status::waiting) {
    // (b)
    if (!waits_satisfied(inst)) return;
    if (done(inst)) return;
    inst.waits.clear();
    inst.status = Status::running;
    Event e = make_event(Event::Kind::resume, &inst);
    emit_event(e);
  } else {
    // (c)
    if (inst.entering) {
      enter_node(inst);
      if (done(inst)) return;
    }
    if (!inst.waits.empty()) {
      const bool ok = waits_satisfied(inst);
      if (done(inst)) return;
      if (!ok) {
        inst.status = Status::waiting;
        Event e = make_event(Event::Kind::wait, &inst);
        for (const Wait& w : inst.waits) e.waits.push_back(wait_kind_name(w.kind));
        emit_event(e);
        return;
      }
      inst.waits.clear();
    }
  }
  // (d)
  choose_arc(inst);
}

void Machine::set_table(TableInput table) {
  table_ = std::move(table);
  has_table_ = true;
  table_syms_.clear();
  for (const std::string& n : table_.names) {
    std::string s = upcase(n);
    for (char& c : s)
      if (c == '_') c = '-';
    table_syms_.push_back(intern(s));
  }
}

void Machine::bind_table_row() {
  if (!has_table_ || table_.rows.empty()) return;
  const double now = time_of(cycle_) + time_slack;
  std::size_t r = table_row_ == static_cast<std::size_t>(-1) ? 0 : table_row_;
  if (table_.rows[0][table_.t_col] > now) return;
  while (r + 1 < table_.rows.size() && table_.rows[r + 1][table_.t_col] <= now) ++r;
  if (r == table_row_) return;
  table_row_ = r;
  Value alist;
  for (std::size_t c = table_.names.size(); c > 0; --c) {
    const double v = table_.rows[r][c - 1];
    const Value x = v == std::floor(v) && std::fabs(v) < 9e15 ? Value::integer(static_cast<std::int64_t>(v)) : Value::real(v);
    alist = Value::cons(Value::cons(Value::symbol(table_syms_[c - 1]), x), alist);
  }
  const int var = intern(upcase(table_.var));
  globals_[static_cast<std::size_t>(var)] = alist;
  bound_[static_cast<std::size_t>(var)] = 1;
}

void Machine::apply_inputs() {
  const double now = time_of(cycle_) + time_slack;
  while (next_input_ < inputs_.size() && inputs_[next_input_].t <= now) {
    InputEvent& in = inputs_[next_input_++];
    try {
      switch (in.kind) {
        case InputEvent::Kind::set:
          for (auto& [name, v] : in.set) {
            const int s = intern(upcase(name));
            globals_[static_cast<std::size_t>(s)] = v;
            bound_[static_cast<std::size_t>(s)] = 1;
          }
          break;
        case InputEvent::Kind::motion: {
          auto m = std::make_unique<Motion>();
          m->name = in.name;
          m->start = in.start;
          m->end = in.end;
          motions_.push_back(std::move(m));
          break;
        }
        case InputEvent::Kind::motion_done: {
          Motion* found = nullptr;
          for (auto& m : motions_)
            if (m->name == in.name) found = m.get();
          if (found == nullptr) {
            motions_.push_back(std::make_unique<Motion>());
            found = motions_.back().get();
            found->name = in.name;
            found->end = std::numeric_limits<double>::infinity();
          }
          found->done = true;
          break;
        }
        case InputEvent::Kind::spawn: {
          const Value c = global(in.name);
          if (c.tag != Tag::netclass) throw LispError{fmt::format("spawn: {} is not a net class ({})", in.name, in.where), {}};
          steps_ = 0;
          depth_ = 0;
          current_ = nullptr;
          create_instance(c.u.cls, in.args.data(), in.args.size(), SrcPos{});
          break;
        }
        case InputEvent::Kind::eval:
          eval_text(in.name, in.where);
          break;
      }
    } catch (const LispError& err) {
      ++errors_;
      Event e = make_event(Event::Kind::error, nullptr);
      e.text = err.pos.line > 0 ? fmt::format("{} ({})", err.message, where(err.pos)) : fmt::format("{} ({})", err.message, in.where);
      emit_event(e);
      if (opt_.strict) throw Error(fest::Status::failure, e.text);
    }
  }
}

Value Machine::eval_text(std::string_view text, const std::string& where_name) {
  std::vector<Datum> forms;
  const int file = static_cast<int>(files_.size());
  files_.push_back(where_name);
  try {
    forms = read_all(text, file);
  } catch (const ReadError& e) {
    throw LispError{e.message, e.pos};
  }
  Value r;
  for (const Datum& d : forms) {
    Expr* e = compile(d);
    steps_ = 0;
    depth_ = 0;
    current_ = nullptr;
    r = eval(e, nullptr, nullptr);
  }
  flush_print(nullptr, true);
  return r;
}

bool Machine::deadlocked() const {
  if (next_input_ < inputs_.size()) return false;
  bool any = false;
  for (const auto& p : insts_) {
    const Instance& i = *p;
    if (done(i)) continue;
    if (i.status != Status::waiting || !i.cls->monitors.empty()) return false;
    for (const Wait& w : i.waits) {
      // Time, conditions and motions may change by themselves; the others only if met now.
      if (w.kind == Wait::Kind::time || w.kind == Wait::Kind::condition || w.kind == Wait::Kind::motion) return false;
      if (w.kind == Wait::Kind::fsm && done(*w.inst)) return false;
      if (w.kind == Wait::Kind::semaphore && w.sem->count > 0) return false;
      if (w.kind == Wait::Kind::state) {
        if (w.inst->entered[static_cast<std::size_t>(w.state_index)] >= w.posted) return false;
      }
    }
    any = true;
  }
  return any;
}

RunSummary Machine::run() {
  RunSummary sum;
  try {
    flush_print(nullptr, true);
    for (;;) {
      if (opt_.cycles >= 0 && cycle_ >= opt_.cycles) break;
      if (cycle_ > 0 && time_of(cycle_) >= opt_.until) break;
      bool live = false;
      for (const auto& p : insts_)
        if (!done(*p)) {
          live = true;
          break;
        }
      if (!live && next_input_ >= inputs_.size()) break;
      if (deadlocked()) {
        sum.deadlock = true;
        Event e = make_event(Event::Kind::deadlock, nullptr);
        emit_event(e);
        if (opt_.strict) throw Error(fest::Status::failure, fmt::format("deadlock at cycle {}: every live net waits", cycle_));
        break;
      }
      if (cycle_ >= opt_.max_cycles)
        throw LimitError{fmt::format("the run reached the cycle limit ({} cycles) with nets still live", opt_.max_cycles)};
      ++cycle_;
      if (opt_.on_cycle) opt_.on_cycle(cycle_, time_of(cycle_));
      apply_inputs();
      bind_table_row();
      const std::size_t n = insts_.size();
      for (std::size_t i = 0; i < n; ++i) {
        Instance& inst = *insts_[i];
        if (inst.created < cycle_ && !done(inst)) step_instance(inst);
      }
    }
  } catch (const LimitError& lim) {
    Event e = make_event(Event::Kind::error, current_);
    e.text = lim.message;
    emit_event(e);
    throw Error(fest::Status::failure, lim.message);
  }
  sum.cycles = cycle_;
  sum.instances = static_cast<std::int64_t>(insts_.size());
  for (const auto& p : insts_) {
    if (p->status == Status::finished) ++sum.finished;
    if (p->status == Status::failed) ++sum.failed;
  }
  sum.errors = errors_;
  return sum;
}

}  // namespace fest::patnet

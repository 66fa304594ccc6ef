#pragma once
// The PaT-Net machine: loads PaT-Lisp source (compiling it to expression trees), keeps
// the net classes, instances, semaphores and motions, and runs the "net operating
// system" that time-slices all instances in fixed cycles (docs/patnet.md "Scheduler").
// No I/O: the trace goes to a TraceSink, inputs come in as typed events.

#include <cmath>
#include <cstdint>
#include <deque>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/rng.hpp"
#include "core/stack_budget.hpp"
#include "patnet/net.hpp"
#include "patnet/reader.hpp"
#include "patnet/value.hpp"

namespace fest::patnet {

struct Diagnostic {
  bool error = true;
  std::string message;
  std::string file;
  SrcPos pos;
  std::string text() const;  // "message (file:line:col)"
};

struct Event {
  enum class Kind : std::uint8_t { create, enter, arc, wait, resume, monitor, print, exit, kill, error, deadlock };
  Kind kind = Kind::create;
  std::int64_t cycle = 0;
  double t = 0.0;
  const Instance* inst = nullptr;  // null for run-wide events (deadlock, load errors)
  std::string_view node, from, cond, to, name, cls;
  double prob = -1.0;              // >= 0: a probabilistic arc
  std::string text;                // print text, error message, exit status
  std::vector<std::string_view> waits;
  std::vector<std::string> args;   // create: printed arguments; exit: locals "name=value"
  const Instance* by = nullptr;    // kill: the instance whose exit killed this one
};

class TraceSink {
 public:
  virtual ~TraceSink() = default;
  virtual void event(const Event& e) = 0;
};

struct RunOptions {
  double dt = 1.0 / 30.0;
  double t0 = 0.0;
  std::uint64_t seed = 1;
  std::int64_t cycles = -1;  // stop after this many cycles (< 0: run until done)
  double until = std::numeric_limits<double>::infinity();
  std::int64_t max_cycles = 1000000;
  std::int64_t max_nets = 100000;
  std::int64_t max_steps = 1000000;  // evaluation steps per action, condition or monitor
  int max_depth = 2000;              // nested calls
  bool strict = false;
  bool dump_locals = false;
  // Called before each cycle with its number and motion time (the tool paces --realtime).
  std::function<void(std::int64_t, double)> on_cycle;
};

// Inputs from the outside world (docs/patnet.md "Inputs").
struct InputEvent {
  enum class Kind { set, motion, motion_done, spawn, eval };
  Kind kind = Kind::set;
  double t = 0.0;
  std::vector<std::pair<std::string, Value>> set;
  std::string name;            // motion name, motion-done name, spawn class, eval text
  double start = 0.0, end = 0.0;
  std::vector<Value> args;     // spawn arguments
  std::string where;           // "events.jsonl:12" for messages
};

// A table whose row at the current time is bound to a global as an association list.
struct TableInput {
  std::string var;
  std::vector<std::string> names;           // column names (the t column included)
  std::vector<std::vector<double>> rows;    // rows[r][c]
  std::size_t t_col = 0;
};

struct RunSummary {
  std::int64_t cycles = 0;
  std::int64_t instances = 0;
  std::int64_t finished = 0, failed = 0;
  bool deadlock = false;
  std::int64_t errors = 0;
};

// A run-time error of PaT-Lisp code (becomes an `error` event, or exit 1 with --strict).
struct LispError {
  std::string message;
  SrcPos pos;
};

// A --max-* limit was hit: the run stops (exit 1).
struct LimitError {
  std::string message;
};

class Machine {
 public:
  explicit Machine(RunOptions opt = {}, TraceSink* sink = nullptr);
  ~Machine();
  Machine(const Machine&) = delete;
  Machine& operator=(const Machine&) = delete;

  // Reads and compiles one file's forms. With `execute`, top-level forms run (cycle 0)
  // after the whole file compiled cleanly; errors throw fest::Error(bad_input) naming
  // file:line:col. Without it, nothing runs and problems collect in diagnostics().
  void load(std::string_view text, const std::string& file_name, bool execute);
  // Static checks over everything loaded (undefined functions, unreachable nodes...).
  void finish_checks();
  const std::vector<Diagnostic>& diagnostics() const { return diags_; }
  bool has_errors() const;

  // Evaluates one expression at top level (--eval), after loading.
  Value eval_text(std::string_view text, const std::string& where);

  void set_inputs(std::vector<InputEvent> events) { inputs_ = std::move(events); }
  void set_table(TableInput table);
  void set_cycle_hook(std::function<void(std::int64_t, double)> hook) { opt_.on_cycle = std::move(hook); }
  // Runs cycles until done; throws fest::Error(failure) for --strict errors and limits.
  RunSummary run();

  // Introspection for dot, tests and the tool.
  const std::vector<NetClass*>& classes() const { return class_order_; }
  const std::string& symbol_name(int sym) const { return names_[static_cast<std::size_t>(sym)]; }
  int intern(std::string_view upper_name);
  Value global(std::string_view name) const;
  const std::vector<std::unique_ptr<Instance>>& instances() const { return insts_; }
  std::string print(const Value& v, bool escape) const;
  const std::string& file_name(int index) const { return files_[static_cast<std::size_t>(index)]; }
  double time() const { return time_of(cycle_); }
  std::int64_t cycle() const { return cycle_; }

 private:
  RunOptions opt_;
  TraceSink* sink_;
  Rng rng_;
  std::deque<std::string> names_;
  std::unordered_map<std::string, int> symtab_;
  std::vector<std::string> files_;
  std::vector<Diagnostic> diags_;
  std::vector<std::unique_ptr<Expr>> exprs_;
  std::vector<std::unique_ptr<Function>> funcs_;
  std::vector<Function*> user_fns_;       // by symbol
  std::vector<Value> globals_;            // by symbol
  std::vector<char> bound_;               // by symbol
  std::vector<std::unique_ptr<NetClass>> class_store_;
  std::vector<NetClass*> class_order_;
  std::vector<std::unique_ptr<Instance>> insts_;
  std::vector<std::unique_ptr<Semaphore>> sems_;
  std::vector<std::unique_ptr<Motion>> motions_;
  std::vector<std::pair<int, SrcPos>> calls_;  // user-function calls to check at the end
  std::vector<InputEvent> inputs_;
  std::size_t next_input_ = 0;
  TableInput table_;
  bool has_table_ = false;
  std::size_t table_row_ = static_cast<std::size_t>(-1);
  std::vector<int> table_syms_;
  std::int64_t cycle_ = 0;
  std::uint64_t sem_seq_ = 0;
  std::int64_t steps_ = 0;
  int depth_ = 0;
  StackBudget stack_;  // armed at the outermost call (depth_ == 0)
  std::int64_t errors_ = 0;
  Instance* current_ = nullptr;  // instance whose code runs (for :exit of self)

  double time_of(std::int64_t k) const { return opt_.t0 + static_cast<double>(k) * opt_.dt; }
  void emit_event(Event& e);
  Event make_event(Event::Kind k, const Instance* inst) const;

  // load
  void add_diag(bool error, std::string msg, SrcPos pos);
  void top_level(const Datum& d, bool execute, std::vector<const Datum*>& to_run);
  void define_net(const Datum& d);
  void finalize_class(NetClass& c);
  Expr* compile(const Datum& d);

  // eval
  Value eval(const Expr* e, Instance* self, const std::shared_ptr<Frame>& env);
  Value call_function(const Function* fn, Instance* self, const std::shared_ptr<Frame>& env, const Value* args,
                      std::size_t n, SrcPos pos);
  Value apply(const Value& f, const Value* args, std::size_t n, SrcPos pos);
  Value call_builtin(int id, const Value* args, std::size_t n, SrcPos pos, Instance* self);
  Value send(Instance* self, const Value& obj, int msg, const Value* args, std::size_t n, SrcPos pos);
  Value val_get(const Expr* e, Instance* self);
  void val_set(const Expr* e, Instance* self, Value v);
  bool lookup_lexical(const std::shared_ptr<Frame>& env, int sym, Value** out) const;
  [[noreturn]] void error(SrcPos pos, std::string msg) const;
  std::string where(SrcPos pos) const;
  void format_into(std::string& out, const Value* args, std::size_t n, SrcPos pos);
  void flush_print(Instance* inst, bool all);
  std::string top_print_;
  int loop_depth_ = 0;  // compiling inside DOLIST/DOTIMES bodies (where RETURN may appear)

  // scheduler
  Instance* create_instance(NetClass* cls, const Value* args, std::size_t n, SrcPos pos);
  void step_instance(Instance& inst);
  bool run_code(Instance& inst, const Function* fn, Value* result);  // false: the instance failed
  bool waits_satisfied(Instance& inst);
  bool try_acquire(Instance& inst);
  void leave_queues(Instance& inst);
  void finish(Instance& inst, Status st, const Instance* killer);
  void enter_node(Instance& inst);
  void choose_arc(Instance& inst);
  void apply_inputs();
  void bind_table_row();
  bool deadlocked() const;
  void runtime_failure(Instance& inst, const LispError& err);

 public:
  // Symbols the evaluator compares against (interned at construction).
  struct Syms;
  std::unique_ptr<Syms> sy_;
};

}  // namespace fest::patnet

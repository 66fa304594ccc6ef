#pragma once
// Compiled code and the objects of a PaT-Net run: expressions, functions, net classes
// with their nodes and arcs, instances, waits, semaphores, motions (docs/patnet.md
// "Concepts" and "Data structures").

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "patnet/reader.hpp"
#include "patnet/value.hpp"

namespace fest::patnet {

enum class Op : std::uint8_t {
  constant, self, var, setvar, val_get, val_set, if_, and_, or_, progn, let, letstar, cond, lambda, funcref,
  call_builtin, call_user, send, dolist, dotimes, return_
};

struct LambdaList {
  std::vector<int> required;
  std::vector<std::pair<int, struct Expr*>> optional;  // name, default (may be null)
  std::vector<std::pair<int, struct Expr*>> key;       // name (keyword :NAME matches), default
  int rest = -1;
};

struct Expr {
  Op op = Op::constant;
  SrcPos pos;
  Value k;             // constant
  int sym = -1;        // variable, function, builtin id, message keyword
  std::vector<Expr*> kids;
  std::vector<int> syms;      // let: names; dolist/dotimes: the variable
  const Function* fn = nullptr;  // lambda
  // Inline cache of (val x): the class last seen and where x lives in it.
  mutable const NetClass* cache_cls = nullptr;
  mutable int cache_slot = -1;       // >= 0: instance local; -1: class variable
  mutable Value* cache_cv = nullptr;
};

struct Function {
  int name = -1;
  LambdaList params;
  Expr* body = nullptr;  // a progn
  SrcPos pos;
};

struct Arc {
  int cond = -1;       // condition name (keyword symbol); -1 for probabilistic arcs
  bool is_default = false;
  double prob = 0.0;   // probability (weights already scaled)
  int target = -1;     // node name symbol
  SrcPos pos;
  // Resolved per class:
  const Function* cond_fn = nullptr;
  struct NodeDef* to = nullptr;  // null = exit
};

enum class NodeKind { plain, prob, weight, rand };

struct NodeDef {
  int name = -1;
  NodeKind kind = NodeKind::plain;
  int action = -1;   // keyword symbol; NO-OP = -1
  SrcPos pos, action_pos;
  std::vector<Arc> arcs;
  const Function* action_fn = nullptr;  // resolved per class
  const struct NetClass* owner = nullptr;
  int index = -1;  // in the class's flattened node table (Instance::entered)
};

struct MonitorDef {
  int name = -1;
  int cond = -1, action = -1;
  SrcPos pos;
  const Function* cond_fn = nullptr;
  const Function* action_fn = nullptr;
};

struct NetClass {
  int name = -1;
  std::string print_name;  // lower case, as traced
  SrcPos pos;
  std::vector<NetClass*> parents;
  std::vector<NetClass*> cpl;  // class precedence list, this class first
  std::vector<int> own_locals;
  std::vector<int> own_classvars;
  std::vector<Value> classvar_values;  // of own_classvars
  std::map<int, Function*> actions, conds;   // own definitions
  std::vector<NodeDef> own_nodes;            // own definitions, in order
  std::vector<MonitorDef> own_monitors;
  Function* init = nullptr;
  int start_sym = -1;
  SrcPos start_pos;
  // Flattened over the precedence list:
  std::unordered_map<int, int> local_slot;
  std::vector<int> local_names;  // slot -> name
  std::unordered_map<int, NodeDef> nodes;     // copies resolved against this class
  std::vector<MonitorDef> monitors;           // parents' first
  NodeDef* start = nullptr;
  Function* initializer = nullptr;
  const Function* find_action(int name) const;
  const Function* find_cond(int name) const;
  Value* find_classvar(int name);
};

enum class Status : std::uint8_t { idle, running, waiting, finished, failed };
const char* status_name(Status s);

struct Semaphore;
struct Motion {
  std::string name;
  double start = 0.0, end = 0.0;
  bool done = false;
};

struct Wait {
  enum class Kind : std::uint8_t { fsm, state, time, condition, motion, semaphore } kind;
  Instance* inst = nullptr;
  int state = -1;
  int state_index = -1;
  std::int64_t posted = 0;  // cycle
  double time = 0.0;
  Value closure;
  Motion* motion = nullptr;
  Semaphore* sem = nullptr;
};
const char* wait_kind_name(Wait::Kind k);

struct Instance {
  int id = 0;
  NetClass* cls = nullptr;
  std::vector<Value> locals;
  Status status = Status::idle;
  const NodeDef* node = nullptr;
  bool entering = true;
  std::int64_t created = 0;
  std::vector<Wait> waits;
  std::vector<Instance*> dependents;
  std::vector<Instance*> state_waiters;  // instances that posted :wait-fsm this :state
  std::vector<std::int64_t> entered;  // by NodeDef::index: last cycle entered, -1 never
  std::string var;      // global it was bound to, for the trace
  std::string label;    // class#id
  bool exit_requested = false;
  std::string print_buf;  // (format t ...) text up to the next newline
};

struct Semaphore {
  int id = 0;
  std::int64_t count = 1;
  struct Entry {
    double priority;
    std::uint64_t seq;
    Instance* inst;
  };
  std::vector<Entry> queue;  // kept sorted: priority high first, then seq
};

}  // namespace fest::patnet

#pragma once
// PaT-Lisp values (docs/patnet.md "Data structures"): a tagged word; lists, strings and
// closures are reference-counted; instances, classes, semaphores and motions belong to
// the Machine and live for the whole run.

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace fest::patnet {

struct Instance;
struct NetClass;
struct Semaphore;
struct Motion;
struct Function;

enum class Tag : std::uint8_t { nil, t, integer, real, string, symbol, cons, closure, builtin, instance, netclass, semclass, semaphore, motion };

struct HeapObj {
  virtual ~HeapObj() = default;
};

struct Value {
  Tag tag = Tag::nil;
  union {
    std::int64_t i;
    double d;
    int sym;
    int builtin;
    Instance* inst;
    NetClass* cls;
    Semaphore* sem;
    Motion* motion;
  } u{};
  std::shared_ptr<HeapObj> obj;  // string, cons or closure

  static Value nil() { return Value{}; }
  static Value t() { Value v; v.tag = Tag::t; return v; }
  static Value boolean(bool b) { return b ? t() : nil(); }
  static Value integer(std::int64_t i) { Value v; v.tag = Tag::integer; v.u.i = i; return v; }
  static Value real(double d) { Value v; v.tag = Tag::real; v.u.d = d; return v; }
  static Value symbol(int s) { Value v; v.tag = Tag::symbol; v.u.sym = s; return v; }
  static Value string(std::string s);
  static Value cons(Value car, Value cdr);
  static Value instance(Instance* p) { Value v; v.tag = Tag::instance; v.u.inst = p; return v; }
  static Value netclass(NetClass* p) { Value v; v.tag = Tag::netclass; v.u.cls = p; return v; }
  static Value semaphore(Semaphore* p) { Value v; v.tag = Tag::semaphore; v.u.sem = p; return v; }
  static Value motion(Motion* p) { Value v; v.tag = Tag::motion; v.u.motion = p; return v; }

  bool is_nil() const { return tag == Tag::nil; }
  bool truthy() const { return tag != Tag::nil; }
  bool is_number() const { return tag == Tag::integer || tag == Tag::real; }
  double number() const { return tag == Tag::integer ? static_cast<double>(u.i) : u.d; }
};

struct StringObj : HeapObj {
  std::string s;
};
struct Cons : HeapObj {
  Value car, cdr;
  ~Cons() override;
};
struct Frame;
// A lambda closed over its lexical frame and the instance it was made in (so that
// (val x) inside a :wait-condition closure reads that instance's variables).
struct Closure : HeapObj {
  const Function* fn = nullptr;
  std::shared_ptr<Frame> env;
  Instance* self = nullptr;
};

inline Value Value::string(std::string s) {
  Value v;
  v.tag = Tag::string;
  auto o = std::make_shared<StringObj>();
  o->s = std::move(s);
  v.obj = std::move(o);
  return v;
}
inline Value Value::cons(Value car, Value cdr) {
  Value v;
  v.tag = Tag::cons;
  auto o = std::make_shared<Cons>();
  o->car = std::move(car);
  o->cdr = std::move(cdr);
  v.obj = std::move(o);
  return v;
}
// A long list is freed cell by cell in a loop: the default chain of destructors would
// recurse once per cell and overflow the stack on a million-element list.
inline Cons::~Cons() {
  Value rest = std::move(cdr);
  while (rest.tag == Tag::cons && rest.obj.use_count() == 1) {
    Value next = std::move(static_cast<Cons*>(rest.obj.get())->cdr);
    rest = std::move(next);
  }
}
inline const std::string& str_of(const Value& v) { return static_cast<const StringObj*>(v.obj.get())->s; }
inline Cons* cons_of(const Value& v) { return static_cast<Cons*>(v.obj.get()); }
inline Closure* closure_of(const Value& v) { return static_cast<Closure*>(v.obj.get()); }

// Lexical variables: a chain of small frames.
struct Frame : HeapObj {
  std::shared_ptr<Frame> parent;
  std::vector<std::pair<int, Value>> vars;
};

}  // namespace fest::patnet

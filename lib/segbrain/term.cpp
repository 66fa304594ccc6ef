// Term construction, printing, copying and ordering.
#include "segbrain/term.hpp"

#include <atomic>
#include <cmath>
#include <map>
#include <sstream>
#include <unordered_map>

#include <fmt/format.h>

#include "segbrain/operators_table.hpp"

namespace fest::segbrain {

const OpDef* infix_op(const std::string& name) {
  static const std::map<std::string, OpDef> ops = {
      {":-", {1200, OpType::xfx}}, {";", {1100, OpType::xfy}}, {"->", {1050, OpType::xfy}},
      {",", {1000, OpType::xfy}},  {"=", {700, OpType::xfx}},  {"\\=", {700, OpType::xfx}},
      {"==", {700, OpType::xfx}},  {"\\==", {700, OpType::xfx}}, {"is", {700, OpType::xfx}},
      {"<", {700, OpType::xfx}},   {">", {700, OpType::xfx}},  {"=<", {700, OpType::xfx}},
      {">=", {700, OpType::xfx}},  {"=:=", {700, OpType::xfx}}, {"=\\=", {700, OpType::xfx}},
      {"+", {500, OpType::yfx}},   {"-", {500, OpType::yfx}},  {"*", {400, OpType::yfx}},
      {"/", {400, OpType::yfx}},   {"//", {400, OpType::yfx}}, {"mod", {400, OpType::yfx}},
      {"**", {200, OpType::xfx}}};
  auto it = ops.find(name);
  return it == ops.end() ? nullptr : &it->second;
}

const OpDef* prefix_op(const std::string& name) {
  static const std::map<std::string, OpDef> ops = {
      {":-", {1200, OpType::fx}}, {"\\+", {900, OpType::fy}}, {"-", {200, OpType::fy}}};
  auto it = ops.find(name);
  return it == ops.end() ? nullptr : &it->second;
}

namespace {
Term make_node(Kind kind) {
  auto n = std::make_shared<Node>();
  n->kind = kind;
  return n;
}
}  // namespace

// Variables are numbered in the order they are made, so that printed terms (_G<n>) and
// the standard order of unbound variables are the same on every run; an address would not be.
std::atomic<std::int64_t> next_variable{0};

Term make_var(const std::string& name) {
  Term n = make_node(Kind::var);
  n->name = name;
  n->ival = next_variable.fetch_add(1, std::memory_order_relaxed);
  return n;
}
Term make_atom(const std::string& name) {
  Term n = make_node(Kind::atom);
  n->name = name;
  return n;
}
Term make_int(std::int64_t v) {
  Term n = make_node(Kind::integer);
  n->ival = v;
  return n;
}
Term make_real(double v) {
  Term n = make_node(Kind::real);
  n->fval = v;
  return n;
}
Term make_string(const std::string& s) {
  Term n = make_node(Kind::string);
  n->name = s;
  return n;
}
Term make_compound(const std::string& functor, std::vector<Term> args) {
  if (args.empty()) return make_atom(functor);
  Term n = make_node(Kind::compound);
  n->name = functor;
  n->args = std::move(args);
  return n;
}
Term make_list(const std::vector<Term>& items, Term tail) {
  Term t = tail ? tail : make_atom("[]");
  for (auto it = items.rbegin(); it != items.rend(); ++it) t = make_compound(".", {*it, t});
  return t;
}

Term deref(Term t) {
  while (t->kind == Kind::var && t->ref) t = t->ref;
  return t;
}

bool is_atom(const Term& t, const char* name) {
  Term d = deref(t);
  return d->kind == Kind::atom && d->name == name;
}
bool is_callable(const Term& t) {
  Term d = deref(t);
  return d->kind == Kind::atom || d->kind == Kind::compound;
}
bool is_number(const Term& t) {
  Term d = deref(t);
  return d->kind == Kind::integer || d->kind == Kind::real;
}
double number_value(const Term& t) {
  Term d = deref(t);
  return d->kind == Kind::integer ? static_cast<double>(d->ival) : d->fval;
}
std::string indicator(const Term& t) {
  Term d = deref(t);
  return fmt::format("{}/{}", d->name, d->kind == Kind::compound ? d->args.size() : 0);
}

bool list_items(Term t, std::vector<Term>& items) {
  items.clear();
  for (t = deref(t); t->kind == Kind::compound && t->name == "." && t->args.size() == 2; t = deref(t->args[1]))
    items.push_back(t->args[0]);
  return t->kind == Kind::atom && t->name == "[]";
}

namespace {

bool is_letter_atom(const std::string& s) {
  if (s.empty() || !std::islower(static_cast<unsigned char>(s[0]))) return false;
  for (char c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}
bool is_symbol_atom(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s)
    if (std::string("+-*/\\^<>=~:.?@#&$").find(c) == std::string::npos) return false;
  return true;
}

std::string atom_text(const std::string& s) {
  if (is_letter_atom(s) || is_symbol_atom(s) || s == "[]" || s == "!" || s == ";" || s == ",") {
    return s == "," ? "','" : s;
  }
  std::string q = "'";
  for (char c : s) {
    if (c == '\'' || c == '\\') q += '\\';
    q += c;
  }
  return q + "'";
}

std::string number_text(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

void print(const Term& t0, int max_prec, std::string& out) {
  Term t = deref(t0);
  switch (t->kind) {
    case Kind::var: out += fmt::format("_G{}", t->ival); return;
    case Kind::atom: {
      bool op = infix_op(t->name) || prefix_op(t->name);
      if (op && max_prec < 1200) out += "(" + atom_text(t->name) + ")";
      else out += atom_text(t->name);
      return;
    }
    case Kind::integer: {
      std::string s = std::to_string(t->ival);
      if (t->ival < 0 && max_prec < 200) s = "(" + s + ")";
      out += s;
      return;
    }
    case Kind::real: {
      std::string s = number_text(t->fval);
      if (t->fval < 0 && max_prec < 200) s = "(" + s + ")";
      out += s;
      return;
    }
    case Kind::string: {
      out += '"';
      for (char c : t->name) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
      }
      out += '"';
      return;
    }
    case Kind::compound: break;
  }
  if (t->name == "." && t->args.size() == 2) {
    out += '[';
    Term cur = t;
    bool first = true;
    while (true) {
      cur = deref(cur);
      if (cur->kind == Kind::compound && cur->name == "." && cur->args.size() == 2) {
        if (!first) out += ", ";
        print(cur->args[0], 999, out);
        first = false;
        cur = cur->args[1];
        continue;
      }
      if (!(cur->kind == Kind::atom && cur->name == "[]")) {
        out += " | ";
        print(cur, 999, out);
      }
      break;
    }
    out += ']';
    return;
  }
  if (t->args.size() == 2) {
    if (const OpDef* op = infix_op(t->name)) {
      int lp = op->type == OpType::yfx ? op->priority : op->priority - 1;
      int rp = op->type == OpType::xfy ? op->priority : op->priority - 1;
      bool paren = op->priority > max_prec;
      if (paren) out += '(';
      print(t->args[0], lp, out);
      if (t->name == ",") out += ", ";
      else if (is_letter_atom(t->name)) out += " " + t->name + " ";
      else out += " " + t->name + " ";
      print(t->args[1], rp, out);
      if (paren) out += ')';
      return;
    }
  }
  if (t->args.size() == 1) {
    if (const OpDef* op = prefix_op(t->name)) {
      int ap = op->type == OpType::fy ? op->priority : op->priority - 1;
      bool paren = op->priority > max_prec;
      if (paren) out += '(';
      out += t->name;
      Term a = deref(t->args[0]);
      // A space keeps "- 1" (the compound) apart from the number -1 and "\+a" readable.
      out += ' ';
      print(a, ap, out);
      if (paren) out += ')';
      return;
    }
  }
  out += atom_text(t->name);
  out += '(';
  for (std::size_t i = 0; i < t->args.size(); ++i) {
    if (i) out += ", ";
    print(t->args[i], 999, out);
  }
  out += ')';
}

Term copy_rec(const Term& t0, std::unordered_map<const Node*, Term>& vars) {
  Term t = deref(t0);
  if (t->kind == Kind::var) {
    auto it = vars.find(t.get());
    if (it != vars.end()) return it->second;
    Term v = make_var(t->name);
    vars.emplace(t.get(), v);
    return v;
  }
  if (t->kind != Kind::compound) return t;
  std::vector<Term> args;
  args.reserve(t->args.size());
  for (const auto& a : t->args) args.push_back(copy_rec(a, vars));
  return make_compound(t->name, std::move(args));
}

int rank(Kind k) {
  switch (k) {
    case Kind::var: return 0;
    case Kind::integer:
    case Kind::real: return 1;
    case Kind::atom: return 2;
    case Kind::string: return 3;
    case Kind::compound: return 4;
  }
  return 5;
}

}  // namespace

std::string to_string(const Term& t) {
  std::string out;
  print(t, 1200, out);
  return out;
}

Term copy_term(const Term& t) {
  std::unordered_map<const Node*, Term> vars;
  return copy_rec(t, vars);
}

int compare_terms(const Term& a0, const Term& b0) {
  Term a = deref(a0), b = deref(b0);
  int ra = rank(a->kind), rb = rank(b->kind);
  if (ra != rb) return ra < rb ? -1 : 1;
  switch (a->kind) {
    case Kind::var: return a->ival < b->ival ? -1 : (a->ival == b->ival ? 0 : 1);
    case Kind::integer:
    case Kind::real: {
      double x = number_value(a), y = number_value(b);
      if (x != y) return x < y ? -1 : 1;
      if (a->kind != b->kind) return a->kind == Kind::real ? -1 : 1;  // 1.0 @< 1
      return 0;
    }
    case Kind::atom:
    case Kind::string: return a->name.compare(b->name) < 0 ? -1 : (a->name == b->name ? 0 : 1);
    case Kind::compound: {
      if (a->args.size() != b->args.size()) return a->args.size() < b->args.size() ? -1 : 1;
      if (a->name != b->name) return a->name < b->name ? -1 : 1;
      for (std::size_t i = 0; i < a->args.size(); ++i)
        if (int c = compare_terms(a->args[i], b->args[i])) return c;
      return 0;
    }
  }
  return 0;
}

}  // namespace fest::segbrain

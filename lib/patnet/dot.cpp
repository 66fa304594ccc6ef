#include "patnet/dot.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace fest::patnet {

namespace {

std::string quote(const std::string& s) {
  std::string r = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') r += '\\';
    if (c == '\n') {
      r += "\\n";
      continue;
    }
    r += c;
  }
  return r + "\"";
}

std::string node_id(const NetClass& c, const std::string& node) { return quote(c.print_name + "/" + node); }

std::string number(double p) { return fmt::format("{:.4g}", p); }

}  // namespace

std::string to_dot(const Machine& m, const std::string& only_class) {
  std::vector<const NetClass*> todo;
  for (const NetClass* c : m.classes())
    if (only_class.empty() || upcase(only_class) == m.symbol_name(c->name)) todo.push_back(c);
  if (todo.empty()) {
    if (!only_class.empty()) throw bad_input("no net class named {}", only_class);
    throw bad_input("the files define no net class");
  }
  std::string out = "digraph patnet {\n  rankdir=LR;\n  node [fontname=\"Helvetica\", fontsize=10];\n"
                    "  edge [fontname=\"Helvetica\", fontsize=9];\n";
  for (std::size_t ci = 0; ci < todo.size(); ++ci) {
    const NetClass& c = *todo[ci];
    out += fmt::format("  subgraph cluster_{} {{\n    label={};\n", ci, quote("net " + c.print_name));
    out += fmt::format("    {} [shape=folder, label={}];\n", quote("class:" + c.print_name), quote(c.print_name));
    bool has_exit = false;
    for (const NodeDef& own : c.own_nodes) {
      const NodeDef& nd = c.nodes.at(own.name);
      const std::string name = m.symbol_name(nd.name);
      const std::string action = nd.action >= 0 ? m.symbol_name(nd.action) : std::string(":no-op");
      const char* shape = nd.kind == NodeKind::plain ? "box" : "diamond";
      const char* kind = nd.kind == NodeKind::prob ? "\nprob" : nd.kind == NodeKind::weight ? "\nweight" : nd.kind == NodeKind::rand ? "\nrand" : "";
      const bool start = c.start != nullptr && c.start->name == nd.name;
      out += fmt::format("    {} [shape={}, label={}{}];\n", node_id(c, name), shape, quote(name + "\n" + action + kind),
                         start ? ", penwidth=2" : "");
      for (const Arc& a : nd.arcs) {
        const std::string label = nd.kind == NodeKind::plain ? m.symbol_name(a.cond) : number(a.prob);
        std::string target;
        if (a.to == nullptr) {
          target = quote(c.print_name + "/EXIT");
          has_exit = true;
        } else {
          target = node_id(*a.to->owner, m.symbol_name(a.to->name));
        }
        out += fmt::format("    {} -> {} [label={}];\n", node_id(c, name), target, quote(label));
      }
    }
    if (has_exit) out += fmt::format("    {} [shape=doublecircle, label=\"exit\"];\n", quote(c.print_name + "/EXIT"));
    for (std::size_t k = 0; k < c.own_monitors.size(); ++k) {
      const MonitorDef& mo = c.own_monitors[k];
      const std::string id = quote(c.print_name + "/monitor/" + std::to_string(k));
      out += fmt::format("    {} [shape=note, label={}];\n", id,
                         quote("monitor " + m.symbol_name(mo.name) + "\n" + (mo.cond >= 0 ? m.symbol_name(mo.cond) : "?") +
                               " -> " + (mo.action >= 0 ? m.symbol_name(mo.action) : "?")));
      out += fmt::format("    {} -> {} [style=dotted, arrowhead=none];\n", quote("class:" + c.print_name), id);
    }
    if (c.start != nullptr)
      out += fmt::format("    {} -> {} [style=dotted, label=\"start\"];\n", quote("class:" + c.print_name),
                         node_id(*c.start->owner, m.symbol_name(c.start->name)));
    out += "  }\n";
  }
  for (const NetClass* c : todo)
    for (const NetClass* p : c->parents)
      out += fmt::format("  {} -> {} [style=dashed, label=\"inherits\"];\n", quote("class:" + c->print_name),
                         quote("class:" + p->print_name));
  out += "}\n";
  return out;
}

}  // namespace fest::patnet

// Loading rule files and reading their label/4 facts (docs/segbrain.md §2).
#include "knowledge_base.hpp"

#include <set>

#include "core/error.hpp"
#include "core/file_io.hpp"

namespace fest::segbrain_tool {

using namespace fest::segbrain;

namespace {

std::string folder_of(const std::string& path) {
  auto p = path.find_last_of('/');
  return p == std::string::npos ? std::string() : path.substr(0, p + 1);
}

// Parses a rule file and, depth first, the files it includes (relative to its folder).
void load_kb_file(const std::string& path, std::vector<Program>& out, std::set<std::string>& seen) {
  if (!seen.insert(path).second) return;
  Program p = parse_program(read_input(path), path);
  for (const auto& d : p.directives) {
    Term g = deref(d.goal);
    if (g->kind == Kind::compound && g->name == "include" && g->args.size() == 1) {
      Term f = deref(g->args[0]);
      if (f->kind != Kind::atom && f->kind != Kind::string)
        throw bad_input("{}:{}: include/1 expects a file name", d.file, d.line);
      std::string inc = f->name.size() && f->name[0] == '/' ? f->name : folder_of(path) + f->name;
      load_kb_file(inc, out, seen);
    }
  }
  out.push_back(std::move(p));
}

}  // namespace

std::vector<Program> load_kb(const std::vector<std::string>& files) {
  std::vector<Program> progs;
  if (files.empty()) {
    progs.push_back(parse_program(kDefaultKb, kDefaultKbName));
    return progs;
  }
  std::set<std::string> seen;
  for (const auto& f : files) load_kb_file(f, progs, seen);
  return progs;
}

std::vector<LabelEntry> label_entries(Engine& engine) {
  std::vector<LabelEntry> out;
  if (!engine.defines("label", 4)) return out;
  Term all = make_var("L");
  Term tmpl = make_compound("label", {make_var("I"), make_var("N"), make_var("P"), make_var("C")});
  if (!engine.prove(make_compound("findall", {tmpl, tmpl, all}))) return out;
  std::vector<Term> items;
  list_items(deref(all), items);
  for (const auto& it : items) {
    Term t = deref(it);
    std::vector<Term> rgb;
    if (!is_number(t->args[0]) || deref(t->args[1])->kind != Kind::atom || !list_items(deref(t->args[3]), rgb) || rgb.size() != 3)
      throw bad_input("label/4 expects label(Index, name, parent, [R, G, B]), got {}", to_string(t));
    LabelEntry e;
    e.index = static_cast<int>(number_value(t->args[0]));
    e.name = deref(t->args[1])->name;
    e.parent = to_string(deref(t->args[2]));
    for (int c = 0; c < 3; ++c) e.rgb[c] = static_cast<int>(number_value(rgb[c]));
    out.push_back(e);
  }
  return out;
}

std::vector<LabelEntry> kb_labels(const std::vector<std::string>& kb) {
  Engine engine;
  for (const auto& p : load_kb(kb)) engine.consult(p);
  return label_entries(engine);
}

}  // namespace fest::segbrain_tool

// segbrain run: formats -> lib/segbrain (the engine proving the goal with the workspace's
// operators) -> formats (segbrain(1)).
#include "commands.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "core/stopwatch.hpp"
#include "core/threads.hpp"
#include "core/tool_main.hpp"
#include "knowledge_base.hpp"
#include "segbrain/canonical.hpp"
#include "segbrain/engine.hpp"
#include "segbrain/kb_parser.hpp"
#include "segbrain/parallel.hpp"
#include "segbrain/workspace.hpp"
#include "volume_files.hpp"

namespace fest::segbrain_tool {

using namespace fest::segbrain;
using nlohmann::json;

const char* modality_name(Modality m) {
  switch (m) {
    case Modality::t2: return "t2";
    case Modality::pd: return "pd";
    case Modality::t1: break;
  }
  return "t1";
}

namespace {

constexpr const char* kTool = "segbrain";

// The knowledge base's atoms that `pred(X)` holds for, "a, b, c" (empty if none).
std::string known_atoms(Engine& engine, const char* pred) {
  std::string known;
  Term all = make_var("L"), x = make_var("X");
  if (!engine.prove(make_compound("findall", {x, make_compound(pred, {x}), all}))) return known;
  std::vector<Term> items;
  list_items(deref(all), items);
  for (const auto& it : items) known += (known.empty() ? "" : ", ") + to_string(it);
  return known;
}

// --set NAME=VALUE (segbrain(1)): candidates/2 and limit/2 facts are replaced by
// name; any other NAME/1 predicate is replaced by the single fact NAME(VALUE).
void apply_set(Engine& engine, const FactSetting& s) {
  const std::string& name = s.name;
  Term value;
  try {
    value = parse_term(s.value, "--set " + name);
  } catch (const Error& e) {
    throw usage_error("{}", e.what());
  }
  engine.set_param(name, value);
  Term key = make_atom(name);
  bool replaced = false;
  for (const char* table : {"candidates", "limit"}) {
    Term goal = make_compound(table, {key, make_var()});
    if (engine.defines(table, 2) && engine.prove(make_compound("once", {goal}))) {
      // Put the override first and cut the others away with a guard clause pair.
      Clause c;
      c.head = make_compound(table, {key, value});
      c.body = make_atom("!");
      c.file = "--set";
      engine.add_clause(c, true);
      replaced = true;
    }
  }
  if (!replaced && engine.defines(name, 1)) {
    engine.remove_predicate(name, 1);
    Clause c;
    c.head = make_compound(name, {value});
    c.body = make_atom("true");
    c.file = "--set";
    engine.add_clause(c);
    replaced = true;
  }
  if (!replaced) throw usage_error("--set {}: the knowledge base has no candidates/2, limit/2 or {}/1 fact of that name", name, name);
}

// --modality M (segbrain(1)): the knowledge base says which contrasts its rules
// are written for (supported_modality/1; a KB without those facts is taken as T1-only)
// and reads the one asked for from modality/1.
void apply_modality(Engine& engine, Modality modality) {
  const std::string m = modality_name(modality);
  Term t = make_atom(m);
  const bool declared = engine.defines("supported_modality", 1);
  if (declared ? !engine.prove(make_compound("supported_modality", {t})) : m != "t1") {
    const std::string known = declared ? known_atoms(engine, "supported_modality") : "t1";
    throw usage_error("--modality {}: the knowledge base's rules are written for {} only; give rules for {} with --kb", m, known, m);
  }
  if (engine.defines("modality", 1)) {
    engine.remove_predicate("modality", 1);
    Clause c;
    c.head = make_compound("modality", {t});
    c.body = make_atom("true");
    c.file = "--modality";
    engine.add_clause(c);
  }
}

// --objects a,b,c -> segment_objects([a, b, c]); every name must be a known_object/1
// fact of the knowledge base (which objects it can find is knowledge, not code).
Term objects_goal(Engine& engine, const std::vector<std::string>& objects) {
  std::vector<Term> names;
  for (const std::string& name : objects) {
    Term t = make_atom(name);
    if (!engine.defines("known_object", 1) || !engine.prove(make_compound("known_object", {t}))) {
      const std::string known = engine.defines("known_object", 1) ? known_atoms(engine, "known_object") : "";
      throw usage_error("--objects: the knowledge base has no rules for '{}' (it knows: {})", name, known.empty() ? "none" : known);
    }
    names.push_back(t);
  }
  return make_compound("segment_objects", {make_list(names)});
}

// Label volume in the input's voxel order and geometry.
Volume label_volume(const Volume& in, const Reorientation& r, const std::vector<std::uint16_t>& labels) {
  std::vector<double> canon(labels.begin(), labels.end());
  Volume out = in;
  out.voxels = from_canonical(canon, in, r);
  std::uint16_t mx = 0;
  for (auto l : labels) mx = std::max(mx, l);
  out.type = mx > 255 ? ScalarType::u16 : ScalarType::u8;
  return out;
}

json trace_json(const TraceEvent& e) {
  json j = {{"t_ms", std::round(e.t_ms * 1000) / 1000}, {"port", e.port}, {"depth", e.depth},
            {"goal", e.goal}, {"clause", e.clause}};
  if (e.dur_ms >= 0) j["dur_ms"] = std::round(e.dur_ms * 1000) / 1000;
  if (!e.measure.empty()) {
    json m = json::object();
    for (const auto& [k, v] : e.measure) m[k] = v;
    j["measure"] = m;
  }
  return j;
}

// The report's "objects": each emitted object's label, size, centroid (world RAS mm
// through the input's own geometry) and canonical bounding box.
json objects_json(const Workspace& ws, const Grid& grid, const Volume& in, const Reorientation& ro) {
  json objs = json::object();
  for (const auto& em : ws.emitted()) {
    const Mask& m = ws.mask(em.object);
    std::size_t n = 0;
    double c[3] = {0, 0, 0};
    std::array<std::size_t, 3> lo{grid.n}, hi{0, 0, 0};
    for (std::size_t z = 0; z < grid.n[2]; ++z)
      for (std::size_t y = 0; y < grid.n[1]; ++y)
        for (std::size_t x = 0; x < grid.n[0]; ++x)
          if (m[grid.index(x, y, z)]) {
            ++n;
            c[0] += x, c[1] += y, c[2] += z;
            std::array<std::size_t, 3> p{x, y, z};
            for (int ax = 0; ax < 3; ++ax) lo[ax] = std::min(lo[ax], p[ax]), hi[ax] = std::max(hi[ax], p[ax]);
          }
    json o = {{"label", em.label}, {"voxels", n}, {"volume_ml", double(n) * grid.voxel_ml()}};
    if (n) {
      std::array<double, 3> src{};
      for (int ax = 0; ax < 3; ++ax) {
        double ci = c[ax] / double(n);
        src[ro.source_axis[ax]] = ro.flip[ax] ? double(grid.n[ax] - 1) - ci : ci;
      }
      o["centroid_mm"] = in.world(src[0], src[1], src[2]);
      o["bbox_canonical"] = {lo, hi};
    }
    objs[em.object] = o;
  }
  return objs;
}

// The knowledge base with the run's settings (--set, --modality, --tissue) in the engine,
// and the goal to prove (--goal, or segment_objects of --objects).
Term prepare_engine(Engine& engine, const RunArgs& a) {
  for (const auto& p : load_kb(a.kb)) engine.consult(p);
  for (const auto& s : a.sets) apply_set(engine, s);
  apply_modality(engine, a.modality);
  if (a.tissue) {
    if (!engine.defines("tissue_classification", 0))
      throw usage_error("--tissue: the knowledge base has no tissue classification (no tissue_classification/0)");
    Clause c;
    c.head = make_atom("tissue_classification");
    c.body = make_atom("true");
    c.file = "--tissue";
    engine.add_clause(c);
  }
  Term goal;
  try {
    goal = parse_term(a.goal, "--goal");
  } catch (const Error& e) {
    throw usage_error("{}", e.what());
  }
  if (!a.objects.empty()) goal = objects_goal(engine, a.objects);
  return goal;
}

// What the knowledge base found the volume to hold and what it left out (docs/segbrain.md
// §1): scene/1, scene_note(Level, Text) and skipped_object(Object, Reason) facts.
struct SceneReport {
  std::string scene;                                           // whole_head, brain_only, partial; "" if none
  std::vector<std::pair<std::string, std::string>> notes;      // level, text
  std::vector<std::pair<std::string, std::string>> skipped;    // object, reason
  // One line: the notes of the given levels, then the skipped objects grouped by reason.
  std::string line(bool with_info) const {
    std::string out;
    auto add = [&out](const std::string& s) { out += (out.empty() ? "" : "; ") + s; };
    for (const auto& [level, text] : notes)
      if (with_info || level != "info") add(text);
    std::vector<std::string> reasons;
    for (const auto& sk : skipped)
      if (std::find(reasons.begin(), reasons.end(), sk.second) == reasons.end()) reasons.push_back(sk.second);
    for (const auto& why : reasons) {
      std::string objs;
      for (const auto& [obj, r] : skipped)
        if (r == why) objs += (objs.empty() ? "" : ", ") + obj;
      add(objs + " not sought: " + why);
    }
    return out;
  }
};

std::string term_text(const Term& t) {
  Term d = deref(t);
  return d->kind == Kind::atom || d->kind == Kind::string ? d->name : to_string(d);
}

// All solutions of Goal's arguments (a findall over the dynamic facts).
std::vector<std::vector<std::string>> facts_of(Engine& engine, const char* pred, std::size_t arity) {
  std::vector<std::vector<std::string>> out;
  if (!engine.defines(pred, static_cast<int>(arity))) return out;
  std::vector<Term> vars;
  for (std::size_t i = 0; i < arity; ++i) vars.push_back(make_var());
  Term all = make_var("L");
  if (!engine.prove(make_compound("findall", {make_list(vars), make_compound(pred, vars), all}))) return out;
  std::vector<Term> items;
  list_items(deref(all), items);
  for (const auto& it : items) {
    std::vector<Term> args;
    list_items(deref(it), args);
    std::vector<std::string> row;
    for (const auto& x : args) row.push_back(term_text(x));
    out.push_back(row);
  }
  return out;
}

SceneReport scene_report(Engine& engine) {
  SceneReport r;
  for (const auto& f : facts_of(engine, "scene", 1)) r.scene = f[0];
  for (const auto& f : facts_of(engine, "scene_note", 2)) r.notes.emplace_back(f[0], f[1]);
  for (const auto& f : facts_of(engine, "skipped_object", 2)) r.skipped.emplace_back(f[0], f[1]);
  return r;
}


// The find_<object> goals named anywhere in the bodies of the goal's clauses (inside
// optional/1 and if-then-else too): the steps of --progress.
std::set<std::string> find_goals(const std::vector<Program>& kb, const Term& goal) {
  std::set<std::string> out;
  const std::string top = deref(goal)->name;
  std::function<void(const Term&)> walk = [&](const Term& t0) {
    const Term t = deref(t0);
    if (t->kind != Kind::atom && t->kind != Kind::compound) return;
    if (t->name.rfind("find_", 0) == 0) out.insert(t->name);
    for (const Term& arg : t->args) walk(arg);
  };
  for (const Program& p : kb)
    for (const Clause& c : p.clauses)
      if (deref(c.head)->name == top) walk(c.body);
  return out;
}

}  // namespace

int run_segment(const RunArgs& a) {
  const Stopwatch clock;
  set_worker_threads(resolve_threads(a.threads));
#ifdef __GLIBC__
  // The operators allocate and free volume-sized arrays (7-60 MB) a hundred times per
  // run. glibc would map each afresh and the kernel fault in and zero every page again
  // (a third of the CPU time on Colin27); kept in the heap, freed blocks are reused.
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
  Engine engine;
  const Term goal = prepare_engine(engine, a);
  const std::vector<LabelEntry> table = label_entries(engine);

  Volume in = read_volume_input(a.input, "segbrain");
  if (in.size() == 0) throw bad_input("volume has no voxels ({})", a.input);
  std::size_t bad = 0;
  for (auto& v : in.voxels)
    if (!std::isfinite(v)) {
      ++bad;
      v = 0;
    }
  if (bad == in.size()) throw bad_input("every voxel is NaN or infinite ({})", a.input);
  if (bad && !a.quiet) warn(kTool, fmt::format("{} non-finite voxels read as 0", bad));
  Reorientation ro = find_reorientation(in);
  if (ro.obliquity_deg > 20 && !a.quiet)
    warn(kTool, fmt::format("volume is oblique ({:.1f} degrees); axes are taken as the nearest anatomical ones", ro.obliquity_deg));
  Grid grid = canonical_grid(in, ro);
  for (int ax = 0; ax < 3; ++ax)
    if (grid.n[ax] < 3) throw bad_input("volume of {}x{}x{} voxels: segbrain needs a 3-D head ({})", in.dims[0], in.dims[1], in.dims[2], a.input);

  Workspace ws(grid);
  Object t1;
  t1.image = to_canonical(in, ro);
  ws.put_root("t1", std::move(t1));
  ws.register_operators(engine);
  // --progress: the steps of the proof are the find_<object> goals its clauses name, each
  // counted once when it exits or fails (an optional object the knowledge base skips).
  const bool progress = progress_wanted(a.progress);
  const std::set<std::string> finds = progress ? find_goals(load_kb(a.kb), goal) : std::set<std::string>{};
  Progress bar("segbrain", finds.size(), progress);
  std::set<std::string> finds_done;

  std::string trace_text;
  if (!a.trace.empty() || progress)
    engine.set_trace([&](const TraceEvent& e) {
      if (!a.trace.empty()) trace_text += trace_json(e).dump() + "\n";
      if (progress && std::strcmp(e.port, "call") != 0 && std::strcmp(e.port, "redo") != 0) {
        const std::string name = e.goal.substr(0, e.goal.find('('));
        if (finds.count(name) && finds_done.insert(name).second) bar.set(finds_done.size());
      }
    });
  engine.set_log([&](const std::string& s) {
    if (!a.quiet) std::fputs(s.c_str(), stderr);
  });
  Limits lim;
  lim.max_depth = a.max_depth;
  lim.max_inferences = static_cast<std::uint64_t>(a.max_inferences);
  lim.time_limit_s = a.time_limit;
  engine.set_limits(lim);

  bool ok = false;
  std::string failure;
  try {
    ok = engine.prove(goal);
  } catch (const Error& e) {
    if (!a.trace.empty()) write_output(a.trace, trace_text);
    throw;
  }
  if (!a.trace.empty()) write_output(a.trace, trace_text);
  if (ok) bar.finish();
  if (!ok) {
    failure = fmt::format("goal {} failed after {} alternatives", to_string(goal), engine.counters().backtracks);
    if (!engine.last_failing_check().empty()) failure += "; last failing check: " + engine.last_failing_check();
  }

  const SceneReport scene = scene_report(engine);
  if (!a.quiet) {
    const std::string line = scene.line(a.verbose);
    if (!line.empty()) std::fprintf(stderr, "%s: %s\n", kTool, line.c_str());
  }
  std::vector<std::uint16_t> labels = assemble_labels(ws);
  if (!a.report.empty()) {
    json rep;
    rep["input"] = {{"file", a.input}, {"dims", in.dims}, {"spacing", in.spacing}, {"datatype", scalar_type_name(in.type)},
                    {"orientation", ro.code}, {"obliquity_deg", ro.obliquity_deg}};
    rep["goal"] = to_string(goal);
    rep["proved"] = ok;
    if (!ok) rep["failure"] = failure;
    rep["objects"] = objects_json(ws, grid, in, ro);
    json labs = json::array();
    for (const auto& l : table) labs.push_back({{"index", l.index}, {"name", l.name}, {"parent", l.parent}, {"rgb", l.rgb}});
    rep["labels"] = labs;
    if (!scene.scene.empty()) rep["scene"] = scene.scene;
    rep["skull_stripped_input"] = scene.scene == "brain_only";
    json notes = json::array(), not_sought = json::array();
    for (const auto& [level, text] : scene.notes) notes.push_back({{"level", level}, {"text", text}});
    for (const auto& [obj, why] : scene.skipped) not_sought.push_back({{"object", obj}, {"reason", why}});
    rep["notes"] = notes;
    rep["not_sought"] = not_sought;
    rep["summary"] = scene.line(true);
    rep["accepted_by"] = engine.accepted_by();
    rep["skipped"] = engine.skipped();
    rep["counts"] = {{"inferences", engine.counters().inferences}, {"backtracks", engine.counters().backtracks},
                     {"operator_calls", engine.counters().foreign_calls}, {"cache_hits", ws.memo_hits()}};
    rep["wall_s"] = clock.seconds();
    write_output(a.report, rep.dump(2) + "\n");
  }
  if (!ok) throw runtime_failure("{}", failure);
  if (!a.label_table.empty()) {
    std::string text = "# segbrain label table (index name R G B A); parents in the JSON report\n";
    for (const auto& l : table) text += fmt::format("{} {} {} {} {} 255\n", l.index, l.name, l.rgb[0], l.rgb[1], l.rgb[2]);
    write_output(a.label_table, text);
  }
  if (!a.masks.empty()) {
    std::set<std::string> written;
    for (const auto& em : ws.emitted()) {
      if (!written.insert(em.object).second) continue;
      const Mask& m = ws.mask(em.object);
      write_volume_output(label_volume(in, ro, std::vector<std::uint16_t>(m.begin(), m.end())),
                          a.masks + "/" + em.object + ".nii.gz", std::nullopt);
    }
  }
  write_volume_output(label_volume(in, ro, labels), a.output, a.to);
  return 0;
}

}  // namespace fest::segbrain_tool

// Subcommands: formats -> lib/segbrain -> formats.
#include "commands.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <map>
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/threads.hpp"
#include "core/tool_main.hpp"
#include "formats/input.hpp"
#include "formats/volume/volume_io.hpp"
#include "segbrain/canonical.hpp"
#include "segbrain/engine.hpp"
#include "segbrain/kb_parser.hpp"
#include "segbrain/measures.hpp"
#include "segbrain/morphology.hpp"
#include "segbrain/parallel.hpp"
#include "segbrain/phantom.hpp"
#include "segbrain/workspace.hpp"

namespace segbrain_tool {

using namespace fest;
using namespace fest::segbrain;
using nlohmann::json;

namespace {

constexpr const char* kTool = "segbrain";

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

// --set NAME=VALUE (spec §4): candidates/2 and limit/2 facts are replaced by name; any
// other NAME/1 predicate is replaced by the single fact NAME(VALUE).
void apply_set(Engine& engine, const std::string& s) {
  auto eq = s.find('=');
  if (eq == std::string::npos || eq == 0) throw usage_error("--set expects NAME=VALUE, got '{}'", s);
  std::string name = s.substr(0, eq);
  Term value;
  try {
    value = parse_term(s.substr(eq + 1), "--set " + name);
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

// --modality M (spec §4): the knowledge base says which contrasts its rules are written
// for (supported_modality/1; a KB without those facts is taken as T1-only) and reads the
// one asked for from modality/1.
void apply_modality(Engine& engine, const std::string& m) {
  Term t = make_atom(m);
  const bool declared = engine.defines("supported_modality", 1);
  if (declared ? !engine.prove(make_compound("supported_modality", {t})) : m != "t1") {
    std::string known = "t1";
    if (declared) {
      known.clear();
      Term all = make_var("L"), x = make_var("X");
      engine.prove(make_compound("findall", {x, make_compound("supported_modality", {x}), all}));
      std::vector<Term> items;
      list_items(deref(all), items);
      for (const auto& it : items) known += (known.empty() ? "" : ", ") + to_string(it);
    }
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

Volume read_volume_input(const std::string& path) {
  formats::Input in = formats::load_input(path);
  if (formats::kind_of(in.format) != formats::Kind::volume)
    throw bad_input("expected a volume (NIfTI, NRRD, MHA), got {} ({})", formats::format_name(in.format), in.name);
  Volume v = formats::parse(in, formats::read_volume);
  v.require_3d(fmt::format("segbrain ({})", in.name).c_str());
  return v;
}

void write_volume_output(const Volume& v, const std::string& path, const std::string& to) {
  formats::OutputFormat of{formats::Format::nifti, false};
  if (!to.empty()) of = formats::output_format_from_name(to);
  else if (!is_stdio(path)) of = formats::output_format_from_path(path);
  if (formats::kind_of(of.format) != formats::Kind::volume) throw usage_error("--to: not a volume format");
  formats::store_volume(path, v, of);
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

// --objects a,b,c -> segment_objects([a, b, c]); every name must be a known_object/1
// fact of the knowledge base (which objects it can find is knowledge, not code).
Term objects_goal(Engine& engine, const std::string& list) {
  std::vector<Term> names;
  std::size_t pos = 0;
  while (pos <= list.size()) {
    std::size_t comma = list.find(',', pos);
    std::string name = list.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
    if (name.empty()) throw usage_error("--objects: empty object name in '{}'", list);
    Term t = make_atom(name);
    if (!engine.defines("known_object", 1) || !engine.prove(make_compound("known_object", {t}))) {
      std::string known;
      Term all = make_var("L"), x = make_var("X");
      if (engine.defines("known_object", 1) &&
          engine.prove(make_compound("findall", {x, make_compound("known_object", {x}), all}))) {
        std::vector<Term> items;
        list_items(deref(all), items);
        for (const auto& it : items) known += (known.empty() ? "" : ", ") + to_string(it);
      }
      throw usage_error("--objects: the knowledge base has no rules for '{}' (it knows: {})", name, known.empty() ? "none" : known);
    }
    names.push_back(t);
    if (comma == std::string::npos) break;
    pos = comma + 1;
  }
  return make_compound("segment_objects", {make_list(names)});
}

// label(Index, Name, Parent, [R, G, B]) facts of the knowledge base, in file order.
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

}  // namespace

int run_segment(const RunArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  set_worker_threads(resolve_threads(a.threads));
#ifdef __GLIBC__
  // The operators allocate and free volume-sized arrays (7-60 MB) a hundred times per
  // run. glibc would map each afresh and the kernel fault in and zero every page again
  // (a third of the CPU time on Colin27); kept in the heap, freed blocks are reused.
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
  Engine engine;
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
  const std::vector<LabelEntry> table = label_entries(engine);

  Volume in = read_volume_input(a.input);
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

  std::string trace_text;
  if (!a.trace.empty()) engine.set_trace([&](const TraceEvent& e) { trace_text += trace_json(e).dump() + "\n"; });
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
  if (!ok) {
    failure = fmt::format("goal {} failed after {} alternatives", to_string(goal), engine.counters().backtracks);
    if (!engine.last_failing_check().empty()) failure += "; last failing check: " + engine.last_failing_check();
  }

  std::vector<std::uint16_t> labels = assemble_labels(ws);
  if (!a.report.empty()) {
    json rep;
    rep["input"] = {{"file", a.input}, {"dims", in.dims}, {"spacing", in.spacing}, {"datatype", scalar_type_name(in.type)},
                    {"orientation", ro.code}, {"obliquity_deg", ro.obliquity_deg}};
    rep["goal"] = to_string(goal);
    rep["proved"] = ok;
    if (!ok) rep["failure"] = failure;
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
        // Centroid in world RAS mm through the input's own geometry.
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
    rep["objects"] = objs;
    json labs = json::array();
    for (const auto& l : table) labs.push_back({{"index", l.index}, {"name", l.name}, {"parent", l.parent}, {"rgb", l.rgb}});
    rep["labels"] = labs;
    rep["accepted_by"] = engine.accepted_by();
    rep["skipped"] = engine.skipped();
    rep["counts"] = {{"inferences", engine.counters().inferences}, {"backtracks", engine.counters().backtracks},
                     {"operator_calls", engine.counters().foreign_calls}, {"cache_hits", ws.memo_hits()}};
    rep["wall_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
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
                          a.masks + "/" + em.object + ".nii.gz", "");
    }
  }
  write_volume_output(label_volume(in, ro, labels), a.output, a.to);
  return 0;
}

std::vector<LabelEntry> kb_labels(const std::vector<std::string>& kb) {
  Engine engine;
  for (const auto& p : load_kb(kb)) engine.consult(p);
  return label_entries(engine);
}

int run_kb_check(const KbCheckArgs& a) {
  Engine engine;
  Grid g;
  g.n = {3, 3, 3};
  Workspace ws(g);
  ws.register_operators(engine);
  std::vector<Program> progs = load_kb(a.files);
  std::size_t problems = 0;
  for (const auto& p : progs) {
    engine.consult(p);
    for (const auto& c : p.clauses)
      for (const auto& s : c.singletons) std::printf("%s:%d: warning: singleton variable %s\n", c.file.c_str(), c.line, s.c_str());
  }
  for (const auto& [pred, where] : engine.undefined_calls()) {
    std::printf("%s: error: unknown predicate %s\n", where.c_str(), pred.c_str());
    ++problems;
  }
  if (problems) throw bad_input("{} unknown predicate call(s) in the knowledge base", problems);
  return 0;
}

int run_ops(bool as_json) {
  Engine engine;
  Grid g;
  g.n = {3, 3, 3};
  Workspace ws(g);
  ws.register_operators(engine);
  json j = json::array();
  std::string text;
  for (const auto& [name, info] : engine.foreigns()) {
    j.push_back({{"predicate", name}, {"modes", info.modes}, {"doc", info.doc}});
    text += fmt::format("{:<28} {:<40} {}\n", name, "(" + info.modes + ")", info.doc);
  }
  write_output("-", as_json ? j.dump(2) + "\n" : text);
  return 0;
}

namespace {

template <typename T, std::size_t N>
std::array<T, N> parse_triple(const std::string& s, const char* option) {
  std::array<T, N> out{};
  std::size_t pos = 0;
  for (std::size_t i = 0; i < N; ++i) {
    std::size_t comma = s.find(',', pos);
    std::string part = s.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
    try {
      std::size_t used = 0;
      double v = std::stod(part, &used);
      if (used != part.size() || !(v > 0)) throw std::invalid_argument("x");
      out[i] = static_cast<T>(v);
    } catch (const std::exception&) {
      throw usage_error("{} expects {} positive numbers separated by commas, got '{}'", option, N, s);
    }
    if (i + 1 < N) {
      if (comma == std::string::npos) throw usage_error("{} expects {} numbers, got '{}'", option, N, s);
      pos = comma + 1;
    } else if (comma != std::string::npos) {
      throw usage_error("{} expects {} numbers, got '{}'", option, N, s);
    }
  }
  return out;
}

Volume grid_volume(const Grid& g) {
  Volume v;
  v.resize(g.n[0], g.n[1], g.n[2]);
  v.spacing = g.spacing;
  for (int a = 0; a < 3; ++a) v.origin[a] = -0.5 * double(g.n[a] - 1) * g.spacing[a];
  return v;
}

// "brain=3,4,6-8;csf=2" -> name -> set of label values. Empty text: one object "object"
// of every nonzero value.
std::vector<std::pair<std::string, std::vector<std::pair<double, double>>>> parse_map(const std::string& text, const char* option) {
  std::vector<std::pair<std::string, std::vector<std::pair<double, double>>>> out;
  if (text.empty()) {
    out.push_back({"object", {{1, INFINITY}}});
    return out;
  }
  std::size_t pos = 0;
  while (pos <= text.size()) {
    std::size_t semi = text.find(';', pos);
    std::string item = text.substr(pos, semi == std::string::npos ? std::string::npos : semi - pos);
    auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0) throw usage_error("{}: expected name=values, got '{}'", option, item);
    std::vector<std::pair<double, double>> ranges;
    std::string vals = item.substr(eq + 1);
    std::size_t p = 0;
    while (p <= vals.size()) {
      std::size_t comma = vals.find(',', p);
      std::string v = vals.substr(p, comma == std::string::npos ? std::string::npos : comma - p);
      auto dash = v.find('-', 1);
      try {
        if (dash == std::string::npos) ranges.push_back({std::stod(v), std::stod(v)});
        else ranges.push_back({std::stod(v.substr(0, dash)), std::stod(v.substr(dash + 1))});
      } catch (const std::exception&) {
        throw usage_error("{}: bad label value '{}'", option, v);
      }
      if (comma == std::string::npos) break;
      p = comma + 1;
    }
    out.push_back({item.substr(0, eq), ranges});
    if (semi == std::string::npos) break;
    pos = semi + 1;
  }
  return out;
}

Mask select(const Volume& v, const std::vector<std::pair<double, double>>& ranges) {
  Mask m(v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    for (const auto& [lo, hi] : ranges)
      if (v.voxels[i] >= lo && v.voxels[i] <= hi) {
        m[i] = 1;
        break;
      }
  return m;
}

bool same_grid(const Volume& a, const Volume& b) {
  if (a.dims != b.dims) return false;
  for (int i = 0; i < 3; ++i)
    if (std::abs(a.spacing[i] - b.spacing[i]) > 1e-4 || std::abs(a.origin[i] - b.origin[i]) > 1e-3) return false;
  for (int i = 0; i < 9; ++i)
    if (std::abs(a.direction[i] - b.direction[i]) > 1e-5) return false;
  return true;
}

// The reference on the segmentation's grid: each voxel takes the value of the reference
// voxel nearest to its world position (0 outside the reference), so label volumes of
// other voxel sizes, orientations or fields of view compare by anatomy (spec §4 eval).
Volume resample_nearest(const Volume& ref, const Volume& grid) {
  // Inverse of world = origin + D diag(s) ijk.
  double m[9];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m[3 * r + c] = ref.direction[3 * r + c] * ref.spacing[c];
  const double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
  if (std::abs(det) < 1e-12) throw bad_input("the reference's voxel axes are degenerate");
  const double inv[9] = {(m[4] * m[8] - m[5] * m[7]) / det, (m[2] * m[7] - m[1] * m[8]) / det, (m[1] * m[5] - m[2] * m[4]) / det,
                         (m[5] * m[6] - m[3] * m[8]) / det, (m[0] * m[8] - m[2] * m[6]) / det, (m[2] * m[3] - m[0] * m[5]) / det,
                         (m[3] * m[7] - m[4] * m[6]) / det, (m[1] * m[6] - m[0] * m[7]) / det, (m[0] * m[4] - m[1] * m[3]) / det};
  Volume out = grid;
  out.type = ref.type;
  for (std::size_t k = 0; k < grid.dims[2]; ++k)
    for (std::size_t j = 0; j < grid.dims[1]; ++j)
      for (std::size_t i = 0; i < grid.dims[0]; ++i) {
        auto w = grid.world(double(i), double(j), double(k));
        const double d[3] = {w[0] - ref.origin[0], w[1] - ref.origin[1], w[2] - ref.origin[2]};
        double v = 0;
        long long p[3];
        bool inside = true;
        for (int r = 0; r < 3; ++r) {
          p[r] = std::llround(inv[3 * r] * d[0] + inv[3 * r + 1] * d[1] + inv[3 * r + 2] * d[2]);
          inside = inside && p[r] >= 0 && p[r] < static_cast<long long>(ref.dims[r]);
        }
        if (inside) v = ref.at(std::size_t(p[0]), std::size_t(p[1]), std::size_t(p[2]));
        out.at(i, j, k) = v;
      }
  return out;
}

}  // namespace

int run_synth(const SynthArgs& a) {
  PhantomOptions o;
  o.size = parse_triple<std::size_t, 3>(a.size, "--size");
  o.spacing = parse_triple<double, 3>(a.spacing, "--spacing");
  if (a.noise < 0 || a.bias < 0) throw usage_error("--noise and --bias must be >= 0");
  o.noise = a.noise;
  o.bias = a.bias;
  o.seed = a.seed;
  Phantom p = make_phantom(o);
  Volume img = grid_volume(p.grid);
  img.type = ScalarType::f32;
  img.voxels.assign(p.t1.begin(), p.t1.end());
  Volume truth = grid_volume(p.grid);
  truth.type = ScalarType::u8;
  truth.voxels.assign(p.truth.begin(), p.truth.end());
  write_volume_output(img, a.output, "");
  write_volume_output(truth, a.truth, "");
  return 0;
}

int run_eval(const EvalArgs& a) {
  Volume ref = read_volume_input(a.ref);
  Volume seg = read_volume_input(a.seg);
  if (!same_grid(ref, seg)) ref = resample_nearest(ref, seg);
  auto smap = parse_map(a.map, "--map");
  auto rmap = parse_map(a.ref_map.empty() ? a.map : a.ref_map, "--ref-map");
  std::string out = "object\tdice\tjaccard\tvolume_seg_ml\tvolume_ref_ml\tvolume_diff_pct\n";
  const double ml = seg.spacing[0] * seg.spacing[1] * seg.spacing[2] / 1000.0;
  for (const auto& [name, ranges] : smap) {
    auto it = std::find_if(rmap.begin(), rmap.end(), [&](const auto& r) { return r.first == name; });
    if (it == rmap.end()) throw usage_error("--ref-map has no object '{}'", name);
    Mask s = select(seg, ranges), r = select(ref, it->second);
    double d = dice(s, r);
    double vs = double(count(s)) * ml, vr = double(count(r)) * ml;
    out += fmt::format("{}\t{:.4f}\t{:.4f}\t{:.2f}\t{:.2f}\t{:.2f}\n", name, d, d / (2 - d), vs, vr,
                       vr > 0 ? 100 * (vs - vr) / vr : 0.0);
  }
  write_output("-", out);
  return 0;
}

}  // namespace segbrain_tool

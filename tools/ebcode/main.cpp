// ebcode: triangle mesh -> .ebm (Edgebreaker connectivity with the chapter's
// conditional-unity coder, quantised parallelogram-predicted positions), or Draco for
// comparison; `ebcode model` prints the chapter's state machines.
//
// Wiring only: formats/ reads the mesh, lib/edgebreaker codes it.

#include <chrono>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>


#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <OpenMesh/Core/System/omstream.hh>

#include "cli/cli.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/resources.hpp"
#include "core/tool_main.hpp"
#include "edgebreaker/ebm.hpp"
#include "edgebreaker/state_machine.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "mesh_soup.hpp"

namespace {

using namespace fest;
using namespace fest::edgebreaker;
using Clock = std::chrono::steady_clock;

struct Options {
  std::string input = "-";
  std::string output = "-";
  std::string conn = "auto";
  std::string model = "m236";
  int qp = 14;
  int qn = 10;
  int qt = 12;
  std::string box;
  std::string predict = "para";
  bool no_stitch = false;
  bool drop_isolated = false;
  bool no_geometry = false;
  bool strict = false;
  std::string to = "ebm";
  int draco_cl = 7;
  std::string report;
  bool symbols = false;
  bool no_verify = false;
  int ebm_version = 2;
  bool quiet = false;
};

struct ModelOptions {
  std::string model;
  int lmax = -1, pmax = -1, smax = -1, cmax = 19;
  bool all_patterns = false;
  bool literal = false;
  std::string to = "tsv";
};

double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

std::array<float, 4> parse_box(const std::string& text) {
  std::array<float, 4> box{};
  std::stringstream in(text);
  std::string item;
  std::size_t k = 0;
  while (std::getline(in, item, ',')) {
    if (k == 4) throw usage_error("--box takes four numbers X,Y,Z,EXT");
    try {
      std::size_t used = 0;
      box[k] = std::stof(item, &used);
      if (used != item.size() || !std::isfinite(box[k])) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw usage_error("--box: '{}' is not a number", item);
    }
    ++k;
  }
  if (k != 4) throw usage_error("--box takes four numbers X,Y,Z,EXT");
  if (box[3] < 0) throw usage_error("--box: the extent must be >= 0");
  return box;
}

Predictor parse_predictor(const std::string& name) {
  if (name == "para") return Predictor::parallelogram;
  if (name == "delta") return Predictor::delta;
  if (name == "none") return Predictor::none;
  if (name == "multi") return Predictor::multi;
  throw usage_error("--predict: unknown predictor '{}' (para, multi, delta, none)", name);
}

ConnChoice parse_conn(const std::string& name) {
  if (name == "auto") return ConnChoice::automatic;
  if (name == "static") return ConnChoice::static_model;
  if (name == "adaptive") return ConnChoice::adaptive;
  if (name == "raw") return ConnChoice::raw;
  throw usage_error("--conn: unknown coder '{}' (auto, static, adaptive, raw)", name);
}

int encode(const Options& opt) {
  const Clock::time_point t0 = Clock::now();
  const formats::Input in = formats::load_input(opt.input);
  if (formats::kind_of(in.format) != formats::Kind::mesh)
    throw bad_input("{} input is not a mesh ({})", formats::format_name(in.format), in.name);
  const Mesh mesh = formats::parse(in, formats::read_mesh);
  const MeshSoup soup = tools::to_soup(mesh);
  const double read_ms = ms_since(t0);
  if (soup.positions.empty()) throw bad_input("the mesh is empty ({})", in.name);
  if (!opt.quiet && (mesh.has_face_colors() || mesh.has_face_normals()))
    warn("ebcode", "face colours and normals are not coded; vertex attributes are");

  if (opt.symbols) {
    write_output(opt.output, to_string(mesh_symbols(soup, opt.strict)) + "\n");
    return 0;
  }
  if (opt.to == "drc") {
    formats::MeshWriteOptions w;
    w.draco_position_bits = opt.qp;
    w.draco_speed = 10 - opt.draco_cl;
    formats::store_output(opt.output, formats::write_mesh(mesh, formats::Format::drc, w), false);
    return 0;
  }
  if (opt.to != "ebm") throw usage_error("--to: unknown output '{}' (ebm, drc)", opt.to);

  EncodeOptions e;
  e.conn = parse_conn(opt.conn);
  e.model_id = named_model(opt.model).id;
  e.qp = opt.qp;
  e.qn = opt.qn;
  e.qt = opt.qt;
  if (!opt.box.empty()) e.box = parse_box(opt.box);
  e.predictor = parse_predictor(opt.predict);
  e.stitch = !opt.no_stitch;
  e.drop_isolated = opt.drop_isolated;
  e.geometry = !opt.no_geometry;
  e.strict = opt.strict;
  e.verify = !opt.no_verify;
  e.version = opt.ebm_version;
  EncodeStats stats;
  const Clock::time_point t1 = Clock::now();
  const std::string bytes = encode_ebm(soup, e, &stats);
  const double encode_ms = ms_since(t1);
  const Clock::time_point t2 = Clock::now();
  write_output(opt.output, bytes);
  const double write_ms = ms_since(t2);

  if (!opt.report.empty()) {
    const double v = static_cast<double>(stats.input_vertices);
    const auto bpv = [&](std::size_t b) { return v > 0 ? 8.0 * static_cast<double>(b) / v : 0.0; };
    nlohmann::json r;
    r["input"] = in.name;
    r["vertices"] = stats.input_vertices;
    r["faces"] = stats.input_faces;
    r["components"] = stats.components;
    r["genus"] = stats.genus_sum;
    r["holes"] = stats.holes;
    r["events"] = stats.events;
    r["stitch"] = stats.stitch;
    r["isolated"] = stats.isolated;
    r["dropped_degenerate"] = stats.dropped_degenerate;
    r["symbols"] = {{"C", stats.histogram[0]}, {"L", stats.histogram[1]}, {"E", stats.histogram[2]},
                    {"R", stats.histogram[3]}, {"S", stats.histogram[4]}};
    r["conn_mode"] = stats.conn_mode;
    r["model"] = stats.conn_mode == "static" ? opt.model : "";
    r["qp"] = opt.qp;
    nlohmann::json sections = nlohmann::json::object();
    for (const auto& [tag, n] : stats.section_bytes) sections[tag] = {{"bytes", n}, {"bits", 8 * n}};
    r["sections"] = sections;
    const auto section = [&](const char* tag) {
      const auto it = stats.section_bytes.find(tag);
      return it == stats.section_bytes.end() ? std::size_t{0} : it->second;
    };
    r["total_bytes"] = stats.total_bytes;
    r["bpv"] = {{"connectivity", bpv(section("CONN"))},
                {"geometry", bpv(section("GEOM"))},
                {"total", bpv(stats.total_bytes)}};
    r["error"] = {{"max", stats.max_error}, {"rms", stats.rms_error}, {"bound", stats.error_bound}};
    r["ms"] = {{"read", read_ms}, {"encode", encode_ms}, {"write", write_ms}};
    r["triangles_per_s"] = encode_ms > 0 ? static_cast<double>(stats.input_faces) / (encode_ms / 1000.0) : 0.0;
    r["peak_rss_kb"] = peak_rss_kb();
    write_output(opt.report, r.dump(2) + "\n");
  }
  return 0;
}

int model(const ModelOptions& opt) {
  std::vector<NamedModel> models;
  if (opt.to == "inc") {
    models = named_models();
  } else if (!opt.model.empty()) {
    models.push_back(named_model(opt.model));
  } else {
    models.push_back({"custom", 0, {opt.lmax, opt.pmax, opt.smax, opt.cmax, opt.all_patterns, opt.literal}});
  }
  std::string out;
  if (opt.to == "inc") {
    out += "// Generated by `ebcode model --to inc` (spec 2.6, \"Embedding\"); do not edit.\n"
           "// Per state: frequencies of C, L, E, R, S summing to 2^15, and the next state.\n";
    std::string list;
    for (const NamedModel& m : models) {
      const StateMachine sm = build_state_machine(m.params);
      const auto freq = frequency_table(sm);
      out += fmt::format("// {}: {} states, alpha {:.9f}, {:.6f} bpv\n", m.name, sm.states.size(), sm.alpha, sm.rate());
      out += fmt::format("const std::uint16_t {}_freq[][5] = {{\n", m.name);
      for (const auto& f : freq) out += fmt::format("  {{{}, {}, {}, {}, {}}},\n", f[0], f[1], f[2], f[3], f[4]);
      out += "};\n";
      out += fmt::format("const std::int16_t {}_next[][5] = {{\n", m.name);
      for (const auto& st : sm.states)
        out += fmt::format("  {{{}, {}, {}, {}, {}}},\n", st.next[0], st.next[1], st.next[2], st.next[3], st.next[4]);
      out += "};\n";
      list += fmt::format("    {{{}, \"{}\", {}, {}_freq, {}_next}},\n", m.id, m.name, sm.states.size(), m.name, m.name);
    }
    out += "const StaticModelTable committed_models[] = {\n" + list + "};\n";
  } else {
    const NamedModel& m = models.front();
    const auto t0 = Clock::now();
    const StateMachine sm = build_state_machine(m.params);
    const double ms = ms_since(t0);
    if (opt.to == "json") {
      nlohmann::json j;
      j["model"] = m.name;
      j["raw_states"] = sm.raw_states;
      j["states"] = sm.states.size();
      j["alpha"] = sm.alpha;
      j["bpv"] = sm.rate();
      j["ms"] = ms;
      nlohmann::json states = nlohmann::json::array();
      for (const auto& st : sm.states)
        states.push_back({{"history", st.history}, {"l", st.l}, {"p", st.p}, {"s", st.s},
                          {"unity", st.unity}, {"c_allowed", st.c_allowed}, {"next", st.next}});
      j["state_list"] = states;
      out = j.dump(2) + "\n";
    } else if (opt.to == "tsv") {
      out += fmt::format("# model {}: {} states ({} before minimisation), alpha {:.9f}, {:.6f} bpv\n", m.name,
                         sm.states.size(), sm.raw_states, sm.alpha, sm.rate());
      out += "state\thistory\tl\tp\ts\tunity\tC\tL\tE\tR\tS\n";
      const auto len = [](int x) { return x < 0 ? std::string("?") : std::to_string(x); };
      const auto freq = frequency_table(sm);
      for (std::size_t i = 0; i < sm.states.size(); ++i) {
        const auto& st = sm.states[i];
        out += fmt::format("{}\t{}\t{}\t{}\t{}\t{:.6f}", i, st.history.empty() ? "-" : st.history, len(st.l), len(st.p),
                           len(st.s), st.unity);
        for (int k = 0; k < 5; ++k)
          out += st.next[static_cast<std::size_t>(k)] < 0 ? std::string("\t-")
                                                         : fmt::format("\t{}>{}", freq[i][static_cast<std::size_t>(k)],
                                                                       st.next[static_cast<std::size_t>(k)]);
        out += "\n";
      }
    } else {
      throw usage_error("--to: unknown output '{}' (tsv, json, inc)", opt.to);
    }
  }
  write_output("-", out);
  return 0;
}

int limit_value(const std::string& text, const char* flag) {
  if (text == "-") return -1;
  try {
    std::size_t used = 0;
    const int v = std::stoi(text, &used);
    if (used == text.size() && v >= 3 && v <= 64) return v;
  } catch (const std::exception&) {
  }
  throw usage_error("{}: '{}' is not a length 3..64 or -", flag, text);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Compress a triangle mesh into an .ebm stream: Edgebreaker connectivity with the conditional-unity\n"
               "coder (< 3.525 bits per vertex for genus 0) or an adaptive one, quantised parallelogram-predicted\n"
               "positions; non-manifold input, holes, handles and several components are kept exactly.",
               "ebcode"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  app.require_subcommand(0, 1);
  Options opt;
  app.add_option("input", opt.input, "Input mesh (PLY, OFF, OBJ, STL, Draco), or - for standard input")->default_val("-");
  app.add_option("-o,--output", opt.output, "Output file, or - for standard output")->default_val("-");
  app.add_option("--conn", opt.conn, "Connectivity coder: auto (smaller of static and adaptive), static, adaptive, raw")
      ->default_val("auto");
  app.add_option("--model", opt.model, "Static state machine: m2, m26, m68, m236, m240x")->default_val("m236");
  app.add_option("--qp", opt.qp, "Position bits 1..30; 0 = lossless float32")->default_val(14)->check(CLI::Range(0, 30));
  app.add_option("--qn", opt.qn, "Vertex normal bits per component (over [-1, 1])")->default_val(10)->check(CLI::Range(1, 30));
  app.add_option("--qt", opt.qt, "Texture coordinate bits (over their own box)")->default_val(12)->check(CLI::Range(1, 30));
  app.add_option("--box", opt.box, "Quantisation box X,Y,Z,EXT instead of the bounding box");
  app.add_option("--predict", opt.predict, "Position predictor: para, multi (mean of all parallelograms), delta, none")->default_val("para");
  app.add_flag("--no-stitch", opt.no_stitch, "Keep the copies of non-manifold vertices as separate vertices");
  app.add_flag("--drop-isolated", opt.drop_isolated, "Drop vertices no face uses");
  app.add_flag("--no-geometry", opt.no_geometry, "Connectivity only");
  app.add_flag("--strict", opt.strict, "Degenerate faces, non-manifold input and boundaries are errors");
  app.add_option("--to", opt.to, "Output: ebm, or drc (Draco through libdraco, for comparison)")->default_val("ebm");
  app.add_option("--draco-cl", opt.draco_cl, "Draco compression level 0..10 for --to drc")
      ->default_val(7)->check(CLI::Range(0, 10));
  app.add_option("--report", opt.report, "Write counts, bits per section, errors and times as JSON to this file");
  app.add_flag("--symbols", opt.symbols, "Write the forward CLERS string instead of the stream");
  app.add_flag("--no-verify", opt.no_verify, "Skip re-encoding the decoded connectivity (the cheap check stays)");
  app.add_option("--ebm-version", opt.ebm_version, "Container version: 2 (compact, the default) or 1 (for readers before fest 0.2)")
      ->default_val(2)->check(CLI::Range(1, 2));

  ModelOptions mopt;
  std::string lmax = "-", pmax = "-", smax = "-";
  CLI::App* sub = app.add_subcommand("model", "Print a state machine of the chapter: alpha, rate, unities, frequencies");
  sub->add_option("--model", mopt.model, "A named model (m2, m26, m68, m236, m240x) instead of the limits");
  sub->add_option("--lmax", lmax, "Longest tracked current-loop length, or -")->default_val("-");
  sub->add_option("--pmax", pmax, "Longest tracked top-loop length, or -")->default_val("-");
  sub->add_option("--smax", smax, "Longest tracked second-loop length, or -")->default_val("-");
  sub->add_option("--cmax", mopt.cmax, "Number of exclusion patterns used (0..19)")->default_val(19)->check(CLI::Range(0, 19));
  sub->add_flag("--all-patterns", mopt.all_patterns, "Also the two patterns starting with EE (m240x)");
  sub->add_flag("--literal-rule", mopt.literal, "C excluded only when the history itself is a pattern (diagnostic)");
  sub->add_option("--to", mopt.to, "tsv, json, or inc (the committed tables of all named models)")->default_val("tsv");
  app.footer("Exit status: 0 success, 1 self-verification failed, 2 usage error, 3 bad input, 4 I/O error.\n"
             "See ebcode(1), ebdecode(1), ebm(5).");
  return fest::cli::run(app, argc, argv, [&] {
    ::omerr().disable();
    opt.quiet = common.quiet;
    if (sub->parsed()) {
      mopt.lmax = limit_value(lmax, "--lmax");
      mopt.pmax = limit_value(pmax, "--pmax");
      mopt.smax = limit_value(smax, "--smax");
      return model(mopt);
    }
    return encode(opt);
  });
}

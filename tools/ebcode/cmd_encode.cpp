// ebcode (encode): triangle mesh -> .ebm (Edgebreaker connectivity with the chapter's
// conditional-unity coder, quantised parallelogram-predicted positions), Draco for
// comparison, or the CLERS string. formats/ reads the mesh, lib/edgebreaker codes it.

#include <nlohmann/json.hpp>
#include <OpenMesh/Core/System/omstream.hh>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/resources.hpp"
#include "core/stopwatch.hpp"
#include "core/tool_main.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "formats/mesh/triangle_soup.hpp"

namespace fest::ebcode_tool {

namespace {

using namespace fest::edgebreaker;

nlohmann::json report_json(const EncodeOptions& opt, const std::string& input, const EncodeStats& stats,
                           double read_ms, double encode_ms, double write_ms) {
  const double v = static_cast<double>(stats.input_vertices);
  const auto bpv = [&](std::size_t b) { return v > 0 ? 8.0 * static_cast<double>(b) / v : 0.0; };
  nlohmann::json r;
  r["input"] = input;
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
  r["model"] = stats.conn_mode == "static" ? opt.model.name : "";
  r["qp"] = opt.qp;
  r["geom_version"] = stats.geom_version;
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
  return r;
}

}  // namespace

int encode_command(const EncodeOptions& opt) {
  ::omerr().disable();  // add_face reports rejected (non-manifold) faces there; they are kept aside
  const SteadyClock::time_point t0 = SteadyClock::now();
  const formats::Input in = formats::load_input(opt.input);
  if (formats::kind_of(in.format) != formats::Kind::mesh)
    throw bad_input("{} input is not a mesh ({})", formats::format_name(in.format), in.name);
  const Mesh mesh = formats::parse(in, formats::read_mesh);
  const MeshSoup soup = formats::to_triangle_soup(mesh);
  const double read_ms = ms_since(t0);
  if (soup.positions.empty()) throw bad_input("the mesh is empty ({})", in.name);
  if (!opt.quiet && (mesh.has_face_colors() || mesh.has_face_normals()))
    warn("ebcode", "face colours and normals are not coded; vertex attributes are");

  if (opt.symbols) {
    std::string clers;
    try {
      clers = to_string(mesh_symbols(soup, opt.strict));
    } catch (const Error& e) {
      throw in_flag_terms(e);
    }
    write_output(opt.output, clers + "\n");
    return 0;
  }
  if (opt.format == EncodeFormat::drc) {
    formats::MeshWriteOptions w;
    w.draco_position_bits = opt.qp;
    w.draco_speed = 10 - opt.draco_cl;
    w.draco_normal_bits = opt.qn;  // the same bits as ebm's, for a like-for-like comparison
    w.draco_texcoord_bits = opt.qt;
    formats::store_output(opt.output, formats::write_mesh(mesh, formats::Format::drc, w), false);
    return 0;
  }

  edgebreaker::EncodeOptions e;
  e.conn = opt.conn;
  e.model_id = opt.model.id;
  e.qp = opt.qp;
  e.qn = opt.qn;
  e.qt = opt.qt;
  e.box = opt.box;
  e.predictor = opt.predictor;
  e.stitch = opt.stitch;
  e.drop_isolated = opt.drop_isolated;
  e.geometry = opt.geometry;
  e.strict = opt.strict;
  e.verify = opt.verify;
  e.version = opt.ebm_version;
  e.geom_version = opt.geom_version;
  EncodeStats stats;
  const SteadyClock::time_point t1 = SteadyClock::now();
  std::string bytes;
  try {
    bytes = encode_ebm(soup, e, &stats);
  } catch (const Error& err) {
    throw in_flag_terms(err);
  }
  const double encode_ms = ms_since(t1);
  const SteadyClock::time_point t2 = SteadyClock::now();
  write_output(opt.output, bytes);
  const double write_ms = ms_since(t2);
  if (!opt.report.empty())
    write_output(opt.report, report_json(opt, in.name, stats, read_ms, encode_ms, write_ms).dump(2) + "\n");
  return 0;
}

}  // namespace fest::ebcode_tool

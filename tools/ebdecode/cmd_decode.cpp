// ebdecode: .ebm (or Draco .drc) -> triangle mesh. Everything is decoded and checked
// (magic, version, CRC, counts, every index) before a byte is written. lib/edgebreaker
// decodes .ebm, formats/ reads Draco and writes the mesh.

#include <nlohmann/json.hpp>
#include <OpenMesh/Core/System/omstream.hh>

#include "cli/word_choice.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/resources.hpp"
#include "core/stopwatch.hpp"
#include "edgebreaker/ebm.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "formats/mesh/triangle_soup.hpp"

namespace fest::ebdecode_tool {

namespace {

using namespace fest::edgebreaker;

nlohmann::json header_json(const EbmHeader& h) {
  static const char* modes[] = {"raw", "static", "adaptive"};
  nlohmann::json j;
  j["format"] = "ebm";
  j["version"] = std::to_string(h.major) + "." + std::to_string(h.minor);
  j["bytes"] = h.total_bytes;
  j["vertices"] = h.vertices;
  j["faces"] = h.faces;
  j["components"] = h.components;
  j["holes"] = h.dummies;
  j["stitch"] = h.stitch;
  j["events"] = h.events;
  j["isolated"] = h.isolated;
  j["symbols"] = h.symbols;
  j["conn_mode"] = modes[h.conn_mode];
  j["model_id"] = h.model_id;
  j["qp"] = h.qp;
  j["predictor"] = h.predictor;
  j["geometry"] = (h.flags & ebm_flags::geometry) != 0;
  j["exclusion"] = (h.flags & ebm_flags::exclusion) != 0;
  j["box"] = {h.box[0], h.box[1], h.box[2], h.box[3]};
  j["attributes"] = h.attribute_names;
  nlohmann::json sections = nlohmann::json::object();
  for (const auto& [tag, n] : h.section_bytes) sections[tag] = n;
  j["sections"] = sections;
  return j;
}

formats::Format output_format(const DecodeOptions& opt) {
  if (!opt.format && !is_stdio(opt.output)) {
    const formats::OutputFormat f = formats::output_format_from_path(opt.output);
    if (formats::kind_of(f.format) != formats::Kind::mesh) throw usage_error("-o {}: not a mesh file name", opt.output);
    return f.format;
  }
  return opt.format.value_or(formats::Format::ply);
}

}  // namespace

void parse_output_format(const std::string& name, DecodeOptions& o) {
  o.format = cli::word_choice<formats::Format>(
      name, {{"ply", formats::Format::ply}, {"plya", formats::Format::ply}, {"obj", formats::Format::obj}, {"off", formats::Format::off}},
      "--to", "output");
  o.ascii = name == "plya";
}

int decode_command(const DecodeOptions& opt) {
  ::omerr().disable();  // add_face reports rejected (non-manifold) faces there; they are kept aside
  const formats::Format out_format = output_format(opt);
  const SteadyClock::time_point t0 = SteadyClock::now();
  // .ebm is recognised here by its magic; anything else goes through formats/ (Draco).
  std::string bytes_in = read_input(opt.input);
  formats::Input in;
  if (is_ebm(bytes_in)) {
    in.name = opt.input;
    in.bytes = std::move(bytes_in);
    in.format = formats::Format::drc;  // unused for .ebm
  } else if (bytes_in.empty()) {
    throw bad_input("empty input ({})", opt.input);
  } else {
    in = formats::recognise(std::move(bytes_in), opt.input);
  }
  Mesh mesh;
  nlohmann::json report;
  if (is_ebm(in.bytes)) {
    if (opt.info) {
      const EbmHeader h = formats::parse(in, [](const std::string& b, formats::Format) { return read_ebm_header(b); });
      write_output(opt.output, header_json(h).dump(2) + "\n");
      return 0;
    }
    EbmHeader h;
    const MeshSoup soup = formats::parse(in, [&](const std::string& b, formats::Format) {
      return decode_ebm(b, opt.stitch, opt.verify, &h);
    });
    const double decode_ms = ms_since(t0);
    mesh = formats::to_mesh(soup);
    report = header_json(h);
    report["ms"] = {{"decode", decode_ms}};
    report["triangles_per_s"] = decode_ms > 0 ? static_cast<double>(soup.triangles.size()) / (decode_ms / 1000.0) : 0.0;
  } else if (in.format == formats::Format::drc) {
    mesh = formats::parse(in, formats::read_mesh);
    if (opt.info) {
      nlohmann::json j = formats::describe_mesh(mesh);
      j["format"] = "drc";
      write_output(opt.output, j.dump(2) + "\n");
      return 0;
    }
    report = {{"format", "drc"}, {"ms", {{"decode", ms_since(t0)}}}};
  } else {
    throw bad_input("not an .ebm or Draco stream ({})", in.name);
  }
  formats::MeshWriteOptions w;
  w.ascii = opt.ascii;
  const std::string bytes = formats::write_mesh(mesh, out_format, w);  // complete before any output
  formats::store_output(opt.output, bytes, false);
  if (!opt.report.empty()) {
    report["peak_rss_kb"] = peak_rss_kb();
    write_output(opt.report, report.dump(2) + "\n");
  }
  return 0;
}

}  // namespace fest::ebdecode_tool

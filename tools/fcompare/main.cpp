// fcompare: kind-aware numeric comparison of two files -- the check behind every
// golden-file test of fest. Exit 0 when within tolerance, 1 when not.
//
// Wiring only: formats/ reads, lib/compare measures, lib/compare/checks decides.

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli.hpp"

#include "compare/checks.hpp"
#include "compare/dataset_compare.hpp"
#include "compare/image_compare.hpp"
#include "compare/json_compare.hpp"
#include "compare/mesh_compare.hpp"
#include "compare/table_compare.hpp"
#include "compare/volume_compare.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/threads.hpp"
#include "core/tool_main.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "formats/table/table_io.hpp"
#include "formats/volume/volume_io.hpp"

namespace {

using namespace fest;
using namespace fest::formats;
using fest::compare::Metrics;

struct Options {
  std::string a, b;
  double tol = 0;
  std::vector<std::string> thresholds;
  std::size_t samples = 100000;
  int threads = 0;
  bool ignore_counts = false;
  bool ignore_topology = false;
  std::string report;
  bool quiet = false;
  bool tol_given = false;  // --tol on the command line: a criterion the user asked for
};

// The check of a kind's main metric: --tol given is the user's own criterion (a -t on
// another metric of the family leaves it in place); otherwise it is a default that any
// -t on the family replaces (see compare::Metrics).
void require_main(Metrics& m, const std::string& metric, const Options& opt) {
  if (opt.tol_given)
    m.require(compare::Check{metric, true, opt.tol});
  else
    m.require(metric, "<=", opt.tol);
}

nlohmann::json topology_json(const compare::MeshTopology& t) {
  return {{"vertices", t.vertices},       {"faces", t.faces},
          {"edges", t.edges},             {"isolated_vertices", t.isolated_vertices},
          {"boundary_edges", t.boundary_edges}, {"boundary_loops", t.boundary_loops},
          {"components", t.components},   {"nonmanifold_vertices", t.nonmanifold_vertices},
          {"euler", t.euler},             {"genus", t.genus},
          {"faces_beside_halfedges", t.faces_beside}};
}

// A mesh file as it is: the halfedge mesh, and the faces it could not hold beside it.
Mesh read_mesh_file(const Input& in) {
  Mesh mesh = parse(in, read_mesh);
  for (const std::string& w : read_warnings(mesh)) warn("fcompare", w + " (" + in.name + ")");
  return mesh;
}

void compare_meshes(const Input& ia, const Input& ib, const Options& opt, Metrics& m) {
  const Mesh a = read_mesh_file(ia);
  const Mesh b = read_mesh_file(ib);
  const compare::FaceList beside_a = faces_beside(a), beside_b = faces_beside(b);
  const auto ta = compare::mesh_topology(a, beside_a), tb = compare::mesh_topology(b, beside_b);
  m.details["topology_a"] = topology_json(ta);
  m.details["topology_b"] = topology_json(tb);
  // Line and point elements count like faces: a file that lost them differs.
  m.set("line_count_diff",
        std::abs(static_cast<double>(line_segments(a)) - static_cast<double>(line_segments(b))));
  m.set("point_count_diff", std::abs(static_cast<double>(point_count(a)) - static_cast<double>(point_count(b))));
  m.set("vertex_count_diff", std::abs(static_cast<double>(ta.vertices) - static_cast<double>(tb.vertices)));
  m.set("face_count_diff", std::abs(static_cast<double>(ta.faces) - static_cast<double>(tb.faces)));
  m.set("genus_diff", std::abs(static_cast<double>(ta.genus - tb.genus)));
  m.set("boundary_loops_diff",
        std::abs(static_cast<double>(ta.boundary_loops) - static_cast<double>(tb.boundary_loops)));
  m.set("components_diff", std::abs(static_cast<double>(ta.components) - static_cast<double>(tb.components)));
  m.set("nonmanifold_vertices_diff",
        std::abs(static_cast<double>(ta.nonmanifold_vertices) - static_cast<double>(tb.nonmanifold_vertices)));
  if (a.n_vertices() == b.n_vertices()) {
    // Same counts: also compare vertex by vertex, the exact check for lossless round trips.
    double worst = 0;
    for (std::size_t i = 0; i < a.n_vertices(); ++i) {
      const auto d = a.point(Mesh::VertexHandle(static_cast<int>(i))) - b.point(Mesh::VertexHandle(static_cast<int>(i)));
      worst = std::max({worst, std::abs(d[0]), std::abs(d[1]), std::abs(d[2])});
    }
    m.set("vertex_max_abs", worst);
  }
  const auto d = compare::surface_distance(a, beside_a, b, beside_b, opt.samples, 1, resolve_threads(opt.threads));
  m.set("hausdorff", d.hausdorff);
  m.set("rms", d.rms);
  m.set("mean", d.mean);
  m.set("max_a_to_b", d.max_a_to_b);
  m.set("max_b_to_a", d.max_b_to_a);
  m.details["samples"] = {d.samples_a, d.samples_b};

  m.family({"hausdorff", "rms", "mean", "max_a_to_b", "max_b_to_a", "vertex_max_abs"});
  require_main(m, "hausdorff", opt);
  if (!opt.ignore_counts) {
    m.require("vertex_count_diff", "<=", 0);
    m.require("face_count_diff", "<=", 0);
    m.require("line_count_diff", "<=", 0);
    m.require("point_count_diff", "<=", 0);
  }
  if (!opt.ignore_topology) {
    for (const char* k : {"genus_diff", "boundary_loops_diff", "components_diff", "nonmanifold_vertices_diff"})
      m.require(k, "<=", 0);
  }
}

void compare_images(const Input& ia, const Input& ib, const Options& opt, Metrics& m) {
  const Image a = parse(ia, read_image);
  const Image b = parse(ib, read_image);
  const auto e = compare::image_error(a.pixels, b.pixels);
  m.set("rmse", e.all.rmse);
  m.set("psnr", e.all.psnr);
  m.set("max_abs", e.all.max_abs);
  nlohmann::json channels = nlohmann::json::array();
  for (const auto& c : e.channels)
    channels.push_back({{"rmse", c.rmse}, {"psnr", compare::json_number(c.psnr)}, {"max_abs", c.max_abs}});
  m.details["channels"] = channels;
  m.details["peak"] = e.peak;
  if (e.alpha.measured) {
    // Only one image has alpha: the other is opaque, so its distance from opaque is
    // the alpha difference, reported and checked on its own.
    m.set("alpha_max_abs", e.alpha.max_abs);
    m.details["alpha"] = {{"in", e.alpha.image == 1 ? "a" : "b"}, {"min", e.alpha.min_alpha}};
    require_main(m, "alpha_max_abs", opt);
  }
  m.family({"max_abs", "rmse", "psnr"});
  require_main(m, "max_abs", opt);
}

void compare_volumes(const Input& ia, const Input& ib, const Options& opt, Metrics& m) {
  const Volume a = parse(ia, read_volume);
  const Volume b = parse(ib, read_volume);
  const auto e = compare::volume_error(a, b);
  m.set("max_abs", e.max_abs);
  m.set("rmse", e.rmse);
  m.set("spacing_diff", e.max_spacing_diff);
  m.set("origin_diff", e.max_origin_diff);
  if (e.labels) {
    m.set("dice", e.min_dice);
    nlohmann::json per = nlohmann::json::object();
    for (const auto& [label, dice] : e.dice) per[std::to_string(label)] = dice;
    m.details["dice_per_label"] = per;
  }
  m.family({"max_abs", "rmse", "dice"});
  require_main(m, "max_abs", opt);
  // Geometry to a micrometre: files that place the same voxels differently differ.
  m.require("spacing_diff", "<=", 1e-6);
  m.require("origin_diff", "<=", 1e-6);
}

void compare_tables(const Input& ia, const Input& ib, const Options& opt, Metrics& m) {
  const Table a = parse(ia, read_table);
  const Table b = parse(ib, read_table);
  const auto e = compare::table_error(a, b);
  m.set("max_abs", e.max_abs);
  m.set("max_rel", e.max_rel);
  nlohmann::json cols = nlohmann::json::object();
  for (const auto& c : e.columns) cols[c.name] = {{"max_abs", c.max_abs}, {"max_rel", c.max_rel}};
  m.details["columns"] = cols;
  m.family({"max_abs", "max_rel"});
  require_main(m, "max_abs", opt);
}

void compare_datasets(const Input& ia, const Input& ib, const Options& opt, Metrics& m) {
  const auto a = parse(ia, read_dataset);
  const auto b = parse(ib, read_dataset);
  const auto d = compare::dataset_difference(a, b);
  m.set("point_count_diff", std::abs(static_cast<double>(d.points_a) - static_cast<double>(d.points_b)));
  m.set("cell_count_diff", std::abs(static_cast<double>(d.cells_a) - static_cast<double>(d.cells_b)));
  m.set("cell_diffs", static_cast<double>(d.cell_diffs));
  m.set("missing_arrays", static_cast<double>(d.missing_arrays));
  m.set("point_max_abs", d.point_max_abs);
  m.set("max_abs", d.array_max_abs_all);
  nlohmann::json arrays = nlohmann::json::object();
  for (const auto& [name, value] : d.array_max_abs) arrays[name] = compare::json_number(value);
  m.details["arrays"] = arrays;
  m.details["dataset_type"] = {a.class_name(), b.class_name()};
  for (const char* k : {"point_count_diff", "cell_count_diff", "cell_diffs", "missing_arrays"}) m.require(k, "<=", 0);
  require_main(m, "point_max_abs", opt);
  require_main(m, "max_abs", opt);
}

void compare_json(const Input& ia, const Input& ib, const Options& opt, Metrics& m) {
  const auto d = compare::json_difference(parse(ia, read_json_document), parse(ib, read_json_document));
  m.set("max_abs", d.max_abs);
  m.set("structural_diffs", static_cast<double>(d.structural));
  m.details["numbers"] = d.numbers;
  if (d.structural > 0) m.details["first_structural_diff"] = d.first_structural_path;
  require_main(m, "max_abs", opt);
  m.require("structural_diffs", "<=", 0);
}

int run(const Options& opt) {
  const Input a = load_input(opt.a);
  const Input b = load_input(opt.b);
  const Kind kind = kind_of(a.format);
  if (kind != kind_of(b.format))
    throw bad_input("cannot compare a {} ({}) with a {} ({})", kind_name(kind), a.name, kind_name(kind_of(b.format)),
                    b.name);

  Metrics m;
  switch (kind) {
    case Kind::mesh: compare_meshes(a, b, opt, m); break;
    case Kind::image: compare_images(a, b, opt, m); break;
    case Kind::volume: compare_volumes(a, b, opt, m); break;
    case Kind::table: compare_tables(a, b, opt, m); break;
    case Kind::dataset: compare_datasets(a, b, opt, m); break;
    case Kind::json: compare_json(a, b, opt, m); break;
  }
  for (const std::string& t : opt.thresholds) m.require(compare::parse_threshold(t));

  const auto failures = m.evaluate();
  if (!opt.report.empty()) {
    nlohmann::json report = m.to_json();
    report["a"] = a.name;
    report["b"] = b.name;
    report["kind"] = kind_name(kind);
    write_output(opt.report, report.dump(2) + "\n");
  }
  if (!opt.quiet) write_output("-", m.summary());
  for (const auto& f : failures)
    std::fprintf(stderr, "fcompare: %s (%s, %s)\n", f.c_str(), a.name.c_str(), b.name.c_str());
  return failures.empty() ? 0 : static_cast<int>(Status::failure);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Compare two files of the same kind numerically: meshes (surface distance, counts,\n"
               "topology), images (RMSE, PSNR, max abs), volumes (max abs, Dice per label), tables\n"
               "(max abs per column), VTK datasets (cells, points, arrays), JSON (numbers and structure).\n"
               "Exit 0 when within tolerance, 1 when not.",
               "fcompare"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  Options opt;
  app.add_option("a", opt.a, "First file (- for standard input)")->required();
  app.add_option("b", opt.b, "Second file")->required();
  CLI::Option* tol = app.add_option("--tol", opt.tol,
                 "Tolerance of the main metric: mesh Hausdorff distance, else max absolute difference")
      ->default_val(0.0)
      ->check(CLI::NonNegativeNumber);
  app.add_option("-t,--threshold", opt.thresholds,
                 "Extra check METRIC<=VALUE or METRIC>=VALUE, e.g. 'psnr>=40', 'rms<=1e-4', 'dice>=0.9'; "
                 "replaces the default check of that metric and of the metrics that measure the same error "
                 "(image max_abs/rmse/psnr; mesh hausdorff/rms/mean; volume max_abs/rmse/dice; table max_abs/max_rel)")
      ->allow_extra_args(false);
  app.add_option("--samples", opt.samples, "Meshes: random surface samples per mesh besides the vertices")
      ->default_val(100000);
  fest::cli::add_threads(app, opt.threads);
  app.add_flag("--ignore-counts", opt.ignore_counts, "Meshes: allow different vertex, face, line and point counts");
  app.add_flag("--ignore-topology", opt.ignore_topology, "Meshes: allow different genus, boundaries, components");
  app.add_option("--report", opt.report, "Write every metric and check as JSON to this file");
  app.footer("Exit status: 0 within tolerance, 1 not (failing checks on standard error), 2 usage error,\n"
             "3 bad input, 4 I/O error. See fcompare(1).");
  return fest::cli::run(app, argc, argv, [&] {
    opt.quiet = common.quiet;
    opt.tol_given = tol->count() > 0;
    return run(opt);
  });
}

// softobj field: f and grad f at given points (the field of docs/softobj.md §1), for tests.
#include "commands.hpp"
#include "core/error.hpp"
#include "core/table.hpp"
#include "formats/input.hpp"
#include "formats/table/table_io.hpp"
#include "skeleton_input.hpp"
#include "softobj/field.hpp"

namespace fest::softobj_tool {

int run_field(const FieldArgs& a) {
  if (a.at.empty()) throw usage_error("--at POINTS is required");
  if (a.at == "-" && a.input == "-") throw usage_error("the skeleton and --at cannot both be standard input");
  const softobj::Field field(softobj::compile_terms(read_skeleton(a.input, SkeletonFormat::json)));
  const formats::Input in = formats::load_input(a.at);
  if (in.format != formats::Format::csv && in.format != formats::Format::tsv)
    throw bad_input("points are {}, not CSV/TSV ({})", formats::format_name(in.format), in.name);
  const Table pts = formats::parse(in, formats::read_table);
  const std::size_t cx = pts.find("x"), cy = pts.find("y"), cz = pts.find("z");
  if (cx == Table::npos || cy == Table::npos || cz == Table::npos)
    throw bad_input("points need columns x, y and z ({})", in.name);
  Table out;
  std::vector<double> x, y, z, f, gx, gy, gz;
  for (std::size_t i = 0; i < pts.rows(); ++i) {
    const Eigen::Vector3d r(pts.columns[cx][i], pts.columns[cy][i], pts.columns[cz][i]);
    if (!r.allFinite()) throw bad_input("point {} is not finite ({})", i, in.name);
    const auto s = field.eval(r);
    x.push_back(r.x()), y.push_back(r.y()), z.push_back(r.z());
    f.push_back(s.f), gx.push_back(s.grad.x()), gy.push_back(s.grad.y()), gz.push_back(s.grad.z());
  }
  out.add_column("x", x), out.add_column("y", y), out.add_column("z", z), out.add_column("f", f);
  out.add_column("gx", gx), out.add_column("gy", gy), out.add_column("gz", gz);
  formats::store_output(a.output, formats::write_table(out, formats::Format::tsv), false);
  return 0;
}

}  // namespace fest::softobj_tool

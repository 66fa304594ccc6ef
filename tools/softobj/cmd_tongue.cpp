// softobj tongue: shape parameters -> the tongue skeleton JSON (docs/softobj.md §4).
#include <cmath>
#include <cstdlib>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/table.hpp"
#include "formats/input.hpp"
#include "formats/table/table_io.hpp"
#include "core/file_io.hpp"
#include "softobj/palate.hpp"
#include "softobj/skeleton_json.hpp"
#include "softobj/tongue.hpp"

namespace fest::softobj_tool {

namespace {

void apply_set(softobj::TongueParams& p, const std::string& item) {
  const auto eq = item.find('=');
  if (eq == std::string::npos) throw usage_error("--set {}: expected name=value", item);
  const std::string name = item.substr(0, eq), value = item.substr(eq + 1);
  const int i = softobj::TongueParams::index_of(name);
  if (i < 0) throw usage_error("--set: unknown parameter {} (x0 y0 z0 l1..l9 a1..a3 c1..c6)", name);
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0' || !std::isfinite(v)) throw usage_error("--set {}: {} is not a number", name, value);
  p[i] = v;
}

}  // namespace

int run_tongue(const TongueArgs& a) {
  if (!(a.radius > 0)) throw usage_error("--radius must be positive");
  if (a.layout != "default" && a.layout != "paper9") throw usage_error("--layout {} is not default or paper9", a.layout);
  softobj::TongueParams p = softobj::neutral_tongue();
  for (const auto& s : a.set) apply_set(p, s);  // usage errors before reading
  if (!a.neutral) {
    const formats::Input in = formats::load_input(a.input);
    if (in.format != formats::Format::csv && in.format != formats::Format::tsv)
      throw bad_input("tongue parameters are {}, not TSV ({})", formats::format_name(in.format), in.name);
    const Table t = formats::parse(in, formats::read_table);
    if (a.frame < 0 || static_cast<std::size_t>(a.frame) >= t.rows())
      throw bad_input("frame {} is not in the table ({} rows) ({})", a.frame, t.rows(), in.name);
    for (int i = 0; i < softobj::TongueParams::count; ++i) {
      const char* name = softobj::TongueParams::names()[static_cast<std::size_t>(i)];
      const std::size_t c = t.find(name);
      if (c == Table::npos) throw bad_input("tongue parameters lack column {} ({})", name, in.name);
      const double v = t.columns[c][static_cast<std::size_t>(a.frame)];
      if (!std::isfinite(v)) throw bad_input("{} in frame {} is not finite ({})", name, a.frame, in.name);
      p[i] = v;
    }
    for (const auto& s : a.set) apply_set(p, s);  // --set overrides the row
  }
  for (int l = 3; l <= 11; ++l)
    if (!(p[l] >= 0)) throw bad_input("length {} is negative ({})", softobj::TongueParams::names()[static_cast<std::size_t>(l)], p[l]);
  if (!a.palate.empty()) {
    softobj::Palate pl;
    try {
      pl = softobj::decode_palate(read_input(a.palate));
    } catch (const Error& e) {
      if (e.status() != Status::bad_input) throw;
      throw Error(e.status(), with_location(e.what(), a.palate));
    }
    softobj::palate_pass1(p, pl, a.radius);
  }
  const auto layout = a.layout == "paper9" ? softobj::TongueLayout::paper9 : softobj::TongueLayout::default10;
  formats::store_output(a.output, softobj::encode_skeleton(softobj::tongue_skeleton(p, layout, a.radius)), false);
  return 0;
}

}  // namespace fest::softobj_tool

// fcompare on volumes: max abs, RMSE, Dice per label, and the geometry.

#include <string>

#include <nlohmann/json.hpp>

#include "compare/volume_compare.hpp"
#include "formats/volume/volume_io.hpp"
#include "measure.hpp"

namespace fest::fcompare_tool {

void compare_volumes(const formats::Input& ia, const formats::Input& ib, const CompareOptions& opt,
                     compare::Metrics& m) {
  const auto [a, b] = parse_both(ia, ib, formats::read_volume);
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

}  // namespace fest::fcompare_tool

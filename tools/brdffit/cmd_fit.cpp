// brdffit fit (docs/brdffit.md §3): samples (CSV/TSV) or a MERL table -> lib/brdffit's
// Lafortune fit -> brdf.json.

#include <cmath>
#include <string>
#include <vector>

#include "brdffit/brdf_json.hpp"
#include "brdffit/lafortune_fit.hpp"
#include "brdffit/lobe_albedo.hpp"
#include "brdffit/merl.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"
#include "core/progress.hpp"
#include "core/stopwatch.hpp"
#include "fitted_inputs.hpp"
#include "formats/brdf/merl_io.hpp"
#include "formats/table/table_io.hpp"
#include "option_checks.hpp"

namespace fest::brdffit_tool {
namespace {

using brdffit::FitSample;

std::vector<FitSample> samples_from_table(const Table& t, bool angles, const std::string& where) {
  const std::vector<std::string> names = angles ? std::vector<std::string>{"theta_i", "phi_i", "theta_o", "phi_o", "r", "g", "b"}
                                                : std::vector<std::string>{"ux", "uy", "uz", "vx", "vy", "vz", "r", "g", "b"};
  std::vector<const std::vector<double>*> col;
  for (const std::string& n : names) {
    const std::size_t k = t.find(n);
    if (k == Table::npos) throw bad_input("samples table has no column '{}' ({})", n, where);
    col.push_back(&t.columns[k]);
  }
  std::vector<FitSample> out;
  for (std::size_t i = 0; i < t.rows(); ++i) {
    auto v = [&](std::size_t c) { return (*col[c])[i]; };
    Eigen::Vector3d u, w, r;
    if (angles) {
      u = {std::sin(v(0)) * std::cos(v(1)), std::sin(v(0)) * std::sin(v(1)), std::cos(v(0))};
      w = {std::sin(v(2)) * std::cos(v(3)), std::sin(v(2)) * std::sin(v(3)), std::cos(v(2))};
      r = {v(4), v(5), v(6)};
    } else {
      u = {v(0), v(1), v(2)};
      w = {v(3), v(4), v(5)};
      r = {v(6), v(7), v(8)};
    }
    if (!u.allFinite() || !w.allFinite() || !r.allFinite())
      throw bad_input("samples table line {}: not a finite number ({})", i + 2, where);
    if (u.norm() == 0 || w.norm() == 0) throw bad_input("samples table line {}: zero direction ({})", i + 2, where);
    out.push_back(brdffit::make_fit_sample(u.normalized(), w.normalized(), r));
  }
  if (out.empty()) throw bad_input("samples table has no rows ({})", where);
  return out;
}

}  // namespace

int run_fit(const FitArgs& a) {
  const Stopwatch clock;
  const brdffit::FitOptions o = fit_options(a.fit);
  std::vector<FitSample> samples;
  std::string source;
  if (!a.merl.empty()) {
    source = a.merl;
    samples = decoded_from(a.merl, [&] {
      return brdffit::merl_samples(brdffit::MerlTable{formats::read_merl(read_input(a.merl)).values});
    });
  } else {
    source = input_name(a.input);
    const std::string bytes = read_input(a.input);
    const Table t = decoded_from(source, [&] {
      return formats::read_table(bytes, bytes.find('\t') != std::string::npos && bytes.find(',') == std::string::npos
                                            ? formats::Format::tsv
                                            : formats::Format::csv);
    });
    samples = samples_from_table(t, a.angles, source);
  }
  brdffit::FitOptions in_data_units = o;
  in_data_units.model.max_lobe_albedo = brdffit::albedo_bound_in_data_units(o.model.max_lobe_albedo, samples);
  Progress bar("brdffit fit", 0, progress_wanted(a.progress));
  in_data_units.progress = bar.callback();
  const brdffit::FitResult r = brdffit::fit_brdf(samples, in_data_units);
  bar.finish();
  nlohmann::json out = brdffit::brdf_to_json(r.brdf);
  if (o.model.shared) out["shared_lobe"] = true;
  const double rms = std::sqrt(r.mean_squared);
  out["fit"] = {{"samples", samples.size()}, {"samples_fitted", r.samples_used}, {"rms_residual", rms},
                {"iterations", r.iterations}, {"energy", r.energy}};
  write_output(a.output, formats::write_json(out));
  write_report(a.fit.report, {{"command", "fit"}, {"source", source}, {"samples", samples.size()},
                              {"samples_fitted", r.samples_used}, {"rms_residual", rms}, {"sigma2", r.sigma2},
                              {"iterations", r.iterations}, {"seconds", clock.seconds()}});
  return 0;
}

}  // namespace fest::brdffit_tool

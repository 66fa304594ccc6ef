// lbmsim run: case -> solver (one process or the slabs of an MPI job) -> fields as VTI
// series, NRRD files or the frame stream; forces and probes as CSV; a JSON report.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>

#include <omp.h>

#include <nlohmann/json.hpp>

#include "case_loader.hpp"
#include "comm.hpp"
#include "core/progress.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"
#include "core/stopwatch.hpp"
#include "core/threads.hpp"
#include "core/tool_main.hpp"
#include "field_output.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "formats/input.hpp"
#include "lbm/case_json.hpp"
#include "lbm/fields.hpp"
#include "lbm/solver.hpp"
#include "lbm/units.hpp"

namespace fest::lbmsim_tool {

using nlohmann::json;

void set_threads(int threads) { omp_set_num_threads(fest::resolve_threads(threads)); }

const char* precision_name(lbm::Precision p) noexcept { return p == lbm::Precision::f32 ? "float" : "double"; }

std::string build_features() {
  return mpi_built() ? "with MPI (" + std::string("Open MPI") + ")" : std::string("without MPI");
}

namespace {

void make_parent_dir(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (parent.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(parent, ec);
  if (ec) throw io_error("cannot create the output folder: {} ({})", ec.message(), parent.string());
}

// Sums per-layer values of every rank in global layer order (the same bits on any
// number of ranks and threads).
std::vector<double> global_layer_sum(lbm::SlabExchange& ex, const std::vector<double>& local, int comps) {
  const std::vector<double> all = ex.allgather(local);
  std::vector<double> s(comps, 0.0);
  for (std::size_t l = 0; l < all.size() / comps; ++l)
    for (int k = 0; k < comps; ++k) s[k] += all[l * comps + k];
  return s;
}

struct Output {
  std::string pattern;
  FieldFormat format = FieldFormat::stream;
  bool float64 = false, zlib = true;
  std::vector<std::pair<double, std::string>> series;
};

void write_frame(Output& out, const FieldFrame& f) {
  if (out.format == FieldFormat::stream) {
    const std::string bytes = encode_stream_frame(f, out.float64);
    if (std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size() || std::fflush(stdout) != 0)
      throw io_error("cannot write the frame stream (stdout)");
    return;
  }
  const std::string path = expand_pattern(out.pattern, f.index);
  make_parent_dir(path);
  if (out.format == FieldFormat::nrrd) {
    for (const auto& [name, bytes] : encode_nrrd(f, path, out.float64)) write_output(name, bytes);
    return;
  }
  write_output(path, encode_vti(f, out.float64, out.zlib));
  const std::filesystem::path p(path);
  out.series.emplace_back(f.time, p.filename().string());
  write_output((p.parent_path() / "series.pvd").string(), encode_pvd(out.series));
}

// init.file: a .vti that lbmsim wrote (or any image data of the lattice size) with a
// 3-component "velocity" and optionally "density"; physical velocities are converted.
void read_init_file(const lbm::Case& c, const std::string& where, std::vector<double>& rho, std::vector<double>& u) {
  std::string path = c.init.file;
  if (!path.empty() && path[0] != '/' && where != standard_input_name) {
    const std::filesystem::path dir = std::filesystem::path(where).parent_path();
    if (!dir.empty()) path = (dir / path).string();
  }
  const formats::Input in = formats::load_input(path);
  if (in.format != formats::Format::vti) throw bad_input("init.file must be a .vti ({})", path);
  const Dataset img = formats::parse(in, formats::read_dataset);
  if (img.kind != DatasetKind::image) throw bad_input("init.file holds no image data ({})", path);
  const auto dims = img.dimensions();
  if (dims[0] != c.size[0] || dims[1] != c.size[1] || dims[2] != c.size[2])
    throw bad_input("init.file is {}x{}x{} but size is {}x{}x{} ({})", dims[0], dims[1], dims[2], c.size[0], c.size[1],
                    c.size[2], path);
  // The first numeric point array of that name, as VTK's GetArray(name) finds it.
  auto numeric_array = [&img](const char* name) -> const DataArray* {
    for (const DataArray& a : img.point_data)
      if (a.name == name) return a.numeric() ? &a : nullptr;
    return nullptr;
  };
  const DataArray* v = numeric_array("velocity");
  if (!v || v->components != 3) throw bad_input("init.file has no 3-component \"velocity\" array ({})", path);
  const DataArray* d = numeric_array("density");
  const std::size_t N = c.cells();
  const double scale = c.units.physical ? c.units.dt() / c.units.dx : 1.0;
  rho.assign(N, c.init.rho);
  u.assign(3 * N, 0.0);
  for (std::size_t k = 0; k < N; ++k) {
    for (int a = 0; a < 3; ++a) u[3 * k + a] = v->component(k, a) * scale;
    if (d) rho[k] = d->component(k, 0);
    if (!std::isfinite(rho[k]) || !(rho[k] > 0) || !std::isfinite(u[3 * k]) || !std::isfinite(u[3 * k + 1]) ||
        !std::isfinite(u[3 * k + 2]))
      throw bad_input("init.file holds a non-finite or non-positive value at node {} ({})", k, path);
  }
}

// Reads the case and applies the run's flags to it: the usage and bad-input checks of a
// run, in the order a user meets them. Returns an exit status where this rank stops
// quietly (rank 0 reports the error), nothing where the run goes on.
std::optional<int> read_run_case(const RunOptions& o, Comm& comm, LoadedCase& L) {
  if (comm.size() > 1 && (o.case_file.empty() || o.case_file == "-")) {
    if (!comm.root()) return static_cast<int>(Status::usage);
    throw usage_error("mpirun gives standard input to rank 0 only: name the case file for {} ranks", comm.size());
  }
  try {
    L = load_case(o.case_file, o.set);
  } catch (const Error& e) {
    if (!comm.root()) return e.exit_code();  // every rank sees the same error; rank 0 reports it
    throw;
  }
  lbm::Case& c = L.c;
  if (o.steps >= 0) c.steps = o.steps, c.steady = false;
  if (o.every >= 0) c.output.every = o.every;
  if (o.fields) c.output.fields = *o.fields;
  if (o.compress) c.output.compress = *o.compress;
  lbm::check_field_names(c.output.fields, o.fields ? "--fields" : L.where);
  const long frames = c.output.every > 0 ? c.steps / c.output.every + 1 : 1;
  if (o.format != FieldFormat::stream && frames > 1 && !has_index_conversion(o.output))
    throw usage_error("-o \"{}\" needs a %d for {} output steps", o.output, frames);
  if (comm.root() && !o.quiet)
    for (const std::string& w : c.warnings) warn("lbmsim", w);
  return std::nullopt;
}

// The initial state of an init.file, kept while the solver is made from it.
struct InitFields {
  std::vector<double> rho, u;
};

// This rank's slab of the lattice, the precision and the initial state.
lbm::SolverSetup solver_setup(const RunOptions& o, Comm& comm, const LoadedCase& L, InitFields& init) {
  const lbm::Case& c = L.c;
  const int S = c.dim - 1;
  if (comm.size() > c.size[S])
    throw usage_error("{} ranks for {} layers along {}: a slab needs at least one layer; use at most {} ranks",
                      comm.size(), c.size[S], "xyz"[S], c.size[S]);
  const std::vector<int> starts = lbm::slab_starts(c.size[S], comm.size());

  lbm::SolverSetup setup;
  setup.c = &c;
  setup.flags = &L.flags;
  setup.precision = o.precision;
  setup.exchange = &comm.exchange();
  setup.slab_lo = starts[comm.rank()];
  setup.slab_hi = starts[comm.rank() + 1];
  if (c.init.kind == lbm::Init::Kind::taylor_green) {
    const double U = c.init.amplitude, kx = 2 * M_PI / c.size[0], ky = 2 * M_PI / c.size[1];
    setup.init = [=](int x, int y, int, double& rho, std::array<double, 3>& u) {
      rho = 1 - 0.75 * U * U * (std::cos(2 * kx * x) + std::cos(2 * ky * y));
      u = {-U * std::cos(kx * x) * std::sin(ky * y), U * std::sin(kx * x) * std::cos(ky * y), 0.0};
    };
  }
  if (c.init.kind == lbm::Init::Kind::file) {
    read_init_file(c, L.where, init.rho, init.u);
    const int nx = c.size[0], ny = c.size[1];
    setup.init = [&init, nx, ny](int x, int y, int z, double& rho, std::array<double, 3>& u) {
      const std::size_t k = static_cast<std::size_t>(x) + static_cast<std::size_t>(nx) * (y + static_cast<std::size_t>(ny) * z);
      rho = init.rho[k];
      u = {init.u[3 * k], init.u[3 * k + 1], init.u[3 * k + 2]};
    };
  }
  return setup;
}

// What one run works with: the case, this rank's solver, the units and the outputs.
struct RunContext {
  Comm& comm;
  const lbm::Case& c;
  const LoadedCase& L;
  lbm::Solver& solver;
  const lbm::UnitTable& units;
  Output& out;
  Progress* bar = nullptr;  // --progress: steps done of the case's
};

// The forces and probes CSV as they grow, and each force flag's drag coefficient
// statistics (sum, min, max, last).
struct RunRecords {
  std::string forces_csv, probes_csv;
  std::map<int, std::array<double, 4>> cd_stats;
};

// How the time loop ended, and the last gathered state.
struct RunTotals {
  long steps_done = 0;
  double residual = -1;
  bool converged = false;
  std::vector<double> rho, u;
};

void gathered_moments(RunContext& x, std::vector<double>& rho, std::vector<double>& u) {
  std::vector<double> r, v;
  x.solver.moments(r, v);
  rho = x.comm.exchange().allgather(r);
  u = x.comm.exchange().allgather(v);
}

double total_mass(RunContext& x) { return global_layer_sum(x.comm.exchange(), x.solver.layer_mass(), 1)[0]; }

void record_forces(RunContext& x, RunRecords& rec, long step) {
  const lbm::Case& c = x.c;
  const double dt = x.units.dt;
  const double ref_len = c.lref(), ref_u = c.u_ref;
  for (int id : c.forces) {
    const auto F = global_layer_sum(x.comm.exchange(), x.solver.layer_force(static_cast<std::uint8_t>(id)), 3);
    const double norm = 0.5 * ref_u * ref_u * (c.dim == 3 ? ref_len * ref_len : ref_len);
    const double cd = F[0] / norm, cl = F[1] / norm;
    auto& st = rec.cd_stats[id];
    if (step == 1) st = {0, cd, cd, cd};
    st[0] += cd, st[1] = std::min(st[1], cd), st[2] = std::max(st[2], cd), st[3] = cd;
    if (!rec.forces_csv.empty())
      rec.forces_csv += fmt::format("{},{:.17g},{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", step, step * dt, id,
                                    F[0] * x.units.force_scale, F[1] * x.units.force_scale, F[2] * x.units.force_scale, cd, cl);
  }
}

void record_probes(RunContext& x, RunRecords& rec, long step, const std::vector<double>& rho, const std::vector<double>& u) {
  const lbm::Case& c = x.c;
  const double dt = x.units.dt;
  for (std::size_t p = 0; p < c.probes.size(); ++p) {
    int ix[3];
    for (int a = 0; a < 3; ++a)
      ix[a] = a < c.dim ? std::clamp(static_cast<int>(std::floor(c.probes[p][a])), 0, c.size[a] - 1) : 0;
    const std::size_t k = x.L.flags.index(ix[0], ix[1], ix[2]);
    rec.probes_csv += fmt::format("{},{:.17g},{},{},{},{},{:.17g},{:.17g},{:.17g},{:.17g}\n", step, step * dt, p,
                                  c.probes[p][0], c.probes[p][1], c.probes[p][2], rho[k], u[3 * k] * x.units.dx / dt,
                                  u[3 * k + 1] * x.units.dx / dt, u[3 * k + 2] * x.units.dx / dt);
  }
}

// Writes the fields of one output step (rank 0 only).
void emit_fields(RunContext& x, long step, const std::vector<double>& rho, const std::vector<double>& u) {
  if (!x.comm.root()) return;
  const lbm::Case& c = x.c;
  const double dt = x.units.dt;
  FieldFrame f;
  f.index = step;
  f.time = step * dt;
  f.dim = c.dim;
  f.size = c.size;
  f.spacing = x.units.dx;
  std::vector<double> uphys = u;
  if (c.units.physical)
    for (double& v : uphys) v *= x.units.dx / dt;
  f.fields = lbm::derived_fields(c.output.fields, c, x.L.flags, rho, uphys, x.units.pressure_scale, x.units.dx);
  write_frame(x.out, f);
}

// The time loop: steps, forces every step, and at the check, output and steady-state
// steps the gathered state (guarded against divergence), probes and frames; the last
// state is written unless it just was.
void time_steps(RunContext& x, RunRecords& rec, RunTotals& t) {
  const lbm::Case& c = x.c;
  std::vector<double>& rho = t.rho;
  std::vector<double>& u = t.u;
  std::vector<double> prev_u;
  if (c.output.every > 0) {
    gathered_moments(x, rho, u);
    emit_fields(x, 0, rho, u);
  }
  for (long step = 1; step <= c.steps; ++step) {
    x.solver.step();
    t.steps_done = step;
    if (x.bar) x.bar->set(static_cast<std::uint64_t>(step));
    if (!c.forces.empty()) record_forces(x, rec, step);
    const bool guard = step % c.check_every == 0;
    const bool write = c.output.every > 0 && step % c.output.every == 0;
    const bool steady_check = c.steady && step % 1000 == 0;
    if (!(guard || write || steady_check || (!rec.probes_csv.empty() && guard))) continue;
    gathered_moments(x, rho, u);
    double umax = 0;
    bool finite = true;
    for (double v : u) {
      finite = finite && std::isfinite(v);
      umax = std::max(umax, std::abs(v));
    }
    for (double v : rho) finite = finite && std::isfinite(v);
    if (!finite) throw runtime_failure("state became non-finite at step {} (velocity)", step);
    if (umax > 0.5) throw runtime_failure("lattice speed {:.3g} > 0.5 at step {}: the run diverges", umax, step);
    if (!rec.probes_csv.empty() && guard) record_probes(x, rec, step, rho, u);
    if (write) emit_fields(x, step, rho, u);
    if (steady_check) {
      if (!prev_u.empty()) {
        double d = 0;
        for (std::size_t k = 0; k < u.size(); ++k) d = std::max(d, std::abs(u[k] - prev_u[k]));
        t.residual = d / c.u_ref;
        if (t.residual < c.tol) {
          t.converged = true;
          break;
        }
      }
      prev_u = u;
    }
  }
  if (c.output.every == 0 || t.steps_done % c.output.every != 0) {
    gathered_moments(x, rho, u);
    emit_fields(x, t.steps_done, rho, u);
  }
}

void write_run_report(const RunOptions& o, RunContext& x, const RunRecords& rec, const RunTotals& t, double seconds,
                      std::size_t fluid, double m0, double m1) {
  const lbm::Case& c = x.c;
  json r;
  r["case"] = lbm::case_to_json(c);
  r["units"] = lbm::unit_table_json(x.units, c);
  r["steps"] = t.steps_done;
  r["converged"] = t.converged;
  if (t.residual >= 0) r["final_residual"] = t.residual;
  r["wall_seconds"] = seconds;
  r["mlups"] = seconds > 0 ? static_cast<double>(fluid) * t.steps_done / seconds / 1e6 : 0.0;
  r["threads"] = omp_get_max_threads();
  r["ranks"] = x.comm.size();
  r["precision"] = precision_name(o.precision);
  double umax = 0;
  for (double v : t.u) umax = std::max(umax, std::abs(v));
  r["max_speed"] = umax;
  r["mass_drift"] = std::abs(m1 - m0) / m0;
  json fs = json::object();
  for (const auto& [id, st] : rec.cd_stats)
    fs[std::to_string(id)] = {{"cd_mean", st[0] / std::max<long>(1, t.steps_done)}, {"cd_min", st[1]}, {"cd_max", st[2]}, {"cd_last", st[3]}};
  r["forces"] = fs;
  write_output(o.report, r.dump(2) + "\n");
}

}  // namespace

int run_command(const RunOptions& o) {
  // The flags were checked in main.cpp (usage errors); now the case (bad input).
  Comm& comm = Comm::world();
  LoadedCase L;
  if (const std::optional<int> status = read_run_case(o, comm, L)) return *status;
  const lbm::Case& c = L.c;
  Output out;
  out.pattern = o.output;
  out.format = o.format;
  out.float64 = c.output.float64;
  out.zlib = c.output.compress;

  InitFields init;
  auto solver = lbm::make_solver(solver_setup(o, comm, L, init));
  const lbm::UnitTable units = lbm::unit_table(c, o.precision == lbm::Precision::f32);
  Progress bar("lbmsim run", static_cast<std::uint64_t>(std::max(0L, c.steps)), comm.root() && progress_wanted(o.progress));
  RunContext x{comm, c, L, *solver, units, out, &bar};
  RunRecords rec;
  if (!o.forces.empty()) rec.forces_csv = "step,t,flag,Fx,Fy,Fz,CD,CL\n";
  if (!o.probes.empty()) rec.probes_csv = "step,t,probe,x,y,z,rho,ux,uy,uz\n";

  const double m0 = total_mass(x);
  const auto t0 = SteadyClock::now();
  RunTotals totals;
  try {
    time_steps(x, rec, totals);
    bar.finish();
  } catch (const Error& e) {
    if (comm.size() > 1 && e.status() == Status::io) {
      std::fprintf(stderr, "lbmsim: error: %s\n", e.what());
      comm.abort(e.exit_code());
    }
    if (!comm.root()) return e.exit_code();
    throw;
  }
  const double seconds = seconds_since(t0);
  const double m1 = total_mass(x);
  std::size_t fluid = solver->fluid_nodes();
  fluid = static_cast<std::size_t>(global_layer_sum(comm.exchange(), {static_cast<double>(fluid)}, 1)[0]);
  if (!comm.root()) return 0;
  if (!o.forces.empty()) write_output(o.forces, rec.forces_csv);
  if (!o.probes.empty()) write_output(o.probes, rec.probes_csv);
  if (!o.report.empty()) write_run_report(o, x, rec, totals, seconds, fluid, m0, m1);
  return 0;
}

}  // namespace fest::lbmsim_tool

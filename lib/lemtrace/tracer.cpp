#include "lemtrace/tracer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/parallel_for.hpp"

namespace fest::lemtrace {

const char* method_name(Method m) noexcept {
  switch (m) {
    case Method::lem: return "lem";
    case Method::euler: return "euler";
    case Method::heun: return "heun";
    case Method::rk3: return "rk3";
    case Method::rk4: return "rk4";
    case Method::rk45: return "rk45";
  }
  return "?";
}

const char* reason_name(Reason r) noexcept {
  switch (r) {
    case Reason::none: return "none";
    case Reason::out_of_domain: return "out_of_domain";
    case Reason::not_initialized: return "not_initialized";
    case Reason::unexpected_value: return "unexpected_value";
    case Reason::out_of_length: return "out_of_length";
    case Reason::out_of_steps: return "out_of_steps";
    case Reason::stagnation: return "stagnation";
    case Reason::critical_point: return "critical_point";
    case Reason::out_of_time: return "out_of_time";
  }
  return "?";
}

namespace {

// The vertices of the line being traced. They go to a per-thread buffer that keeps its
// capacity from one line to the next and are copied into the Polyline once, at the exact
// size, when the line ends (growing the Polyline's four vectors vertex by vertex
// reallocated and copied them about log2(n) times per line). Shared by the LEM and the
// Runge-Kutta baselines, so that output costs the same in both.
class VertexBuffer {
 public:
  std::size_t size() const noexcept { return n_; }
  // Starts a line (also after a line that ended by an exception).
  void clear() noexcept { n_ = 0; }
  void push(const Vec3& x, double t, int32_t cell, CellType type) {
    if (n_ == x_.size()) grow();
    x_[n_] = x;
    t_[n_] = t;
    cell_[n_] = cell;
    type_[n_] = static_cast<uint8_t>(type);
    ++n_;
  }
  // Hands the vertices to `line` and empties the buffer (its capacity stays).
  void move_to(Polyline& line) {
    const auto n = static_cast<std::ptrdiff_t>(n_);
    line.x.assign(x_.begin(), x_.begin() + n);
    line.t.assign(t_.begin(), t_.begin() + n);
    line.cell.assign(cell_.begin(), cell_.begin() + n);
    line.type.assign(type_.begin(), type_.begin() + n);
    n_ = 0;
  }

 private:
  void grow() {
    const std::size_t m = std::max<std::size_t>(1024, 2 * x_.size());
    x_.resize(m);
    t_.resize(m);
    cell_.resize(m);
    type_.resize(m);
  }
  std::vector<Vec3> x_;
  std::vector<double> t_;
  std::vector<int32_t> cell_;
  std::vector<uint8_t> type_;
  std::size_t n_ = 0;
};

double terminal_speed(const FieldGrid& grid, const TraceOptions& o) {
  return o.terminal_speed >= 0 ? o.terminal_speed : 1e-12 * grid.max_speed();
}

// The smallest e >= -127 with 2^e > v_stop: a cell whose record bounds its speed from
// below by 2^speed_log2 >= 2^e cannot stop a line (no bound: INT8_MIN < -127).
int speed_threshold_log2(double v_stop) {
  if (!(v_stop > 0)) return -127;
  if (!std::isfinite(v_stop)) return std::numeric_limits<int>::max();
  int e;
  std::frexp(v_stop, &e);  // 2^(e-1) <= v_stop < 2^e
  return std::max(e, -127);
}

// ---- locally exact method -------------------------------------------------------------

// Barycentric coordinates, in the neighbour `to`, of a point given by `beta` in `from`
// on their shared face: the shared vertices keep their weights, the vertex of `to`
// opposite the face gets 0 (the chapter's C4 face correspondence, found from the four
// vertex ids instead of stored). No point location and no geometry are needed.
Eigen::Vector4d across_face(const Tet& from, const Tet& to, const Eigen::Vector4d& beta) {
  Eigen::Vector4d out;
  for (int j = 0; j < 4; ++j) {
    const int32_t id = to[j];
    out[j] = id == from[0] ? beta[0] : id == from[1] ? beta[1] : id == from[2] ? beta[2] : id == from[3] ? beta[3] : 0.0;
  }
  const double sum = out.sum();
  if (sum > 0 && sum != 1.0) out /= sum;
  return out;
}

// The world point sum_k beta_k V_k of the tet.
inline Vec3 tet_point(const TetMesh& mesh, const Tet& tet, const Eigen::Vector4d& b) {
  return Vec3(b[0] * mesh.points[static_cast<std::size_t>(tet[0])] + b[1] * mesh.points[static_cast<std::size_t>(tet[1])] +
              b[2] * mesh.points[static_cast<std::size_t>(tet[2])] + b[3] * mesh.points[static_cast<std::size_t>(tet[3])]);
}

// The interpolated field sum_k beta_k v_k of the tet.
inline Vec3 tet_field(const TetMesh& mesh, const Tet& tet, const Eigen::Vector4d& b) {
  return Vec3(b[0] * mesh.vectors[static_cast<std::size_t>(tet[0])] + b[1] * mesh.vectors[static_cast<std::size_t>(tet[1])] +
              b[2] * mesh.vectors[static_cast<std::size_t>(tet[2])] + b[3] * mesh.vectors[static_cast<std::size_t>(tet[3])]);
}

void trace_lem(const FieldGrid& grid, int32_t cell, const Vec3& seed, double t0, double dir,
               const TraceOptions& o, Polyline& line, VertexBuffer& out) {
  const TetMesh& mesh = grid.mesh();
  const double v_stop = terminal_speed(grid, o);
  const int stop_log2 = speed_threshold_log2(v_stop);
  const bool try_fast = o.exit.predict && !o.exit.paper_newton;
  const bool limit_length = o.max_length < std::numeric_limits<double>::infinity();
  CellRecord scratch;
  Vec3 x = seed;
  double t = t0, length = 0;
  {
    const CellRecord& rec = grid.record(cell, scratch);
    out.push(x, t, cell, rec.type);
  }
  // The entry point's barycentric coordinates in `cell`, carried over from the previous
  // cell's exit (have_beta) so that a normal cell in the barycentric frame needs no
  // geometry at all; the seed cell computes them once.
  Eigen::Vector4d carried = Eigen::Vector4d::Zero();
  bool have_beta = false;
  int hops = 0, stuck = 0;
  // The line has reached the exit point x at time t through face e.face: the point is
  // recorded, then the line ends (length spent, the domain's boundary) or enters the
  // neighbour with its entry coordinates carried over. False when the line ends.
  // The speed test at a cell's entry point (squared speed): false when the line ends
  // there, on a non-finite field or at rest (a critical point inside, else stagnation).
  auto keeps_moving = [&](double speed2, const CellRecord& rec) {
    if (!std::isfinite(speed2)) {
      line.reason = Reason::unexpected_value;
      return false;
    }
    if (speed2 <= v_stop * v_stop) {
      line.reason = rec.critical_inside ? Reason::critical_point : Reason::stagnation;
      return false;
    }
    return true;
  };
  auto leave_through = [&](const ExitResult& e, const CellRecord& rec, const Tet& tet) {
    if (e.tau > 0 || out.size() == 1) out.push(x, t, cell, rec.type);
    if (length > o.max_length) {
      line.reason = Reason::out_of_length;
      return false;
    }
    const int32_t next = mesh.neighbors[static_cast<std::size_t>(cell)][e.face];
    if (next < 0) {
      line.reason = Reason::out_of_domain;
      return false;
    }
    carried = across_face(tet, mesh.tets[static_cast<std::size_t>(next)], e.beta);
    have_beta = true;
    cell = next;
    return true;
  };
  for (;;) {
    if (line.cells >= o.max_steps) {
      line.reason = Reason::out_of_steps;
      return;
    }
    const CellRecord& rec = grid.record(cell, scratch);
    const Tet& tet = mesh.tets[static_cast<std::size_t>(cell)];
    // The common crossing: a precomputed normal cell entered through a face, whose
    // predicted exit (eigen coordinates, no geometry) answers. Everything else, and the
    // rare crossing that ends the line by time or wants samples inside the cell, takes
    // the general path below, which decides the same way.
    if (have_beta && rec.bary_frame && try_fast) {
      if (rec.speed_log2 < stop_log2) {
        if (!keeps_moving(tet_field(mesh, tet, carried).squaredNorm(), rec)) return;
      }
      ExitResult e;
      if (predicted_exit_local(rec, carried, dir, e) && !(std::abs(t - t0) + e.tau > o.max_time) &&
          o.samples_per_cell <= 1) {
        hops = 0;
        const Vec3 e_x = tet_point(mesh, tet, e.beta);
        ++line.cells;
        line.evaluations += e.evaluations;
        if (!e_x.allFinite()) {
          line.reason = Reason::unexpected_value;
          return;
        }
        // No progress (see below): the same point again.
        stuck = e_x == x ? stuck + 1 : 0;
        if (stuck > 64) {
          line.reason = Reason::unexpected_value;
          return;
        }
        if (limit_length) length += (e_x - x).norm();
        x = e_x;
        t += dir * e.tau;
        if (!leave_through(e, rec, tet)) return;
        continue;
      }
    }
    const bool local = rec.bary_frame;
    // Normal cells are traced in their barycentric frame (positions u = beta_{1..3}),
    // the others in world coordinates with the cell's geometry.
    TetGeometry g;
    if (!local) g = tet_geometry(mesh, cell);
    Eigen::Vector4d beta;
    if (local && have_beta) beta = carried;
    else {
      if (local) g = tet_geometry(mesh, cell);
      beta = g.bary(x);
    }
    auto world = [&](const Eigen::Vector4d& b) { return tet_point(mesh, tet, b); };
    auto world_of_u = [&](const Vec3& u) { return world(Eigen::Vector4d(1.0 - u.sum(), u[0], u[1], u[2])); };
    // The interpolated (world) field: the speed test is the same in both frames.
    const Vec3 v = local ? tet_field(mesh, tet, beta) : g.interpolate(beta);
    const double speed2 = v.squaredNorm();
    if (!keeps_moving(speed2, rec)) return;
    // A precomputed normal cell first tries the predicted exit in eigen coordinates
    // (no CellPath, no geometry); everything else, and whatever it declines, goes
    // through the general search below (edge/vertex hops included).
    ExitResult e;
    const bool fast = local && o.exit.predict && !o.exit.paper_newton && predicted_exit_local(rec, beta, dir, e);
    const Vec3 pos = local ? Vec3(beta[1], beta[2], beta[3]) : x;
    std::optional<CellPath> lazy_path;
    auto path_of = [&]() -> const CellPath& {
      if (!lazy_path) lazy_path.emplace(rec, pos, dir);
      return *lazy_path;
    };
    if (!fast) {
      const CellPath& path = path_of();
      const UnitGeometry ug(local ? rec.tau_bary : 1.0);
      // The field in the frame of the path (u' for a local cell) and the rate of beta.
      const Vec3 f = local ? path.entry_field() : v;
      const Eigen::Vector4d rate = local ? ug.bary_rate(dir * f) : g.bary_rate(dir * v);
      const double rate_scale = local ? ug.h_min * f.norm() : std::sqrt(speed2) / g.h_min;
      // On an edge or vertex the path may leave at once through another face of this
      // cell (the edge/vertex ambiguity rule): hop there without a step.
      int leave = -1;
      double most = 0;
      for (int k = 0; k < 4; ++k) {
        if (beta[k] <= 1e-13 && rate[k] < -1e-12 * rate_scale && rate[k] < most) {
          most = rate[k];
          leave = k;
        }
      }
      if (leave >= 0 && hops < 16) {
        const int32_t next = mesh.neighbors[static_cast<std::size_t>(cell)][leave];
        if (next < 0) {
          line.reason = Reason::out_of_domain;
          return;
        }
        Eigen::Vector4d b = beta;
        b[leave] = 0;
        carried = across_face(tet, mesh.tets[static_cast<std::size_t>(next)], b);
        have_beta = true;
        cell = next;
        ++hops;
        continue;
      }
      const EntryValues entry{beta, f};
      e = local ? find_exit(ug, path, o.exit, &entry) : find_exit(g, path, o.exit, &entry);
    }
    hops = 0;

    const Vec3 e_x = local ? world(e.beta) : e.x;
    ++line.cells;
    line.evaluations += e.evaluations;
    const double elapsed = std::abs(t - t0);
    const double tau = e.tau;
    auto position = [&](double s) { return local ? world_of_u(path_of().position(s)) : path_of().position(s); };
    if (elapsed + tau > o.max_time) {
      const double rest = o.max_time - elapsed;
      out.push(position(rest), t + dir * rest, cell, rec.type);
      line.reason = Reason::out_of_time;
      return;
    }
    if (o.samples_per_cell > 1 && tau > 0)
      for (int j = 1; j < o.samples_per_cell; ++j) {
        const double s = tau * j / o.samples_per_cell;
        out.push(position(s), t + dir * s, cell, rec.type);
      }
    if (e.kind != ExitResult::exit) {
      if (e.tau > 0) out.push(local ? world_of_u(e.x) : e.x, t + dir * e.tau, cell, rec.type);
      line.reason = rec.critical_inside ? Reason::critical_point : Reason::stagnation;
      return;
    }
    if (!e_x.allFinite()) {
      line.reason = Reason::unexpected_value;
      return;
    }
    // A path that makes no progress (it alternates between cells at one point, which
    // round-off on a face can cause) is stopped rather than spun to --max-steps.
    const double moved = (e_x - x).norm();
    stuck = moved == 0 ? stuck + 1 : 0;
    if (stuck > 64) {
      line.reason = Reason::unexpected_value;
      return;
    }
    length += moved;
    x = e_x;
    t += dir * tau;
    if (!leave_through(e, rec, tet)) return;
  }
}

// ---- Runge-Kutta baselines -------------------------------------------------------------

struct Sampler {
  const FieldGrid& grid;
  Polyline& line;
  double dir;
  int32_t cell;
  bool search;  // bin-grid search instead of the neighbour walk
  // v at x (times dir); false outside the grid.
  bool operator()(const Vec3& x, Vec3& v) {
    ++line.evaluations;
    // Point location (the walk) is the part of each evaluation that the LEM does not
    // pay (§9.2.1-9.2.3); its inside test gives the barycentric weights, so the
    // interpolation itself is four vertex vectors.
    Eigen::Vector4d beta;
    int32_t c;
    if (search) {
      ++line.locator_calls;
      c = grid.locator().locate(x);
      if (c >= 0) beta = barycentric(grid.mesh(), c, x);
    } else {
      c = grid.locator().walk(cell, x, &line.locator_calls, &beta);
    }
    if (c < 0) return false;
    cell = c;
    const TetMesh& mesh = grid.mesh();
    const Tet& t = mesh.tets[static_cast<std::size_t>(c)];
    v = dir * (beta[0] * mesh.vectors[static_cast<std::size_t>(t[0])] + beta[1] * mesh.vectors[static_cast<std::size_t>(t[1])] +
               beta[2] * mesh.vectors[static_cast<std::size_t>(t[2])] + beta[3] * mesh.vectors[static_cast<std::size_t>(t[3])]);
    return v.allFinite();
  }
};

void trace_rk(const FieldGrid& grid, int32_t cell, const Vec3& seed, double t0, double dir, const TraceOptions& o,
              Polyline& line, VertexBuffer& out) {
  const double v_stop = terminal_speed(grid, o);
  Sampler field{grid, line, dir, cell, o.rk_cell_search};
  CellRecord scratch;
  Vec3 x = seed;
  double t = t0, length = 0;
  out.push(x, t, cell, grid.record(cell, scratch).type);
  double h_adapt = -1;
  // The field at the end of a step (evaluated there to see that the step stays in the
  // grid) is the next step's k1: one field evaluation per stage, as the methods count.
  Vec3 k1;
  if (!field(x, k1)) {
    line.reason = Reason::out_of_domain;
    return;
  }
  for (;;) {
    if (line.cells >= o.max_steps) {
      line.reason = Reason::out_of_steps;
      return;
    }
    const double speed = k1.norm();
    if (speed <= v_stop) {
      line.reason = Reason::stagnation;
      return;
    }
    double h = o.step;
    if (o.step_unit == StepUnit::length) h = o.step / speed;
    if (o.step_unit == StepUnit::cell) h = o.step * tet_geometry(grid.mesh(), field.cell).h_min / speed;
    if (o.method == Method::rk45 && h_adapt > 0) h = h_adapt;
    const double elapsed = std::abs(t - t0);
    bool last = false;
    if (elapsed + h >= o.max_time) {
      h = o.max_time - elapsed;
      last = true;
    }
    Vec3 next = x, k2 = Vec3::Zero(), k3 = Vec3::Zero(), k4 = Vec3::Zero();
    bool ok = true;
    switch (o.method) {
      case Method::euler:
        next = x + h * k1;
        break;
      case Method::heun:
        ok = field(x + h * k1, k2);
        next = x + 0.5 * h * (k1 + k2);
        break;
      case Method::rk3:
        ok = field(x + 0.5 * h * k1, k2) && field(x - h * k1 + 2 * h * k2, k3);
        next = x + h / 6 * (k1 + 4 * k2 + k3);
        break;
      case Method::rk4:
        ok = field(x + 0.5 * h * k1, k2) && field(x + 0.5 * h * k2, k3) && field(x + h * k3, k4);
        next = x + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        break;
      case Method::rk45: {
        // Dormand-Prince 5(4) with step control.
        Vec3 k[7];
        k[0] = k1;
        static const double a[6][6] = {{1.0 / 5},
                                       {3.0 / 40, 9.0 / 40},
                                       {44.0 / 45, -56.0 / 15, 32.0 / 9},
                                       {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
                                       {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
                                       {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}};
        static const double e[7] = {71.0 / 57600, 0, -71.0 / 16695, 71.0 / 1920, -17253.0 / 339200, 22.0 / 525,
                                    -1.0 / 40};
        for (int s = 1; s < 7 && ok; ++s) {
          Vec3 y = x;
          for (int j = 0; j < s; ++j) y += h * a[s - 1][j] * k[j];
          ok = field(y, k[s]);
          if (s == 6) next = y;
        }
        if (ok) {
          Vec3 err = Vec3::Zero();
          for (int s = 0; s < 7; ++s) err += h * e[s] * k[s];
          const double en = err.norm();
          const double factor = en > 0 ? std::clamp(0.9 * std::pow(o.tolerance / en, 0.2), 0.2, 5.0) : 5.0;
          if (en > o.tolerance && !last) {
            h_adapt = h * factor;
            continue;  // reject, retry smaller
          }
          h_adapt = h * factor;
        }
        break;
      }
      case Method::lem:
        break;
    }
    Vec3 k_next;
    if (!ok || !field(next, k_next)) {
      line.reason = Reason::out_of_domain;
      return;
    }
    k1 = k_next;
    ++line.cells;
    length += (next - x).norm();
    x = next;
    t += dir * h;
    out.push(x, t, field.cell, grid.record(field.cell, scratch).type);
    if (last) {
      line.reason = Reason::out_of_time;
      return;
    }
    if (length > o.max_length) {
      line.reason = Reason::out_of_length;
      return;
    }
  }
}

Polyline trace_one(const FieldGrid& grid, int32_t cell, const Vec3& seed, double t0, double dir,
                   const TraceOptions& o) {
  // One buffer per thread; it holds on to the memory of the longest line the thread has
  // traced (at most --max-steps vertices).
  thread_local VertexBuffer out;
  out.clear();
  Polyline line;
  if (o.method == Method::lem) trace_lem(grid, cell, seed, t0, dir, o, line, out);
  else trace_rk(grid, cell, seed, t0, dir, o, line, out);
  out.move_to(line);
  return line;
}

}  // namespace

Polyline trace(const FieldGrid& grid, const Vec3& seed, double t0, const TraceOptions& options) {
  Polyline line;
  int64_t calls = 0;
  const int32_t cell = seed.allFinite() ? grid.locator().locate(seed) : -1;
  ++calls;
  if (cell < 0) {
    line.reason = Reason::not_initialized;
    line.locator_calls = calls;
    return line;
  }
  if (options.direction == Direction::forward) line = trace_one(grid, cell, seed, t0, 1.0, options);
  else if (options.direction == Direction::backward) line = trace_one(grid, cell, seed, t0, -1.0, options);
  else {
    Polyline back = trace_one(grid, cell, seed, t0, -1.0, options);
    line = trace_one(grid, cell, seed, t0, 1.0, options);
    // Join: the backward half reversed, then the forward half (the seed once).
    Polyline joined;
    for (std::size_t i = back.x.size(); i-- > 1;) {
      joined.x.push_back(back.x[i]);
      joined.t.push_back(back.t[i]);
      joined.cell.push_back(back.cell[i]);
      joined.type.push_back(back.type[i]);
    }
    joined.x.insert(joined.x.end(), line.x.begin(), line.x.end());
    joined.t.insert(joined.t.end(), line.t.begin(), line.t.end());
    joined.cell.insert(joined.cell.end(), line.cell.begin(), line.cell.end());
    joined.type.insert(joined.type.end(), line.type.begin(), line.type.end());
    joined.reason = line.reason;
    joined.reason_backward = back.reason;
    joined.cells = line.cells + back.cells;
    joined.locator_calls = line.locator_calls + back.locator_calls;
    joined.evaluations = line.evaluations + back.evaluations;
    line = std::move(joined);
  }
  line.locator_calls += calls;
  return line;
}

std::vector<Polyline> trace_all(const FieldGrid& grid, const std::vector<Vec3>& seeds, const std::vector<double>& t0,
                                const TraceOptions& options, int threads) {
  std::vector<Polyline> lines(seeds.size());
  grid.locator();
  ProgressCounter done(options.progress, seeds.size());
  parallel_for(seeds.size(), threads, [&](std::size_t i) {
    lines[i] = trace(grid, seeds[i], i < t0.size() ? t0[i] : 0.0, options);
    done.step();
  });
  done.finish();
  return lines;
}

}  // namespace fest::lemtrace

#pragma once
// Whole paths (docs/lemtrace.md §4): the locally exact method, one closed-form step per cell
// with face-neighbour traversal, and the classical integrators for comparison.

#include <cstdint>
#include <limits>
#include <vector>

#include "core/progress_callback.hpp"
#include "lemtrace/exit_search.hpp"
#include "lemtrace/field_grid.hpp"

namespace fest::lemtrace {

enum class Method { lem, euler, heun, rk3, rk4, rk45 };
const char* method_name(Method m) noexcept;

// Codes as vtkStreamTracer's ReasonForTermination, plus 7 and 8.
enum class Reason : int {
  none = 0,
  out_of_domain = 1,
  not_initialized = 2,
  unexpected_value = 3,
  out_of_length = 4,
  out_of_steps = 5,
  stagnation = 6,
  critical_point = 7,
  out_of_time = 8,
};
const char* reason_name(Reason r) noexcept;

enum class StepUnit { time, length, cell };
enum class Direction { forward, backward, both };

struct TraceOptions {
  Method method = Method::lem;
  ExitParams exit;
  Direction direction = Direction::forward;
  int64_t max_steps = 100000;                                  // cells (LEM) or steps
  double max_length = std::numeric_limits<double>::infinity();
  double max_time = std::numeric_limits<double>::infinity();
  double terminal_speed = -1;                                  // < 0: 1e-12 x max vertex speed
  double step = 0.2;                                           // RK methods
  StepUnit step_unit = StepUnit::cell;
  double tolerance = 1e-6;                                     // RK45 error per step
  int samples_per_cell = 0;                                    // extra closed-form points (LEM)
  // RK point location: false walks face neighbours from the last cell (the default, the
  // cheapest); true searches the bin grid at every field evaluation, the chapter's
  // §9.2.1 loop ("a time consuming cell search is needed for every evaluation"), for
  // the Table 9.4 comparison.
  bool rk_cell_search = false;
  // Seeds traced so far of all of them, on the calling thread (trace_all; empty: none).
  ProgressFn progress;
};

struct Polyline {
  std::vector<Vec3> x;
  std::vector<double> t;
  std::vector<int32_t> cell;
  std::vector<uint8_t> type;    // CellType of the cell the segment ending here crossed
  Reason reason = Reason::none;
  Reason reason_backward = Reason::none;  // for Direction::both
  int64_t cells = 0;            // cells crossed (LEM) or steps taken (RK)
  int64_t locator_calls = 0;    // barycentric tests for point location
  int64_t evaluations = 0;      // closed-form evaluations (LEM), field evaluations (RK)
};

Polyline trace(const FieldGrid& grid, const Vec3& seed, double t0, const TraceOptions& options);

// Traces every seed on `threads` threads; the result is in seed order.
std::vector<Polyline> trace_all(const FieldGrid& grid, const std::vector<Vec3>& seeds,
                                const std::vector<double>& t0, const TraceOptions& options, int threads);

}  // namespace fest::lemtrace

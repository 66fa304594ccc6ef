#pragma once
// The Table 9.4 setting shared by bench_lemtrace_steps and bench_lemtrace_locate:
// `lemtrace gen sphere-rotation --n 20`, 50 seeds on (0.55, 0, 0.13)-(0.8, 0, 0.13), one
// revolution, and the Runge-Kutta step that gives a line as many steps as the LEM crossed
// cells on it (h = T / S), exactly as `lemtrace bench` sets it.

#include <algorithm>
#include <cmath>
#include <vector>

#include "lemtrace/generate.hpp"
#include "lemtrace/tracer.hpp"

namespace fest::lemtrace::bench {

// The grid's mesh; `field` receives its analytic field when given.
inline TetMesh table94_mesh(LinearField* field = nullptr) {
  GenOptions gen;
  gen.kind = "sphere-rotation";
  gen.n = 20;
  GeneratedGrid g = generate(gen);
  if (field) *field = g.field;
  return build_tet_mesh(std::move(g.points), std::move(g.vectors), g.cells, BuildOptions{}, nullptr);
}

inline std::vector<Vec3> table94_seeds() {
  const int n = 50;
  std::vector<Vec3> seeds;
  for (int i = 0; i < n; ++i) seeds.emplace_back(0.55 + 0.25 * static_cast<double>(i) / (n - 1), 0.0, 0.13);
  return seeds;
}

// The LEM over one revolution.
inline TraceOptions table94_lem() {
  TraceOptions o;
  o.max_time = 2 * M_PI;
  return o;
}

// Method m on the line whose LEM trace is `ref`: the LEM's options for the LEM, else as
// many steps as `ref` crossed cells over the same time.
inline TraceOptions equal_step_options(Method m, const Polyline& ref) {
  TraceOptions o = table94_lem();
  o.method = m;
  if (m == Method::lem) return o;
  const double T = std::abs(ref.t.back());
  o.max_steps = std::max<int64_t>(1, ref.cells);
  o.step_unit = StepUnit::time;
  o.step = T / static_cast<double>(o.max_steps);
  o.max_time = T;
  return o;
}

}  // namespace fest::lemtrace::bench

#pragma once
// The OpenMP team of fluidsim's solver (lib/fluidsim runs its loops under OpenMP).

namespace fest::fluidsim_tool {

// Sets the team size for --threads of run and check (0: all cores).
void set_threads(int threads);
// The team size now in effect.
int omp_threads();

}  // namespace fest::fluidsim_tool

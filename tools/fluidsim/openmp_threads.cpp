// OpenMP team size from --threads (fest::resolve_threads: 0 = all cores).
#include "openmp_threads.hpp"

#include <omp.h>

#include "core/threads.hpp"

namespace fest::fluidsim_tool {

int omp_threads() { return omp_get_max_threads(); }

void set_threads(int threads) { omp_set_num_threads(fest::resolve_threads(threads)); }

}  // namespace fest::fluidsim_tool

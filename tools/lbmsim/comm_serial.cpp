// The build without MPI: one process; a launch by mpirun on several ranks is refused.
#include <cstdlib>
#include <string>

#include "comm.hpp"
#include "core/error.hpp"

namespace fest::lbmsim_tool {

Comm::Comm() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* n = std::getenv(v); n && std::atoi(n) > 1)
      throw usage_error("this lbmsim was built without MPI; it cannot run on {} ranks (rebuild with libopenmpi-dev)", n);
  exchange_ = std::make_unique<lbm::LocalExchange>();
}

void Comm::abort(int status) { std::exit(status); }

bool mpi_built() { return false; }
std::string mpi_library() { return ""; }

Comm& Comm::world() {
  static Comm comm;
  return comm;
}

}  // namespace fest::lbmsim_tool

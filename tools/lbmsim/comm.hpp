#pragma once
// The processes of a run: one, or the ranks of an MPI job (Open MPI) when lbmsim was
// built with MPI and started by mpirun. MPI starts only when `run` needs it.

#include <memory>
#include <string>

#include "lbm/exchange.hpp"

namespace fest::lbmsim_tool {

class Comm {
 public:
  // Starts MPI if this process was launched by mpirun (and the build has MPI); throws
  // Status::usage when launched on several ranks by a build without MPI.
  static Comm& world();
  int rank() const { return rank_; }
  int size() const { return size_; }
  bool root() const { return rank_ == 0; }
  // The slab exchange of this job (a LocalExchange on one process).
  lbm::SlabExchange& exchange() { return *exchange_; }
  // Ends the whole job at once with this exit status (an error seen by one rank only).
  [[noreturn]] void abort(int status);

 private:
  Comm();
  int rank_ = 0, size_ = 1;
  std::unique_ptr<lbm::SlabExchange> exchange_;
};

// Whether this build has MPI, and the library's name.
bool mpi_built();
std::string mpi_library();

}  // namespace fest::lbmsim_tool

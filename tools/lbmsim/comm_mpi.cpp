// MPI implementation of the slab exchange (docs/lbmsim.md "MPI"): Sendrecv of the
// populations that cross each cut, Allgatherv for the per-layer sums and the gathered
// output, Allreduce for the guards. Compiled only when CMake found MPI.
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include <mpi.h>

#include "comm.hpp"
#include "core/error.hpp"

namespace fest::lbmsim_tool {

namespace {

class MpiExchange final : public lbm::SlabExchange {
 public:
  MpiExchange() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  int rank() const override { return rank_; }
  int ranks() const override { return size_; }
  void exchange(const void* to_lower, const void* to_upper, void* from_lower, void* from_upper, std::size_t bytes,
                bool periodic) override {
    int lower = rank_ - 1, upper = rank_ + 1;
    if (lower < 0) lower = periodic ? size_ - 1 : MPI_PROC_NULL;
    if (upper >= size_) upper = periodic ? 0 : MPI_PROC_NULL;
    // Upward: my top layer to the upper neighbour, the lower neighbour's into my bottom ghost.
    MPI_Sendrecv(to_upper, static_cast<int>(bytes), MPI_BYTE, upper, 1, from_lower, static_cast<int>(bytes), MPI_BYTE,
                 lower, 1, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    MPI_Sendrecv(to_lower, static_cast<int>(bytes), MPI_BYTE, lower, 2, from_upper, static_cast<int>(bytes), MPI_BYTE,
                 upper, 2, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  }
  std::vector<double> allgather(const std::vector<double>& local) override {
    int n = static_cast<int>(local.size());
    std::vector<int> counts(size_), displs(size_);
    MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    long total = 0;
    for (int r = 0; r < size_; ++r) displs[r] = static_cast<int>(total), total += counts[r];
    std::vector<double> all(static_cast<std::size_t>(total));
    MPI_Allgatherv(local.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, MPI_COMM_WORLD);
    return all;
  }
  double max(double local) override {
    double v = std::isnan(local) ? std::numeric_limits<double>::infinity() : local, out = 0;
    MPI_Allreduce(&v, &out, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    return out;
  }

 private:
  int rank_ = 0, size_ = 1;
};

bool launched_by_mpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(v)) return true;
  return false;
}

void finalize_mpi() {
  int done = 0;
  MPI_Finalized(&done);
  if (!done) MPI_Finalize();
}

}  // namespace

Comm::Comm() {
  if (launched_by_mpirun()) {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    std::atexit(finalize_mpi);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  if (size_ > 1)
    exchange_ = std::make_unique<MpiExchange>();
  else
    exchange_ = std::make_unique<lbm::LocalExchange>();
}

void Comm::abort(int status) {
  if (size_ > 1) MPI_Abort(MPI_COMM_WORLD, status);
  std::exit(status);
}

bool mpi_built() { return true; }

std::string mpi_library() {
  char version[MPI_MAX_LIBRARY_VERSION_STRING];
  int len = 0;
  MPI_Get_library_version(version, &len);
  std::string s(version, static_cast<std::size_t>(len));
  const auto comma = s.find(',');
  return comma == std::string::npos ? s : s.substr(0, comma);
}

Comm& Comm::world() {
  static Comm comm;
  return comm;
}

}  // namespace fest::lbmsim_tool

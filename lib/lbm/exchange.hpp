#pragma once
// The halo exchange behind which a distributed run hides (docs/lbmsim.md "MPI"): the
// lattice is cut into slabs along its last axis, and each step the populations that
// cross a cut travel to the neighbouring slab. The kernels only see this interface, so
// they are tested without MPI; tools/lbmsim holds the MPI implementation.

#include <cstddef>
#include <vector>

namespace fest::lbm {

class SlabExchange {
 public:
  virtual ~SlabExchange() = default;
  virtual int rank() const = 0;
  virtual int ranks() const = 0;
  // Sends `to_lower` to the lower neighbour and `to_upper` to the upper one, receiving the
  // lower neighbour's `to_upper` into `from_lower` and the upper one's `to_lower` into
  // `from_upper` (all `bytes` long). With `periodic` the ends join (rank 0's lower
  // neighbour is the last rank, itself on one rank); otherwise the ends skip the side
  // that has no neighbour.
  virtual void exchange(const void* to_lower, const void* to_upper, void* from_lower, void* from_upper,
                        std::size_t bytes, bool periodic) = 0;
  // Concatenates every rank's `local` in rank order, on every rank.
  virtual std::vector<double> allgather(const std::vector<double>& local) = 0;
  // Largest value over the ranks (NaN wins).
  virtual double max(double local) = 0;
};

// One process: periodic ends copy onto themselves.
class LocalExchange final : public SlabExchange {
 public:
  int rank() const override { return 0; }
  int ranks() const override { return 1; }
  void exchange(const void* to_lower, const void* to_upper, void* from_lower, void* from_upper, std::size_t bytes,
                bool periodic) override;
  std::vector<double> allgather(const std::vector<double>& local) override { return local; }
  double max(double local) override { return local; }
};

// First layer of each rank's slab along an axis of n layers cut into `ranks` slabs
// (sizes differ by at most one; earlier ranks get the extra layers); back() == n.
std::vector<int> slab_starts(int n, int ranks);

}  // namespace fest::lbm

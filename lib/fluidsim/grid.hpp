#pragma once
// The collocated node grid of fluidsim (docs/fluidsim.md §3): n_a interior nodes per
// axis; a closed axis stores one wall node on each side (indices 0 and n+1), a periodic
// axis stores n nodes that wrap. 2-D grids have a third, inactive axis of one node.
//
// Fields are flat arrays, x fastest. Boundary values are never stored outside the grid:
// every stencil folds an index back with the mirror (closed) or wrap (periodic) rule, and
// odd fields change sign across a wall.

#include <array>
#include <cstddef>
#include <vector>

namespace fest::fluidsim {

enum class Boundary { closed, periodic };

// Grids with fewer nodes run their loops on one thread: there a parallel region (and, on
// a loaded machine, waiting for descheduled threads) costs more than the work.
constexpr std::size_t kParallelNodes = 32768;

using Field = std::vector<double>;
using Velocity = std::array<Field, 3>;

// Parity of a field across the walls of one axis.
enum class Parity { even, odd };

struct Layout {
  int dim = 3;                       // 2 or 3
  std::array<int, 3> n{1, 1, 1};     // interior nodes (the paper's grid size)
  std::array<Boundary, 3> bc{Boundary::closed, Boundary::closed, Boundary::closed};
  std::array<int, 3> size{1, 1, 1};  // stored nodes per axis
  double h = 1.0;                    // node spacing (same on every axis)

  // Builds a layout; throws Status::bad_input for sizes out of [3, 1024] or dim not 2/3.
  static Layout make(int dim, std::array<int, 3> n, std::array<Boundary, 3> bc, double h);

  bool active(int axis) const noexcept { return axis < dim; }
  bool closed(int axis) const noexcept { return active(axis) && bc[axis] == Boundary::closed; }
  std::size_t count() const noexcept {
    return static_cast<std::size_t>(size[0]) * size[1] * size[2];
  }
  std::size_t index(int i, int j, int k) const noexcept {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(size[0]) *
                                             (static_cast<std::size_t>(j) + static_cast<std::size_t>(size[1]) * k);
  }
  std::size_t stride(int axis) const noexcept {
    return axis == 0 ? 1 : axis == 1 ? static_cast<std::size_t>(size[0])
                                     : static_cast<std::size_t>(size[0]) * size[1];
  }
  // Folds index i (possibly outside the stored range) onto the grid; sets `flipped` when
  // a wall mirror was crossed an odd number of times (odd fields change sign then).
  int fold(int axis, int i, bool& flipped) const noexcept;
  // Is stored node i of `axis` a wall node (closed axis, index 0 or n+1)?
  bool is_wall(int axis, int i) const noexcept {
    return closed(axis) && (i == 0 || i == n[axis] + 1);
  }
  Field zeros() const { return Field(count(), 0.0); }
};

// Parity of velocity component c across the walls of `axis` as the projection sees it:
// the normal component is odd, tangential components even (free slip).
inline Parity velocity_parity(int component, int axis, bool no_slip = false) noexcept {
  if (component == axis) return Parity::odd;
  return no_slip ? Parity::odd : Parity::even;
}

// Neighbour tables of one axis for a stencil reach r: for every stored index i, the folded
// indices of i + r and i - r and whether the fold crossed a wall.
struct AxisNeighbours {
  std::vector<int> plus, minus;
  std::vector<unsigned char> plus_flip, minus_flip;
};
AxisNeighbours neighbours(const Layout& layout, int axis, int reach);

// The 8 nodes (4 in 2-D; the rest carry weight 0) and trilinear weights around a
// position, computed once and applied to every field advected through it.
struct Corners {
  std::array<std::size_t, 8> index{};
  std::array<double, 8> weight{};
  double apply(const Field& f) const noexcept {
    double s = 0.0;
    for (int c = 0; c < 8; ++c) s += weight[c] * f[index[c]];
    return s;
  }
};
Corners corners(const Layout& layout, const std::array<double, 3>& p) noexcept;

// Trilinear (bilinear in 2-D) sample at continuous index position p; positions are
// clamped onto [0, size-1] on closed axes and wrapped on periodic ones.
double sample(const Layout& layout, const Field& f, const std::array<double, 3>& p) noexcept;

// Clamps or wraps a position onto the domain (closed box / periodic).
std::array<double, 3> confine(const Layout& layout, std::array<double, 3> p) noexcept;

// Sets the odd components to zero on the wall nodes (their mirror value is their negative).
void enforce_walls(const Layout& layout, Velocity& u, bool no_slip = false);

}  // namespace fest::fluidsim

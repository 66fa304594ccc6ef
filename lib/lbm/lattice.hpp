#pragma once
// The two lattices of lbmsim with their fixed velocity ordering (docs/lbmsim.md 2.1):
// golden files and the opposite tables depend on it. Lattice units: dx = dt = 1,
// c_s^2 = 1/3.

namespace fest::lbm {

struct D2Q9 {
  static constexpr int D = 2;
  static constexpr int Q = 9;
  static constexpr int c[Q][3] = {{0, 0, 0},  {1, 0, 0},  {0, 1, 0},   {-1, 0, 0}, {0, -1, 0},
                                  {1, 1, 0},  {-1, 1, 0}, {-1, -1, 0}, {1, -1, 0}};
  static constexpr double w[Q] = {4.0 / 9,  1.0 / 9,  1.0 / 9,  1.0 / 9, 1.0 / 9,
                                  1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36};
  static constexpr int opp[Q] = {0, 3, 4, 1, 2, 7, 8, 5, 6};
  static constexpr const char* name = "d2q9";
};

struct D3Q19 {
  static constexpr int D = 3;
  static constexpr int Q = 19;
  static constexpr int c[Q][3] = {{0, 0, 0},  {1, 0, 0},  {-1, 0, 0},  {0, 1, 0},  {0, -1, 0},
                                  {0, 0, 1},  {0, 0, -1}, {1, 1, 0},   {-1, -1, 0}, {1, -1, 0},
                                  {-1, 1, 0}, {1, 0, 1},  {-1, 0, -1}, {1, 0, -1}, {-1, 0, 1},
                                  {0, 1, 1},  {0, -1, -1}, {0, 1, -1}, {0, -1, 1}};
  static constexpr double w[Q] = {1.0 / 3,  1.0 / 18, 1.0 / 18, 1.0 / 18, 1.0 / 18, 1.0 / 18, 1.0 / 18,
                                  1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36,
                                  1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36};
  // i+1 for odd i, i-1 for even i > 0.
  static constexpr int opp[Q] = {0, 2, 1, 4, 3, 6, 5, 8, 7, 10, 9, 12, 11, 14, 13, 16, 15, 18, 17};
  static constexpr const char* name = "d3q19";
};

enum class LatticeKind { d2q9, d3q19 };

}  // namespace fest::lbm

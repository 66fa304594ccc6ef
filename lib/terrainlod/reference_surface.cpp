#include "terrainlod/reference_surface.hpp"

#include <algorithm>
#include <cmath>

namespace fest::terrainlod {

ReferenceSurface::ReferenceSurface(const HeightGrid& grid, DiagonalRule rule) : grid_(&grid) {
  const int cw = grid.width - 1, ch = grid.height - 1;
  ne_.resize(static_cast<std::size_t>(cw) * ch);
  for (int j = 0; j < ch; ++j)
    for (int i = 0; i < cw; ++i) {
      bool ne = true;
      if (rule == DiagonalRule::alternate) {
        ne = ((i + j) % 2) == 0;
      } else if (rule == DiagonalRule::shortest) {
        // Both diagonals have the same xy length; the 3-D one is shorter when its
        // height difference is smaller. Ties go to SW-NE so the choice is deterministic.
        const double d_ne = std::abs(grid.at(i + 1, j + 1) - grid.at(i, j));
        const double d_nw = std::abs(grid.at(i, j + 1) - grid.at(i + 1, j));
        ne = d_ne <= d_nw;
      }
      ne_[static_cast<std::size_t>(j) * cw + i] = ne ? 1 : 0;
    }
}

double ReferenceSurface::height_at(double x, double y) const {
  const int i = std::clamp(static_cast<int>(std::floor(x)), 0, width() - 2);
  const int j = std::clamp(static_cast<int>(std::floor(y)), 0, height() - 2);
  const double fx = x - i, fy = y - j;
  const double h00 = sample(i, j), h10 = sample(i + 1, j), h01 = sample(i, j + 1), h11 = sample(i + 1, j + 1);
  if (ne_diagonal(i, j)) {
    if (fx >= fy) return h00 + fx * (h10 - h00) + fy * (h11 - h10);  // south-east triangle
    return h00 + fy * (h01 - h00) + fx * (h11 - h01);                // north-west triangle
  }
  if (fx + fy <= 1) return h00 + fx * (h10 - h00) + fy * (h01 - h00);  // south-west triangle
  return h11 + (1 - fx) * (h01 - h11) + (1 - fy) * (h10 - h11);       // north-east triangle
}

}  // namespace fest::terrainlod

#include "lemtrace/generate.hpp"

#include <cmath>
#include <random>

#include "core/error.hpp"
#include "lemtrace/split_cells.hpp"

namespace fest::lemtrace {

namespace {
constexpr double kSphereRadius = 0.4;
}

const std::vector<std::string>& gen_kinds() {
  static const std::vector<std::string> kinds = {"rotation", "helix",  "saddle",          "node",
                                                 "spiral",   "shear",  "uniform",         "jordan",
                                                 "sphere-rotation", "sphere-potential", "abc"};
  return kinds;
}

LinearField linear_kind(const std::string& kind, bool* is_linear) {
  LinearField f;
  *is_linear = true;
  if (kind == "rotation" || kind == "sphere-rotation") {
    f.A << 0, -1, 0, 1, 0, 0, 0, 0, 0;
  } else if (kind == "helix") {
    f.A << 0, -1, 0, 1, 0, 0, 0, 0, 0;
    f.b = Vec3(0, 0, 0.05);
  } else if (kind == "saddle") {
    f.A = Vec3(1, -1, 0.5).asDiagonal();
  } else if (kind == "node") {
    f.A = Vec3(-0.5, -1.0, -1.5).asDiagonal();
  } else if (kind == "spiral") {
    f.A << -0.1, -1, 0, 1, -0.1, 0, 0, 0, -0.2;
    f.b = Vec3(0, 0, 0.1);
  } else if (kind == "shear") {
    f.A << 0, 1, 0, 0, 0, 0, 0, 0, 0;
    f.b = Vec3(0.2, 0, 0);
  } else if (kind == "uniform") {
    f.b = Vec3(0.3, 0.2, 0.1);
  } else if (kind == "jordan") {
    // A defective block: eigenvalue -0.3 twice with one eigenvector, and 0.2.
    f.A << -0.3, 1, 0, 0, -0.3, 0, 0, 0, 0.2;
    f.b = Vec3(0.1, 0.05, 0);
  } else {
    *is_linear = false;
  }
  return f;
}

Vec3 sphere_potential_velocity(const Vec3& x) {
  // Potential flow past a sphere of radius R with U = e_z:
  // v = e_z + (R^3 / 2) (e_z / r^3 - 3 z x / r^5).
  const double r2 = x.squaredNorm(), r = std::sqrt(r2);
  const double R3 = kSphereRadius * kSphereRadius * kSphereRadius;
  if (r < 1e-12) return Vec3(0, 0, 1);
  return Vec3(0, 0, 1) + 0.5 * R3 * (Vec3(0, 0, 1) / (r2 * r) - 3.0 * x[2] * x / (r2 * r2 * r));
}

Vec3 abc_velocity(const Vec3& x) {
  const double A = std::sqrt(3.0), B = std::sqrt(2.0), C = 1.0;
  const Vec3 p = M_PI * x;
  return {A * std::sin(p[2]) + C * std::cos(p[1]), B * std::sin(p[0]) + A * std::cos(p[2]),
          C * std::sin(p[1]) + B * std::cos(p[0])};
}

GeneratedGrid generate(const GenOptions& o) {
  bool known = false;
  for (const auto& k : gen_kinds()) known = known || k == o.kind;
  if (!known) throw usage_error("unknown grid kind '{}'", o.kind);
  if (o.n < 1 || o.n > 400) throw usage_error("{} cubes per side is outside 1..400", o.n);
  if (!(o.jitter >= 0 && o.jitter < 0.5)) throw usage_error("jitter {} is outside [0, 0.5) of the cell size", o.jitter);

  GeneratedGrid g;
  g.field = linear_kind(o.kind, &g.linear);
  const int n = o.n, m = n + 1;
  const double h = 2.0 / n;
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> jit(-0.5 * o.jitter * h, 0.5 * o.jitter * h);
  g.points.reserve(static_cast<std::size_t>(m) * m * m);
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        Vec3 p(-1 + i * h, -1 + j * h, -1 + k * h);
        // Interior vertices move; boundary vertices stay on the cube's faces.
        const int idx[3] = {i, j, k};
        for (int a = 0; a < 3; ++a) {
          const double d = jit(rng);
          if (idx[a] > 0 && idx[a] < n) p[a] += d;
        }
        g.points.push_back(p);
      }
  const bool sphere = o.kind == "sphere-rotation";
  auto id = [m](int i, int j, int k) { return static_cast<int64_t>((static_cast<int64_t>(k) * m + j) * m + i); };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        if (sphere) {
          // The obstacle: cells whose centre lies inside the sphere are cut out.
          const Vec3 c(-1 + (i + 0.5) * h, -1 + (j + 0.5) * h, -1 + (k + 0.5) * h);
          if (c.norm() < kSphereRadius) continue;
        }
        g.cells.add(static_cast<uint8_t>(CellShape::hexahedron),
                    {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                     id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
      }
  if (!o.hex) {
    // Split here so that the file holds tetrahedra (the Kuhn split of split_cells.hpp).
    RawCells tets;
    std::vector<std::array<int64_t, 4>> out;
    for (std::size_t c = 0; c < g.cells.size(); ++c) {
      out.clear();
      split_cell(g.cells.types[c], g.cells.ids.data() + g.cells.offsets[c], 8, out);
      for (const auto& t : out) {
        // Positive orientation in the file, as VTK expects.
        const double vol = signed_volume(g.points[static_cast<std::size_t>(t[0])], g.points[static_cast<std::size_t>(t[1])],
                                         g.points[static_cast<std::size_t>(t[2])], g.points[static_cast<std::size_t>(t[3])]);
        if (vol >= 0) tets.add(static_cast<uint8_t>(CellShape::tetra), {t[0], t[1], t[2], t[3]});
        else tets.add(static_cast<uint8_t>(CellShape::tetra), {t[0], t[1], t[3], t[2]});
      }
    }
    g.cells = std::move(tets);
  }
  g.vectors.reserve(g.points.size());
  for (const Vec3& p : g.points) {
    if (g.linear) g.vectors.push_back(g.field.A * p + g.field.b);
    else if (o.kind == "sphere-potential") g.vectors.push_back(sphere_potential_velocity(p));
    else g.vectors.push_back(abc_velocity(p));
  }
  return g;
}

}  // namespace fest::lemtrace

#include <unsupported/Eigen/MatrixFunctions>

namespace fest::lemtrace {

Vec3 linear_flow(const LinearField& field, const Vec3& x0, double t) {
  Eigen::Matrix4d M = Eigen::Matrix4d::Zero();
  M.topLeftCorner<3, 3>() = field.A * t;
  M.topRightCorner<3, 1>() = field.b * t;
  const Eigen::Matrix4d E = M.exp();
  return E.topLeftCorner<3, 3>() * x0 + E.topRightCorner<3, 1>();
}

}  // namespace fest::lemtrace

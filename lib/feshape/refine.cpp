#include "feshape/refine.hpp"

#include <unordered_map>

#include "core/error.hpp"

namespace fest::feshape {
namespace {

constexpr double on_boundary = 1e-6;

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

// The elements on each side of every edge, kept current while elements are split.
class EdgeFaces {
 public:
  explicit EdgeFaces(const Triangulation& t) {
    for (std::size_t f = 0; f < t.elements(); ++f) link(t, static_cast<int>(f));
  }
  void link(const Triangulation& t, int f) {
    for (int i = 0; i < 3; ++i) {
      auto& slot = map_[edge_key(t.tris[f][i], t.tris[f][(i + 1) % 3])];
      (slot[0] < 0 ? slot[0] : slot[1]) = f;
    }
  }
  void unlink(const Triangulation& t, int f) {
    for (int i = 0; i < 3; ++i) {
      auto& slot = map_[edge_key(t.tris[f][i], t.tris[f][(i + 1) % 3])];
      if (slot[0] == f) slot[0] = slot[1];
      slot[1] = -1;
    }
  }
  int other(int a, int b, int f) const {
    const auto it = map_.find(edge_key(a, b));
    if (it == map_.end()) return -1;
    return it->second[0] == f ? it->second[1] : it->second[0];
  }

 private:
  struct Slot : std::array<int, 2> {
    Slot() : std::array<int, 2>{-1, -1} {}
  };
  std::unordered_map<std::uint64_t, Slot> map_;
};

struct Refiner {
  Triangulation& t;
  std::vector<Eigen::Vector3d>& x;
  std::size_t max_nodes;
  EdgeFaces edges{t};
  std::vector<NewNode> created;
  std::vector<char> split;  // per element index: split since refinement began

  Refiner(Triangulation& mesh, std::vector<Eigen::Vector3d>& positions, std::size_t limit)
      : t(mesh), x(positions), max_nodes(limit), split(mesh.elements(), 0) {}

  // Index i of the longest edge (t.tris[f][i], t.tris[f][i+1]).
  int longest_edge(int f) const {
    int best = 0;
    double best_len = -1;
    std::uint64_t best_key = 0;
    for (int i = 0; i < 3; ++i) {
      const int a = t.tris[f][i], b = t.tris[f][(i + 1) % 3];
      const double len = (x[a] - x[b]).squaredNorm();
      const std::uint64_t key = edge_key(a, b);
      if (len > best_len || (len == best_len && key < best_key)) {
        best = i;
        best_len = len;
        best_key = key;
      }
    }
    return best;
  }

  // Splits element f (and its neighbour g, when given) at the midpoint node m of the
  // edge (a, b). Children: (a, m, c) keeps f's index, (m, b, c) is appended.
  void bisect(int f, int a, int b, int m) {
    edges.unlink(t, f);
    auto tri = t.tris[f];
    while (!((tri[0] == a && tri[1] == b) || (tri[0] == b && tri[1] == a))) tri = {tri[1], tri[2], tri[0]};
    const int p = tri[0], q = tri[1], c = tri[2];
    t.tris[f] = {p, m, c};
    t.tris.push_back({m, q, c});
    const std::uint8_t level = static_cast<std::uint8_t>(std::min(255, t.level[f] + 1));
    t.level[f] = level;
    t.level.push_back(level);
    split[f] = 1;
    split.push_back(1);
    edges.link(t, f);
    edges.link(t, static_cast<int>(t.tris.size()) - 1);
  }

  // Rivara's LEPP step: splits the longest edge of f, first refining the neighbour
  // across it until that edge is the neighbour's longest too.
  void split_longest(int f) {
    for (;;) {
      const int i = longest_edge(f);
      const int a = t.tris[f][i], b = t.tris[f][(i + 1) % 3];
      const int g = edges.other(a, b, f);
      if (g >= 0) {
        const int j = longest_edge(g);
        const int ga = t.tris[g][j], gb = t.tris[g][(j + 1) % 3];
        if (edge_key(ga, gb) != edge_key(a, b)) {
          split_longest(g);  // the closure: the neighbour's longest edge goes first
          continue;          // f's neighbour across (a, b) is now a child of g
        }
      }
      if (t.nodes() >= max_nodes)
        throw make_error(Status::failure, "refinement would exceed the node limit of {}", max_nodes);
      const int m = static_cast<int>(t.nodes());
      double um, vm;
      edge_midpoint_uv(t, a, b, um, vm);
      t.u.push_back(um);
      t.v.push_back(vm);
      x.push_back(0.5 * (x[a] + x[b]));
      created.push_back({m, a, b});
      bisect(f, a, b, m);
      if (g >= 0) bisect(g, a, b, m);
      return;
    }
  }
};

}  // namespace

std::vector<std::vector<int>> faces_around_nodes(const Triangulation& t) {
  std::vector<std::vector<int>> r(t.nodes());
  for (std::size_t f = 0; f < t.elements(); ++f)
    for (int i = 0; i < 3; ++i) r[t.tris[f][i]].push_back(static_cast<int>(f));
  return r;
}

void select_elements(const Triangulation& t, const MeshPoint& p, const std::vector<std::vector<int>>& node_faces,
                     std::vector<char>& selected) {
  if (p.face < 0) return;
  int zeros = 0, nonzero = -1, zero = -1;
  for (int i = 0; i < 3; ++i) {
    if (p.lambda[i] < on_boundary) {
      ++zeros;
      zero = i;
    } else {
      nonzero = i;
    }
  }
  const auto& f = t.tris[p.face];
  if (zeros == 0) {
    selected[p.face] = 1;
  } else if (zeros == 1) {  // on the edge opposite corner `zero`
    const int a = f[(zero + 1) % 3], b = f[(zero + 2) % 3];
    for (int g : node_faces[a])
      for (int k = 0; k < 3; ++k)
        if (t.tris[g][k] == b) selected[g] = 1;
  } else {  // at the node with the non-zero coordinate
    for (int g : node_faces[f[nonzero]]) selected[g] = 1;
  }
}

std::vector<NewNode> rivara_refine(Triangulation& t, std::vector<Eigen::Vector3d>& positions,
                                   const std::vector<char>& selected, std::size_t max_nodes) {
  Refiner r(t, positions, max_nodes);
  const std::size_t original = t.elements();
  for (std::size_t f = 0; f < original; ++f) {
    if (!selected[f] || r.split[f]) continue;  // no longer a leaf: already bisected by a closure
    r.split_longest(static_cast<int>(f));
  }
  return r.created;
}

}  // namespace fest::feshape

#pragma once
// Local subdivision (seed App. C §4.3-4.4, docs/feshape.md §2.1-2.2): which elements a
// far data point selects, and Rivara's longest-edge bisection with conforming closure
// (the LEPP form: before an edge is split, the neighbour across it is refined until that
// edge is also its longest, so no hanging node is ever made).

#include <array>
#include <vector>

#include <Eigen/Core>

#include "feshape/closest.hpp"
#include "feshape/triangulation.hpp"

namespace fest::feshape {

// Elements selected by a data point whose closest model point is `p` (§2.1): the
// element when p is inside it, both elements of the edge when on an edge (one barycentric
// coordinate < 1e-6), every element around the node when at a node (two < 1e-6).
// `node_faces` lists the elements around each node.
void select_elements(const Triangulation& t, const MeshPoint& p, const std::vector<std::vector<int>>& node_faces,
                     std::vector<char>& selected);
std::vector<std::vector<int>> faces_around_nodes(const Triangulation& t);

// A node created by bisecting edge (a, b).
struct NewNode {
  int node, a, b;
};

// Bisects every selected element once by its longest edge (lengths measured on
// `positions`, the current 3-D nodal positions; ties go to the edge whose sorted pair of
// node ids is smaller), keeping the mesh conforming. An element already split by the
// closure of another is not split again. New nodes get the seam-aware parameter
// midpoint and position midpoint (appended to `positions`); children get level + 1.
// Returns the new nodes in creation order. Fails (Status::failure) when the node count
// would exceed max_nodes.
std::vector<NewNode> rivara_refine(Triangulation& t, std::vector<Eigen::Vector3d>& positions,
                                   const std::vector<char>& selected, std::size_t max_nodes);

}  // namespace fest::feshape

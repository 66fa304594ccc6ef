#pragma once
// ffd's own byte formats, as codecs bytes <-> Lattice (docs/ffd.md section 4):
//  * lattice JSON: {"origin": [x,y,z], "axes": [S,T,U], "dims": [L,M,N],
//    "basis": "bernstein" | [b_s, b_t, b_u], "displacements": [[i,j,k,dx,dy,dz], ...]
//    (sparse, missing = 0) or "points": [[x,y,z], ...] (all deformed positions, i fastest)};
//  * PyGeM .prm (INI): [Box info] with "n control points x|y|z", "box length x|y|z",
//    "box origin x|y|z", "rotation angle x|y|z" (degrees), and [Parameters weights] with
//    "parameter x|y|z:" lines "i j k mu" (mu: displacement in box lengths along the box's
//    own axis). PyGeM's box rotation is angles2matrix(z, y, x) = Rx(x) Ry(y) Rz(z) and
//    its displacement is S mu_x + T mu_y + U mu_z (S, T, U the rotated, scaled box axes).
// Decoders throw fest::Error(bad_input) naming the line or key; they never crash.

#include <string>
#include <string_view>

#include "ffd/lattice.hpp"

namespace fest::ffd {

Lattice decode_lattice_json(std::string_view text);
std::string encode_lattice_json(const Lattice& lattice);  // sparse displacements

Lattice decode_pygem_prm(std::string_view text);
// Only lattices PyGeM can express (Bernstein, orthogonal axes); else bad_input.
std::string encode_pygem_prm(const Lattice& lattice);

}  // namespace fest::ffd

#include <vector>

#include "ffd/joints.hpp"

namespace fest::ffd {

// Joints table (docs/ffd.md 2.3): whitespace-separated rows "name x y z tx ty tz" (rest
// position, target); '#' starts a comment; a first row starting with "name" is a header.
std::vector<Joint> decode_joints(std::string_view text);

}  // namespace fest::ffd

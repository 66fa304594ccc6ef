#pragma once
// Quantised positions with parallelogram prediction (docs/ebcode.md §5; project engineering, after
// Touma & Gotsman and Draco): per axis residual r = q - prediction, wrapped into the
// quantisation range, zigzagged, its bit length coded with adaptive binary contexts and
// the bits below the leading one as two adaptive and the rest bypass bits.
// Two binarisations of the bit length (ebm(5), GEOM): .ebm 1.x's
// 6-level tree (six decisions per coordinate), and .ebm 2.0's, which codes the length as
// a signed unary distance from the previous length on the axis (about three decisions)
// with contexts that adapt fast while they are new. .ebm 2.1's GEOM (version 3) codes
// the same residuals as static rANS tokens instead (residual_tokens.hpp): no decision at
// all, so nothing for the decoder to branch on.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fest::edgebreaker {

enum class Predictor : std::uint8_t { parallelogram = 0, multi = 1, delta = 2, none = 3 };

using QPoint = std::array<std::int64_t, 3>;

// Which residual coding a stream uses (GEOM versions, ebm(5)): .ebm 1.x's tree, 2.0's
// distance (ISOL and the attributes of every 2.x), and 2.1's GEOM residual tokens
// (residual_tokens.hpp; positions only, qp 1..30).
enum class ResidualCoding : std::uint8_t { tree_v1 = 1, distance_v2 = 2, tokens_v3 = 3 };

// What the geometry coder needs of the connectivity, per G vertex.
struct GeometryPlan {
  std::vector<std::array<int, 3>> parallelogram;  // (a, b, o) or -1s (DecodedConnectivity)
  std::vector<char> unusable;  // dummies: no position, never a predictor
  std::vector<int> same_as;    // an earlier G vertex at the same input vertex (stitch), or -1
  // For Predictor::multi only: the closed mesh's triangles (G ids) and opposite corners.
  const std::vector<std::array<int, 3>>* triangles = nullptr;
  const std::vector<int>* opposite = nullptr;
};

// `bits` 1..30 quantised (values 0 .. 2^bits - 1), 0 lossless (monotone int32 of float
// bits). Entries of q for unusable vertices are ignored; a vertex with same_as >= 0 costs
// nothing (the decoder copies the earlier value).
std::string encode_positions(const std::vector<QPoint>& q, const GeometryPlan& plan, int bits, Predictor predictor,
                             ResidualCoding coding = ResidualCoding::distance_v2);

// GEOM version 3 (residual_tokens.hpp): the same residuals as tokens with stored tables.
// Nothing when `bits` is 0 or a table cannot be described; the caller keeps version 2.
std::optional<std::string> encode_position_tokens(const std::vector<QPoint>& q, const GeometryPlan& plan, int bits,
                                                  Predictor predictor);

// Inverse (any coding): returns q per G vertex (zeros for unusable ones). Throws bad_input for a
// truncated stream.
std::vector<QPoint> decode_positions(std::string_view bytes, const GeometryPlan& plan, int bits, Predictor predictor,
                                     ResidualCoding coding = ResidualCoding::distance_v2);

// Isolated vertices: delta-coded in order, after the others.
std::string encode_point_list(const std::vector<QPoint>& q, int bits, ResidualCoding coding = ResidualCoding::distance_v2);
std::vector<QPoint> decode_point_list(std::string_view bytes, std::size_t count, int bits,
                                      ResidualCoding coding = ResidualCoding::distance_v2);

}  // namespace fest::edgebreaker

#pragma once
// The .ebm bitstream (docs/ebcode.md §5, documented in man/man5/ebm.5): a whole mesh -- general
// connectivity, quantised positions, the side information that restores non-manifold
// input exactly -- in one CRC-protected container. The format is this algorithm's own
// output, so it lives here with it (a domain's own byte format belongs to its library), in memory only: bytes in, bytes out.

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/triangle_soup.hpp"
#include "edgebreaker/clers.hpp"
#include "edgebreaker/conn_coder.hpp"
#include "edgebreaker/geometry_coder.hpp"

namespace fest::edgebreaker {

// A triangle soup with positions: what goes in and comes out. Vertex ids index positions.
// Per-vertex attributes (docs/ebcode.md §5): normals are quantised over [-1, 1] (clamped), colours
// kept exactly, texture coordinates quantised over their own box.
using MeshSoup = TriangleSoup;
static_assert(std::is_same_v<decltype(MeshSoup::triangles)::value_type, Triangle>);

enum class ConnChoice { automatic, static_model, adaptive, raw };

struct EncodeOptions {
  ConnChoice conn = ConnChoice::automatic;
  int model_id = 4;  // m236 (state_machine.hpp named_models)
  int qp = 14;       // 0 lossless (float32 exact), 1..30 bits
  int qn = 10;       // normal bits per component, 1..30
  int qt = 12;       // texture coordinate bits, 1..30
  Predictor predictor = Predictor::parallelogram;
  bool stitch = true;           // store stitch pairs so the decoder merges copies back
  bool drop_isolated = false;
  bool geometry = true;
  bool strict = false;
  std::optional<std::array<float, 4>> box;  // min x, y, z and extent
  bool verify = true;
  int version = 2;  // .ebm major version written: 2 (compact container), or 1 for old readers
  // GEOM version in a version 2 container (ebm(5)): 0 writes 3 (residual tokens, .ebm
  // 2.1; quantised positions only), except on meshes below 4096 coded vertices where it is
  // larger than 2 (.ebm 2.0, as fest 0.2 wrote it); 2 or 3 forces one.
  int geom_version = 0;
};

struct EbmHeader {
  int major = 1, minor = 0;
  std::uint16_t flags = 0;
  std::uint64_t vertices = 0, faces = 0, components = 0, dummies = 0, stitch = 0, events = 0, isolated = 0,
                symbols = 0;
  int conn_mode = 0, model_id = 0, qp = 0, predictor = 0;
  std::uint64_t attributes = 0;
  std::vector<std::string> attribute_names;  // "normal", "color", "texcoord"
  std::array<float, 4> box{};  // min x, y, z, extent
  std::map<std::string, std::size_t> section_bytes;  // payload bytes per tag
  std::size_t total_bytes = 0;
};

namespace ebm_flags {
constexpr std::uint16_t geometry = 1u << 0, lossless = 1u << 1, stitch = 1u << 2, holes = 1u << 3,
                        events = 1u << 4, isolated = 1u << 5, preserve_order = 1u << 6, exclusion = 1u << 7;
}

struct EncodeStats {
  std::size_t input_vertices = 0, input_faces = 0, components = 0, holes = 0, stitch = 0, events = 0, isolated = 0,
              dropped_degenerate = 0, symbols = 0;
  std::array<std::size_t, 5> histogram{};  // C, L, E, R, S
  int genus_sum = 0;                       // sum over closed components (after hole filling)
  std::string conn_mode;
  int geom_version = 0;  // the GEOM coding written (ebm(5)): 1, 2 or 3; 0 without positions
  std::map<std::string, std::size_t> section_bytes;
  std::size_t total_bytes = 0;
  double max_error = 0, rms_error = 0;  // per coordinate, after quantisation
  double error_bound = 0;  // half a quantisation step: extent / (2 (2^qp - 1)); 0 for qp 0
};

// Throws bad_input for bad mesh data (index out of range, non-finite coordinates, --strict
// violations), usage_error for options out of range, runtime_failure if the
// self-verification fails.
std::string encode_ebm(const MeshSoup& mesh, const EncodeOptions& options, EncodeStats* stats = nullptr);

// Checks magic, version, lengths and CRC; parses the header. Version 2 leaves the output
// vertex and face counts out of the file: for it they are found by decoding (without the
// re-encoding check). Throws bad_input.
EbmHeader read_ebm_header(std::string_view bytes);

// Decodes completely (everything is checked before anything is returned). With stitch
// false, non-manifold copies stay separate vertices. Throws bad_input.
MeshSoup decode_ebm(std::string_view bytes, bool stitch = true, bool verify = true, EbmHeader* header = nullptr);

// The CLERS string of a mesh (forward order, all components) as ebcode --symbols shows it.
Clers mesh_symbols(const MeshSoup& mesh, bool strict = false);

bool is_ebm(std::string_view bytes);

// Rewrites the CRC at the end of a stream (at least 8 bytes) to match its content, so
// tests and fuzzers can reach the decoder behind the CRC with damaged or lying sections.
void reseal_ebm(std::string& bytes);

}  // namespace fest::edgebreaker

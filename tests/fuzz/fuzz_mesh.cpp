// libFuzzer target for formats/mesh: every input goes to all five readers (so seeds of
// any format exercise all of them); whatever reads successfully is written back in the
// same format (ascii and binary where both exist) and read again, which also exercises
// the writers on odd meshes. Only fest::Error may escape a reader.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"
#include "formats/mesh/mesh_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using fest::formats::Format;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  for (Format format : {Format::ply, Format::obj, Format::off, Format::stl, Format::drc}) {
    fest::Mesh mesh;
    try {
      mesh = fest::formats::read_mesh(bytes, format);
    } catch (const fest::Error&) {
      continue;
    }
    if (mesh.n_vertices() > 10000) continue;  // keep each run fast
    // Write the faces the halfedge mesh refused too, in their place (as fconv does).
    fest::formats::carry_skipped_faces(mesh);
    for (bool ascii : {false, true}) {
      fest::formats::MeshWriteOptions options;
      options.ascii = ascii;
      try {
        const std::string written = fest::formats::write_mesh(mesh, format, options);
        fest::formats::read_mesh(written, format);
      } catch (const fest::Error&) {
        // Writers may refuse (e.g. Draco on degenerate data); the re-read may refuse
        // what a lenient first read accepted (e.g. an empty OBJ).
      }
    }
  }
  return 0;
}

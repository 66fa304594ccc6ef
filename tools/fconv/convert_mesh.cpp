// fconv on meshes: the losses checked before anything is written.

#include <string>
#include <vector>

#include <fmt/format.h>

#include "convert.hpp"
#include "core/error.hpp"
#include "core/tool_main.hpp"
#include "mesh_input.hpp"

namespace fest::fconv_tool {

using namespace fest::formats;

namespace {

std::string list_parts(const std::vector<MeshPart>& parts) {
  std::string what;
  for (const MeshPart& part : parts) what += (what.empty() ? "" : ", ") + part.describe();
  return what;
}

// What fest does not keep from the input, and what the output format cannot hold:
// refused (exit 3) unless --drop-unrepresentable, then counted in a warning.
void check_losses(const Mesh& mesh, Format to, const ConvertOptions& opt, const std::string& name) {
  const std::vector<MeshPart> unread = unread_parts(mesh), unwritable = unwritable_parts(mesh, to);
  if (!unread.empty()) {
    if (!opt.drop_unrepresentable)
      throw bad_input("fest does not keep the input's {}; --drop-unrepresentable converts without them ({})",
                      list_parts(unread), name);
    warn("fconv", fmt::format("dropped {}, which fest does not keep ({})", list_parts(unread), name));
  }
  if (!unwritable.empty()) {
    if (!opt.drop_unrepresentable)
      throw bad_input("{} cannot hold the input's {}; --drop-unrepresentable converts without them ({})",
                      format_name(to), list_parts(unwritable), name);
    warn("fconv", fmt::format("dropped {}, which {} cannot hold ({})", list_parts(unwritable), format_name(to), name));
  }
}

}  // namespace

std::string convert_mesh(const Input& in, Format to, const ConvertOptions& opt) {
  MeshWriteOptions w;
  w.ascii = opt.ascii;
  w.draco_position_bits = opt.draco_bits;
  w.draco_speed = opt.draco_speed;
  w.draco_normal_bits = opt.draco_normal_bits;
  w.draco_texcoord_bits = opt.draco_texcoord_bits;
  w.drop_unrepresentable = opt.drop_unrepresentable;
  w.precision = opt.precision;
  const Mesh mesh = read_whole_mesh(in);
  check_losses(mesh, to, opt, in.name);
  return write_mesh(mesh, to, w);
}

}  // namespace fest::fconv_tool

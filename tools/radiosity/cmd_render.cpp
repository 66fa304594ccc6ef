// radiosity render: a lit mesh's vertex colours drawn to PNG (Gouraud).

#include <cstdint>
#include <vector>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"
#include "core/threads.hpp"
#include "formats/detect.hpp"
#include "formats/input.hpp"
#include "formats/image/image_io.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "view.hpp"

namespace fest::radiosity_tool {

int run_render(const RenderArgs& args) {
  const std::string where = input_name(args.input);
  const formats::Input in = formats::load_input(args.input);
  if (formats::kind_of(in.format) != formats::Kind::mesh) throw bad_input("not a mesh ({})", where);
  // read_mesh(Input): a glTF's external buffers are found beside the input.
  const Mesh mesh = formats::parse(in, formats::read_mesh);
  if (!mesh.has_vertex_colors()) throw bad_input("the mesh has no vertex colours to show ({})", where);
  ViewMesh vm;
  for (auto vh : mesh.vertices()) {
    const auto& p = mesh.point(vh);
    const auto& c = mesh.color(vh);
    vm.positions.emplace_back(p[0], p[1], p[2]);
    vm.values.emplace_back(c[0] / 255.0, c[1] / 255.0, c[2] / 255.0);
  }
  for (auto fh : mesh.faces()) {
    std::vector<std::uint32_t> f;
    for (auto vh : mesh.fv_range(fh)) f.push_back(static_cast<std::uint32_t>(vh.idx()));
    for (std::size_t j = 1; j + 1 < f.size(); ++j) vm.triangles.push_back({f[0], f[j], f[j + 1]});
  }
  const Image img = to_display(render_values(vm, args.camera, resolve_threads(args.threads)), 1.0, 1.0);
  write_output(args.output, formats::write_image(img, formats::Format::png));
  return 0;
}

}  // namespace fest::radiosity_tool

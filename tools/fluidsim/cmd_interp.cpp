// fluidsim interp: the blend (1 - a) A + a B of two frames (docs/fluidsim.md, section 5).
#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"
#include "fluidsim/frame.hpp"

namespace fest::fluidsim_tool {

using namespace fest::fluidsim;

int interp_command(const InterpOptions& o) {
  auto one = [](const std::string& path) {
    const std::string where = input_name(path);
    const std::string bytes = read_input(path);
    if (bytes.empty()) throw bad_input("empty input ({})", where);
    Frame f;
    decode_frame(bytes, 0, f, where, 0);
    return f;
  };
  const Frame a = one(o.a), b = one(o.b);
  Frame out = blend_frames(a, b, o.alpha);
  out.float64 = a.float64 || b.float64;
  write_output(o.output, encode_frame(out));
  return 0;
}

}  // namespace fest::fluidsim_tool

// markerpose draw: a printable marker (PNG).
#include "commands.hpp"
#include "core/file_io.hpp"
#include "formats/detect.hpp"
#include "formats/image/image_io.hpp"
#include "marker_art.hpp"
#include "markers/dictionary.hpp"
#include "markers/synth.hpp"

namespace fest::markerpose_tool {

int draw_command(const DrawOptions& o) {
  art_from_flags(o.dict, o.id);  // checks both flags
  const cv::Mat img = markers::draw_marker(markers::dictionary(o.dict), o.id, o.cell_px, o.quiet_cells);
  const formats::Format f =
      is_stdio(o.output) ? formats::output_format_from_name("png").format : formats::output_format_from_path(o.output).format;
  write_output(o.output, formats::write_image({img, ColorSpace::srgb}, f));
  return 0;
}

}  // namespace fest::markerpose_tool

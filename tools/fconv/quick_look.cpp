// fconv VOLUME --to png: a quick look at a volume (docs/fconv.md "Volume quick look").
// The picture is drawn by lib/core/volume_view; this file reads, says what it drew (-v)
// and writes.

#include <string>

#include <fmt/format.h>

#include "convert.hpp"
#include "core/error.hpp"
#include "core/image.hpp"
#include "core/tool_main.hpp"
#include "core/volume_view.hpp"
#include "formats/image/image_io.hpp"
#include "formats/volume/orientation_stated.hpp"
#include "formats/volume/volume_io.hpp"
#include "formats/volume_source/volume_source.hpp"

namespace fest::fconv_tool {

using namespace fest::formats;

namespace {

// The 3-D grid to draw: one frame of a 4-D series (--frame, else the first, with a
// warning naming the count), the chosen frame of a frame stream (else its last, as
// isosurf and volrender take it), the active point array of VTK image data.
Volume volume_to_draw(const Input& in, const ConvertOptions& o) {
  if (kind_of(in.format) == Kind::volume && !is_frame_stream(in.bytes)) {
    Volume v = parse(in, read_volume);
    if (v.frames > 1) {
      if (!o.frame)
        warn("fconv", fmt::format("{} is a series of {} frames: drawing frame 0 (--frame K draws another)", in.name, v.frames));
      return v.frame(o.frame ? *o.frame : 0);
    }
    if (o.frame && *o.frame > 0) return v.frame(*o.frame);  // throws, naming the one frame
    return v;
  }
  VolumeSourceOptions s;
  if (o.frame) s.frame = static_cast<long>(*o.frame);
  return read_volume_source(in, s);
}

}  // namespace

void volume_quick_look(const Input& in, const OutputFormat& out, const ConvertOptions& o) {
  if (o.window && !((*o.window)[0] < (*o.window)[1]))
    throw usage_error("--window LO,HI needs LO < HI, not {},{}", (*o.window)[0], (*o.window)[1]);
  const Volume v = volume_to_draw(in, o);
  VolumeViewOptions view;
  view.kind = o.view.value_or(VolumeViewKind::ortho);
  view.slice = o.slice;
  view.window = o.window;
  view.convention = o.convention;
  view.orientation_known = volume_orientation_stated(in);
  if (o.slice && view.kind != VolumeViewKind::ortho)
    throw usage_error("--slice picks the slices of --view ortho, not of --view {}", volume_view_kind_name(view.kind));
  const VolumeView picture = render_volume_view(v, view);
  if (o.verbose) {
    fmt::print(stderr, "fconv: {} view of {} ({}x{}x{}): {} panels, {} mm per pixel, window {} to {}, scale bar {} mm = {} px, {}\n",
               volume_view_kind_name(view.kind), in.name, v.dims[0], v.dims[1], v.dims[2], picture.panels.size(),
               picture.pixel_mm, picture.window[0], picture.window[1], picture.scale_bar_mm, picture.scale_bar_px,
               view.orientation_known ? display_convention_name(view.convention) : "orientation unknown");
    for (const ViewPanel& p : picture.panels)
      fmt::print(stderr, "fconv: panel '{}' at {},{} size {}x{} left '{}' right '{}' top '{}' bottom '{}'\n", p.title, p.x, p.y,
                 p.width, p.height, p.left, p.right, p.top, p.bottom);
  }
  store_output(o.output, write_image(fest::Image{picture.rgb, ColorSpace::srgb}, out.format), out.gzip);
}

}  // namespace fest::fconv_tool

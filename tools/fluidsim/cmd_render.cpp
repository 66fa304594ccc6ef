// fluidsim render: field file or frame stream -> PNG/PFM.
#include <algorithm>
#include <cmath>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"
#include "core/progress.hpp"
#include "fluidsim/frame.hpp"
#include "image_data_frame.hpp"
#include "output_names.hpp"
#include "plane_image.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/volume/volume_io.hpp"

namespace fest::fluidsim_tool {

using namespace fest::fluidsim;

namespace {

// Every frame of the input: a frame stream (NRRD files with "# fest-frame:" headers) or
// one scalar volume (NRRD, NIfTI, MHA) read by formats/.
std::vector<Frame> load_frames(const std::string& path) {
  const std::string where = input_name(path);
  std::string bytes = read_input(path);
  if (bytes.empty()) throw bad_input("empty input ({})", where);
  std::vector<Frame> frames;
  const auto header_end = bytes.find("\n\n");
  const bool stream = bytes.rfind("NRRD", 0) == 0 && bytes.find("# fest-frame:") < header_end;
  if (stream) {
    std::size_t pos = 0;
    long n = 0;
    while (pos < bytes.size()) {
      Frame f;
      pos = decode_frame(bytes, pos, f, where, n++);
      frames.push_back(std::move(f));
    }
    return frames;
  }
  formats::Input in = formats::recognise(std::move(bytes), where);
  const formats::Kind kind = formats::kind_of(in.format);
  Frame f;
  if (kind == formats::Kind::volume) {
    const Volume v = formats::parse(in, formats::read_volume);
    v.require_3d("fluidsim render");
    f.dim = v.dims[2] == 1 ? 2 : 3;
    f.size = {static_cast<int>(v.dims[0]), static_cast<int>(v.dims[1]), static_cast<int>(v.dims[2])};
    f.spacing = v.spacing[0];
    f.fields = {{"value", 1}};
    f.data = v.voxels;
  } else if (in.format == formats::Format::vti) {
    // VTK image data as fluidsim writes it: every point array becomes a field.
    const Dataset img = formats::parse(in, formats::read_dataset);
    if (img.kind != DatasetKind::image) throw bad_input("VTI input holds no image data ({})", where);
    read_image_data_frame(img, f, UnnamedArrays::name_by_index);
    if (f.fields.empty()) throw bad_input("VTI input has no point arrays ({})", where);
  } else if (in.format == formats::Format::pfm || in.format == formats::Format::exr) {
    // A 2-D field image (row 0 at the top, as fluidsim writes it): channel 0.
    const Image im = formats::parse(in, formats::read_image);
    cv::Mat m;
    im.pixels.convertTo(m, CV_64F);
    f.dim = 2;
    f.size = {m.cols, m.rows, 1};
    f.fields = {{"value", 1}};
    f.data.resize(f.nodes());
    const int ch = m.channels();
    for (int y = 0; y < m.rows; ++y)
      for (int x = 0; x < m.cols; ++x) f.data[x + static_cast<std::size_t>(m.cols) * (m.rows - 1 - y)] = m.ptr<double>(y)[x * ch];
  } else {
    throw bad_input("render reads a frame stream, a volume (NRRD, NIfTI, MHA), VTI, PFM or EXR, not {} ({})",
                    formats::format_name(in.format), where);
  }
  frames.push_back(std::move(f));
  return frames;
}

}  // namespace

int render_command(const RenderOptions& o) {
  fluidsim::RenderOptions ro;
  ro.mode = o.mode;
  ro.axis = o.axis;
  if (!o.range.empty() && !(o.range[1] > o.range[0])) throw usage_error("--range lo,hi needs lo < hi");
  ro.index = o.index;

  const std::vector<Frame> frames = load_frames(o.input);
  const bool many = frames.size() > 1;
  if (many && o.output != "-" && !has_index_conversion(o.output))
    throw usage_error("-o \"{}\" needs a %d for {} frames", o.output, frames.size());
  std::string field = o.field;
  if (frames.front().channel_of(field) < 0) {
    if (frames.front().fields.size() == 1 && o.field == "density")
      field = frames.front().fields.front().name;  // a plain volume: its only field
    else
      throw usage_error("--field \"{}\" is not in the input", o.field);
  }
  if (ro.mode == RenderMode::slice && o.index >= 0) {
    const Frame& f = frames.front();
    const int depth = f.dim == 2 ? 1 : f.size[ro.axis];
    if (o.index >= depth) throw usage_error("--index {} is out of range [0, {}]", o.index, depth - 1);
  }
  // Render everything before writing anything: no partial output on bad input.
  std::vector<std::string> images;
  double lo = 0.0, hi = 1.0;
  bool range_set = !o.range.empty();
  if (range_set) {
    lo = o.range[0];
    hi = o.range[1];
  }
  Progress bar("fluidsim render", frames.size(), progress_wanted(o.progress));
  for (const Frame& f : frames) {
    const Frame& ref = frames.front();
    if (f.size != ref.size || f.dim != ref.dim || f.channel_of(field) < 0)
      throw bad_input("frame {} differs in shape or fields from frame 0", f.index);
    ro.spacing = f.spacing;
    ro.sigma = o.sigma > 0 ? o.sigma : 4.0 / (f.spacing * std::max({f.size[0], f.size[1], f.size[2]}));
    const Plane p = render_plane(f.magnitude(field), f.size, f.dim, ro);
    if (o.to == ImageFormat::pfm) {
      images.push_back(formats::write_image(Image{plane_to_float(p), ColorSpace::linear}, formats::Format::pfm));
      bar.advance();
      continue;
    }
    if (!range_set) {
      // One range for the whole sequence (from the first frame), so frames do not flicker.
      if (ro.mode != RenderMode::absorb) {
        lo = *std::min_element(p.values.begin(), p.values.end());
        hi = *std::max_element(p.values.begin(), p.values.end());
        if (!(hi > lo)) hi = lo + 1.0;
      }
      range_set = true;
    }
    images.push_back(formats::write_image(Image{plane_to_rgb(p, lo, hi, o.colormap, o.depth), ColorSpace::srgb},
                                          formats::Format::png));
    bar.advance();
  }
  bar.finish();
  if (o.output == "-") {
    std::string all;
    for (const auto& im : images) all += im;
    write_output("-", all);
  } else {
    for (std::size_t i = 0; i < images.size(); ++i)
      write_output(expand_pattern(o.output, many ? frames[i].index : frames[i].index), images[i]);
  }
  return 0;
}

}  // namespace fest::fluidsim_tool

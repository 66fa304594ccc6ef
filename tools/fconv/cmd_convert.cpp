// fconv's conversion: choose the output format, check that it is of the input's kind,
// convert completely, then write.

#include <string>

#include "commands.hpp"
#include "convert.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/progress.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/table/table_io.hpp"

namespace fest::fconv_tool {

using namespace fest::formats;

namespace {

const char* article(Kind k) { return k == Kind::image ? "an" : "a"; }

// Every kind but volumes (which convert_volume writes itself): the output file's bytes.
std::string convert(const Input& in, Format to, const ConvertOptions& opt) {
  switch (kind_of(in.format)) {
    case Kind::mesh: return convert_mesh(in, to, opt);
    case Kind::image: {
      ImageWriteOptions w;
      w.ascii = opt.ascii;
      w.exr_half = opt.half;
      w.jpeg_quality = opt.quality;
      w.flatten = opt.flatten;
      w.background = opt.background;
      return write_image_with_bar(parse(in, read_image), to, w, progress_wanted(opt.progress));
    }
    case Kind::volume: throw usage_error("internal: volumes are converted by convert_volume");
    case Kind::dataset: {
      DatasetWriteOptions w;
      w.ascii = opt.ascii;
      return write_dataset(parse(in, read_dataset), to, w);
    }
    case Kind::table: return write_table(parse(in, read_table), to);
    case Kind::json: return write_json(parse(in, read_json_document));
  }
  throw usage_error("unsupported conversion");
}

}  // namespace

int convert_command(const ConvertOptions& opt) {
  const Input in = load_input(opt.input);
  // The output format: --to, else the output file's extension, else (standard output
  // with no --to) the input's own format, so `fconv < a > b` normalises a file.
  OutputFormat out{in.format, false};
  if (opt.to)
    out = *opt.to;
  else if (!is_stdio(opt.output))
    out = output_format_from_path(opt.output);
  // Tables and JSON have no signature: they are what text is taken for when it matches no
  // other format, so a file asked to become a mesh (or image, ...) that reads only as a
  // table is a damaged or unknown file of the wanted kind -- bad input, not a bad request.
  const Kind in_kind = kind_of(in.format);
  // A volume (or VTK image data, a frame stream) asked for as an image: a quick look.
  const bool volume_like = in_kind == Kind::volume || in.format == Format::vti;
  if (kind_of(out.format) == Kind::image && volume_like) {
    volume_quick_look(in, out, opt);
    return 0;
  }
  if (opt.view || opt.slice || opt.window)
    throw usage_error("--view, --slice and --window draw a volume as a picture (--to png); the input is {} {} ({}){}",
                      article(in_kind), kind_name(in_kind), format_name(in.format),
                      volume_like ? fmt::format(" and the output {}", format_name(out.format)) : "");
  if (kind_of(out.format) != in_kind && (in_kind == Kind::table || in_kind == Kind::json) &&
      kind_of(out.format) != Kind::table && kind_of(out.format) != Kind::json)
    throw bad_input("{}", with_location(fmt::format("not {} {} file fest reads: no {} format's signature, and the text "
                                                    "reads only as {} ({})",
                                                    article(kind_of(out.format)), kind_name(kind_of(out.format)),
                                                    kind_name(kind_of(out.format)),
                                                    in_kind == Kind::table ? "a table" : "JSON", format_name(in.format)),
                                        in.name));
  if (kind_of(out.format) != kind_of(in.format))
    throw usage_error("cannot convert {} {} ({}) to {}, which is {} {} format", article(kind_of(in.format)),
                      kind_name(kind_of(in.format)), format_name(in.format), format_name(out.format),
                      article(kind_of(out.format)), kind_name(kind_of(out.format)));
  if (opt.frame && kind_of(in.format) != Kind::volume)
    throw usage_error("--frame picks a frame of a 4-D volume; the input is {} {}", article(kind_of(in.format)),
                      kind_name(kind_of(in.format)));
  // Convert completely before writing anything: bad input leaves no partial output.
  if (kind_of(in.format) == Kind::volume) {
    convert_volume(in, out, opt);
    return 0;
  }
  const std::string bytes = convert(in, out.format, opt);
  store_output(opt.output, bytes, out.gzip);
  return 0;
}

}  // namespace fest::fconv_tool

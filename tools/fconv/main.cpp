// fconv: convert a mesh, image, volume, VTK dataset, table or JSON file to another
// format of the same kind, or describe it as JSON (--info).
//
// Wiring only: formats/ recognises, reads and writes; this file maps flags onto it.

#include <limits>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/cli.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/tool_main.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "formats/table/table_io.hpp"
#include "formats/volume/volume_io.hpp"

namespace {

using namespace fest;
using namespace fest::formats;

struct Options {
  std::string input = "-";
  std::string output = "-";
  std::string to;
  bool info = false;
  bool ascii = false;
  bool compress = false;
  bool half = false;
  int quality = 95;  // JPEG output
  std::string volume_type;
  bool rescale = false;
  long frame = -1;  // --frame K: one frame of a 4-D series; -1: all
  int draco_bits = 0;
  int draco_speed = 5;
  std::string precision;  // "", "float" or "double"
  bool drop_unrepresentable = false;
};

// A mesh as read, with the faces OpenMesh's halfedge structure refused set to be written
// in their place; what the reader read leniently is said as a warning.
Mesh read_whole_mesh(const Input& in) {
  Mesh mesh = parse(in, read_mesh);
  for (const std::string& w : read_warnings(mesh)) warn("fconv", w + " (" + in.name + ")");
  carry_skipped_faces(mesh);
  return mesh;
}

std::string list_parts(const std::vector<MeshPart>& parts) {
  std::string what;
  for (const MeshPart& part : parts) what += (what.empty() ? "" : ", ") + part.describe();
  return what;
}

// What fest does not keep from the input, and what the output format cannot hold:
// refused (exit 3) unless --drop-unrepresentable, then counted in a warning.
void check_losses(const Mesh& mesh, Format to, const Options& opt, const std::string& name) {
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

const char* article(Kind k) { return k == Kind::image ? "an" : "a"; }

// The range of values a type holds, as the clipping warning states it.
std::string type_range(ScalarType t) {
  switch (t) {
    case ScalarType::u8: return "0..255";
    case ScalarType::i8: return "-128..127";
    case ScalarType::u16: return "0..65535";
    case ScalarType::i16: return "-32768..32767";
    case ScalarType::u32: return "0..4294967295";
    case ScalarType::i32: return "-2147483648..2147483647";
    case ScalarType::u64: return "0..18446744073709551615";
    case ScalarType::i64: return "-9223372036854775808..9223372036854775807";
    case ScalarType::f32: return fmt::format("-{}..{}", std::numeric_limits<float>::max(), std::numeric_limits<float>::max());
    case ScalarType::f64: break;
  }
  return "of float64";
}

// What is known about the input before its content is parsed.
nlohmann::json file_facts(const Input& in) {
  return {{"file", in.name},
          {"kind", kind_name(kind_of(in.format))},
          {"format", format_name(in.format)},
          {"gzip", in.was_gzip},
          {"bytes", in.bytes.size()}};
}

nlohmann::json describe(const Input& in) {
  nlohmann::json facts = file_facts(in);
  nlohmann::json content;
  switch (kind_of(in.format)) {
    case Kind::mesh: content = describe_mesh(read_whole_mesh(in)); break;
    case Kind::image: content = describe_image(parse(in, read_image)); break;
    case Kind::volume: content = describe_volume(parse(in, read_volume)); break;
    case Kind::dataset: content = describe_dataset(parse(in, read_dataset)); break;
    case Kind::table: content = describe_table(parse(in, read_table)); break;
    case Kind::json: {
      nlohmann::json doc = parse(in, read_json_document);
      content = {{"type", doc.type_name()}, {"size", doc.size()}};
      break;
    }
  }
  facts.update(content);
  return facts;
}

std::string convert(const Input& in, Format to, const Options& opt) {
  switch (kind_of(in.format)) {
    case Kind::mesh: {
      MeshWriteOptions w;
      w.ascii = opt.ascii;
      w.draco_position_bits = opt.draco_bits;
      w.draco_speed = opt.draco_speed;
      w.drop_unrepresentable = opt.drop_unrepresentable;
      if (opt.precision == "float") w.precision = CoordinatePrecision::float32;
      else if (opt.precision == "double") w.precision = CoordinatePrecision::float64;
      const Mesh mesh = read_whole_mesh(in);
      check_losses(mesh, to, opt, in.name);
      return write_mesh(mesh, to, w);
    }
    case Kind::image: {
      ImageWriteOptions w;
      w.ascii = opt.ascii;
      w.exr_half = opt.half;
      w.jpeg_quality = opt.quality;
      return write_image(parse(in, read_image), to, w);
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

// Volumes: --frame picks one frame, --type/--rescale convert values (warning with the
// count of values clipped to the type's range), and a .hdr/.img pair is two files.
void convert_volume(const Input& in, const OutputFormat& out, const Options& opt) {
  VolumeWriteOptions w;
  w.compress = opt.compress;
  if (!opt.volume_type.empty()) {
    ScalarType t;
    if (!parse_scalar_type(opt.volume_type, t))
      throw usage_error("--type: unknown value type '{}' (uint8, int8, uint16, int16, uint32, int32, "
                        "uint64, int64, float32, float64)",
                        opt.volume_type);
    w.type = t;
  }
  if (opt.rescale && (!w.type || !scalar_type_is_integer(*w.type)))
    throw usage_error("--rescale maps values onto an integer type's range: give --type uint8, int16, ...");
  Volume v = parse(in, read_volume);
  if (opt.frame >= 0) v = v.frame(static_cast<std::size_t>(opt.frame));
  if (opt.rescale) rescale_to_type(v, *w.type);
  if (w.type) {
    const ValueConversion c = count_clipped(v, *w.type);
    if (c.clipped > 0) {
      const ScalarType t = *w.type;
      const std::string range = type_range(t);
      fest::warn("fconv", fmt::format("{} of {} values clipped to the {} range {}{}", c.clipped, c.total,
                                      scalar_type_name(t), range, opt.rescale ? "" : " (--rescale maps the input range onto it)"));
    }
  }
  store_volume(opt.output, v, out, w);
}

int run(const Options& opt) {
  const Input in = load_input(opt.input);
  if (opt.info) {
    write_output(opt.output, describe(in).dump(2) + "\n");
    return 0;
  }
  // The output format: --to, else the output file's extension, else (standard output
  // with no --to) the input's own format, so `fconv < a > b` normalises a file.
  OutputFormat out{in.format, false};
  if (!opt.to.empty())
    out = output_format_from_name(opt.to);
  else if (!is_stdio(opt.output))
    out = output_format_from_path(opt.output);
  if (kind_of(out.format) != kind_of(in.format))
    throw usage_error("cannot convert {} {} ({}) to {}, which is {} {} format", article(kind_of(in.format)),
                      kind_name(kind_of(in.format)), format_name(in.format), format_name(out.format),
                      article(kind_of(out.format)), kind_name(kind_of(out.format)));
  if (opt.frame >= 0 && kind_of(in.format) != Kind::volume)
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

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Convert a file to another format of the same kind, or describe it (--info).\n"
               "Input is recognised by its content; gzip-compressed input is unpacked.",
               "fconv"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  Options opt;
  app.add_option("input", opt.input, "Input file, or - for standard input")->default_val("-");
  app.add_option("-o,--output", opt.output, "Output file, or - for standard output")->default_val("-");
  app.add_option("--to", opt.to,
                 "Output format: ply obj off stl drc | png jpg pgm ppm pam pfm exr tiff | nifti (nii) nifti2 hdr mgh mgz nrrd mha | "
                 "vtu vti vtp vtk | csv tsv json; append .gz to compress (nii.gz)");
  app.add_flag("--info", opt.info, "Print the input's metadata as JSON instead of converting");
  app.add_flag("--ascii", opt.ascii, "Text variant where the format has one (PLY, STL, PGM/PPM, VTK)");
  app.add_flag("--compress", opt.compress, "Compress the data inside NRRD (gzip) and MHA (zlib) files");
  app.add_option("--type", opt.volume_type,
                 "Volume value type to write (uint8 ... float64); values outside its range are clipped, with a warning");
  app.add_flag("--rescale", opt.rescale,
               "With an integer --type: map the input's value range linearly onto the type's full range");
  app.add_option("--frame", opt.frame, "Volume: write only frame K (0-based) of a 4-D series, as a 3-D volume")
      ->check(CLI::Range(0L, 1L << 31));
  app.add_flag("--half", opt.half, "EXR: 16-bit half channels instead of 32-bit float");
  app.add_option("--quality", opt.quality, "JPEG output quality, 1 (smallest) to 100 (best)")
      ->check(CLI::Range(1, 100))
      ->default_val(95);
  app.add_option("--draco-bits", opt.draco_bits, "Draco position quantization bits (0 = lossless)")
      ->check(CLI::Range(0, 30));
  app.add_option("--draco-speed", opt.draco_speed, "Draco encoder speed, 0 (smallest) to 10 (fastest)")
      ->check(CLI::Range(0, 10));
  app.add_option("--precision", opt.precision,
                 "PLY positions and normals: float or double (default: float unless float would lose "
                 "precision the input had)")
      ->check(CLI::IsMember({"float", "double"}));
  app.add_flag("--drop-unrepresentable", opt.drop_unrepresentable,
               "Meshes: convert without what fest or the output format cannot hold (other PLY properties "
               "and elements, OBJ per-corner normals/texture coordinates; line or point elements, faces of "
               "fewer than 3 vertices) and count it in a warning, instead of failing");
  app.footer("Exit status: 0 success, 2 usage error, 3 bad input, 4 I/O error. See fconv(1), fest-formats(5).");
  return fest::cli::run(app, argc, argv, [&] { return run(opt); });
}

// fconv: convert a mesh, image, volume, VTK dataset, table or JSON file to another
// format of the same kind, or describe it as JSON (--info).
//
// Flags only: the jobs live in the fest_fconv_app library (cmd_*.cpp).

#include <cstddef>
#include <string>

#include "cli/cli.hpp"
#include "commands.hpp"
#include "core/error.hpp"

int main(int argc, char** argv) {
  using namespace fest::fconv_tool;
  CLI::App app{"Convert a file to another format of the same kind, or describe it (--info).\n"
               "Input is recognised by its content; gzip-compressed input is unpacked.",
               "fconv"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  ConvertOptions opt;
  std::string to, volume_type, precision;
  long frame = -1;
  bool info = false;
  app.add_option("input", opt.input, "Input file, or - for standard input")->default_val("-");
  app.add_option("-o,--output", opt.output, "Output file, or - for standard output")->default_val("-");
  app.add_option("--to", to,
                 "Output format: ply obj off stl drc | png jpg pgm ppm pam pfm exr tiff | nifti (nii) nifti2 hdr mgh mgz nrrd mha | "
                 "vtu vti vtp vtk | csv tsv json; append .gz to compress (nii.gz)");
  app.add_flag("--info", info, "Print the input's metadata as JSON instead of converting");
  app.add_flag("--ascii", opt.ascii, "Text variant where the format has one (PLY, STL, PGM/PPM, VTK)");
  app.add_flag("--compress", opt.compress, "Compress the data inside NRRD (gzip) and MHA (zlib) files");
  app.add_option("--type", volume_type,
                 "Volume value type to write (uint8 ... float64); values outside its range are clipped, with a warning");
  app.add_flag("--rescale", opt.rescale,
               "With an integer --type: map the input's value range linearly onto the type's full range");
  app.add_option("--frame", frame, "Volume: write only frame K (0-based) of a 4-D series, as a 3-D volume")
      ->check(fest::cli::range(0L, 1L << 31));
  app.add_flag("--half", opt.half, "EXR: 16-bit half channels instead of 32-bit float");
  app.add_option("--quality", opt.quality, "JPEG output quality, 1 (smallest) to 100 (best)")
      ->check(fest::cli::range(1, 100))
      ->default_val(95);
  app.add_option("--draco-bits", opt.draco_bits,
                 "Draco position quantization bits, draco_encoder's -qp (0 = lossless: every attribute exact, "
                 "vertex and face order kept)")
      ->check(fest::cli::range(0, 30))
      ->default_val(11);
  app.add_option("--draco-normal-bits", opt.draco_normal_bits,
                 "Draco normal quantization bits, draco_encoder's -qn (0 = unquantized)")
      ->check(fest::cli::range(0, 30))
      ->default_val(8);
  app.add_option("--draco-texcoord-bits", opt.draco_texcoord_bits,
                 "Draco texture coordinate quantization bits, draco_encoder's -qt (0 = unquantized)")
      ->check(fest::cli::range(0, 30))
      ->default_val(10);
  app.add_option("--draco-speed", opt.draco_speed,
                 "Draco encoder speed, 0 (smallest) to 10 (fastest; sequential coding): 10 minus "
                 "draco_encoder's compression level -cl")
      ->check(fest::cli::range(0, 10))
      ->default_val(3);
  app.add_option("--precision", precision,
                 "PLY positions and normals: float or double (default: float unless float would lose "
                 "precision the input had)")
      ->check(CLI::IsMember({"float", "double"}));
  app.add_flag("--drop-unrepresentable", opt.drop_unrepresentable,
               "Meshes: convert without what fest or the output format cannot hold (other PLY properties "
               "and elements, OBJ per-corner normals/texture coordinates; line or point elements, faces of "
               "fewer than 3 vertices) and count it in a warning, instead of failing");
  app.footer("Exit status: 0 success, 2 usage error, 3 bad input, 4 I/O error. See fconv(1), fest-formats(5).");
  return fest::cli::run(app, argc, argv, [&] {
    if (info) return info_command(InfoOptions{opt.input, opt.output});
    if (!to.empty()) opt.to = fest::formats::output_format_from_name(to);
    if (!volume_type.empty()) {
      fest::ScalarType t;
      if (!fest::parse_scalar_type(volume_type, t))
        throw fest::usage_error("--type: unknown value type '{}' (uint8, int8, uint16, int16, uint32, int32, "
                                "uint64, int64, float32, float64)",
                                volume_type);
      opt.volume_type = t;
    }
    if (frame >= 0) opt.frame = static_cast<std::size_t>(frame);
    if (precision == "float") opt.precision = fest::formats::CoordinatePrecision::float32;
    else if (precision == "double") opt.precision = fest::formats::CoordinatePrecision::float64;
    return convert_command(opt);
  });
}

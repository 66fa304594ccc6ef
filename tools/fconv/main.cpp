// fconv: convert a mesh, image, volume, VTK dataset, table or JSON file to another
// format of the same kind, or describe it as JSON (--info).
//
// Flags only: the jobs live in the fest_fconv_app library (cmd_*.cpp).

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>
#include <string>

#include "cli/cli.hpp"
#include "cli/enum_option.hpp"
#include "cli/number_list.hpp"
#include "commands.hpp"
#include "core/error.hpp"

int main(int argc, char** argv) {
  using namespace fest::fconv_tool;
  CLI::App app{"Convert a file to another format of the same kind, or describe it (--info).\n"
               "A volume (NIfTI, NRRD, MHA, MGH, VTI, frame stream) to an image format (--to png) is a quick\n"
               "look: orthogonal slices, a montage or MIPs with orientation letters and a scale bar.\n"
               "Input is recognised by its content; gzip-compressed input is unpacked.",
               "fconv"};
  fest::cli::Common common;
  fest::cli::add_common(app, common);
  ConvertOptions opt;
  std::string to, volume_type, precision, slice_text, window_text;
  fest::VolumeViewKind view = fest::VolumeViewKind::ortho;
  long frame = -1;
  bool info = false;
  app.add_option("input", opt.input, "Input file, or - for standard input")->default_val("-");
  app.add_option("-o,--output", opt.output, "Output file, or - for standard output")->default_val("-");
  app.add_option("--to", to,
                 "Output format: ply obj off stl drc | png jpg pgm ppm pam pfm exr tiff | nifti (nii) nifti2 hdr mgh mgz nrrd mha | "
                 "vtu vti vtp vtk | csv tsv json; append .gz to compress (nii.gz)");
  fest::cli::add_progress(app, opt.progress);
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
  app.add_flag("--flatten", opt.flatten, "PGM/PPM/JPEG output: composite alpha over --background (default white)");
  app.add_option_function<std::string>(
      "--background",
      [&opt](const std::string& text) {
        const auto rgb = fest::cli::integer_list(text, 3, 3, "--background", 0, 255);
        for (int c = 0; c < 3; ++c) opt.background[std::size_t(c)] = double(rgb[std::size_t(c)]) / 255.0;
        opt.flatten = true;
      },
      "Background R,G,B (sRGB codes 0-255) that --flatten composites over; implies --flatten");
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
  fest::cli::enum_words<fest::VolumeViewKind>(app.add_option("--view", view,
                                       "Volume to image: ortho (three orthogonal slices), montage (12 axial slices) or mip "
                                       "(maximum intensity projections along the three axes)")
                            ->default_str("ortho"),
                        {{"ortho", fest::VolumeViewKind::ortho},
                         {"montage", fest::VolumeViewKind::montage},
                         {"mip", fest::VolumeViewKind::mip}});
  app.add_option("--slice", slice_text, "Volume to image, ortho: the voxel I,J,K (from 0, the file's voxel order) the slices pass through (default: the centre)");
  app.add_option("--window", window_text, "Volume to image: grey window LO,HI in voxel values (default: 1st to 99th percentile of the non-zero voxels)");
  fest::cli::enum_words<fest::DisplayConvention>(app.add_option("--convention", opt.convention,
                                       "Volume to image: neurological (patient's left on the image's left) or radiological "
                                       "(patient's right on the left)")
                            ->default_str("neurological"),
                        {{"neurological", fest::DisplayConvention::neurological},
                         {"radiological", fest::DisplayConvention::radiological}});
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
    opt.verbose = common.verbose;
    if (app.count("--view") > 0) opt.view = view;
    if (!slice_text.empty()) {
      const std::vector<double> ijk = fest::cli::number_list(slice_text, 3, 3, "--slice");
      std::array<std::size_t, 3> at{};
      for (int a = 0; a < 3; ++a) {
        if (ijk[a] < 0 || ijk[a] != std::floor(ijk[a]) || ijk[a] > 1e12)
          throw fest::usage_error("--slice takes voxel indices I,J,K (whole numbers from 0), not '{}'", slice_text);
        at[a] = static_cast<std::size_t>(ijk[a]);
      }
      opt.slice = at;
    }
    if (!window_text.empty()) {
      const std::vector<double> w = fest::cli::number_list(window_text, 2, 2, "--window");
      if (!(w[0] < w[1])) throw fest::usage_error("--window LO,HI needs LO < HI, not '{}'", window_text);
      opt.window = std::array<double, 2>{w[0], w[1]};
    }
    if (frame >= 0) opt.frame = static_cast<std::size_t>(frame);
    if (precision == "float") opt.precision = fest::formats::CoordinatePrecision::float32;
    else if (precision == "double") opt.precision = fest::formats::CoordinatePrecision::float64;
    return convert_command(opt);
  });
}

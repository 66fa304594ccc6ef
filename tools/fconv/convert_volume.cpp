// fconv on volumes: frame selection, value types with a count of what was clipped.

#include <limits>
#include <string>

#include <fmt/format.h>

#include "convert.hpp"
#include "core/error.hpp"
#include "core/tool_main.hpp"
#include "formats/volume/volume_io.hpp"

namespace fest::fconv_tool {

using namespace fest::formats;

namespace {

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

}  // namespace

void convert_volume(const Input& in, const OutputFormat& out, const ConvertOptions& opt) {
  VolumeWriteOptions w;
  w.compress = opt.compress;
  w.type = opt.volume_type;
  if (opt.rescale && (!w.type || !scalar_type_is_integer(*w.type)))
    throw usage_error("--rescale maps values onto an integer type's range: give --type uint8, int16, ...");
  Volume v = parse(in, read_volume);
  if (opt.frame) v = v.frame(*opt.frame);
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

}  // namespace fest::fconv_tool

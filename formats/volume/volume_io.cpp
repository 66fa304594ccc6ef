#include "formats/volume/volume_io.hpp"

#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "formats/volume/metaimage.hpp"
#include "formats/volume/nifti.hpp"
#include "formats/volume/nrrd.hpp"

namespace fest::formats {

Volume read_volume(std::string_view bytes, Format format) {
  if (bytes.empty()) throw bad_input("empty input: no {} volume to read", format_name(format));
  switch (format) {
    case Format::nifti: return volume_detail::read_nifti(bytes);
    case Format::nrrd: return volume_detail::read_nrrd(bytes);
    case Format::mha: return volume_detail::read_metaimage(bytes);
    default: break;
  }
  throw bad_input("{} is not a volume format (NIfTI, NRRD or MetaImage)", format_name(format));
}

// Values are converted to the stored type by volume_detail::storable_value: rounded to
// the nearest integer and clamped to the type's range for integer types (NaN -> 0).
std::string write_volume(const Volume& volume, Format format, const VolumeWriteOptions& options) {
  const ScalarType type = options.type.value_or(volume.type);
  switch (format) {
    case Format::nifti: return volume_detail::write_nifti(volume, type);
    case Format::nrrd: return volume_detail::write_nrrd(volume, type, options.compress);
    case Format::mha: return volume_detail::write_metaimage(volume, type, options.compress);
    default: break;
  }
  throw usage_error("cannot write a volume as {} (use nii, nrrd or mha)", format_name(format));
}

nlohmann::json describe_volume(const Volume& volume) {
  nlohmann::json doc;
  doc["dimensions"] = {volume.dims[0], volume.dims[1], volume.dims[2]};
  doc["spacing"] = volume.spacing;
  doc["origin"] = volume.origin;
  doc["direction"] = volume.direction;
  doc["value_type"] = scalar_type_name(volume.type);
  // NaN voxels (possible in float volumes) are left out of the statistics.
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, sum = 0;
  std::size_t counted = 0;
  for (double v : volume.voxels) {
    if (std::isnan(v)) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    sum += v;
    ++counted;
  }
  if (counted > 0) {
    doc["min"] = lo;
    doc["max"] = hi;
    doc["mean"] = sum / static_cast<double>(counted);
  } else {
    doc["min"] = nullptr;
    doc["max"] = nullptr;
    doc["mean"] = nullptr;
  }
  return doc;
}

}  // namespace fest::formats

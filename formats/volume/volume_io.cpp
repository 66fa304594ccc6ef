#include "formats/volume/volume_io.hpp"

#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/gzip.hpp"
#include "formats/volume/metaimage.hpp"
#include "formats/volume/mgh.hpp"
#include "formats/volume/nifti.hpp"
#include "formats/volume/nrrd.hpp"
#include "formats/volume/voxel_codec.hpp"

namespace fest::formats {

Volume VolumeReader::operator()(std::string_view bytes, Format format) const {
  if (bytes.empty()) throw bad_input("empty input: no {} volume to read", format_name(format));
  switch (format) {
    case Format::nifti:
    case Format::nifti2:
    case Format::nifti_pair:
    case Format::analyze: return volume_detail::read_nifti(bytes);
    case Format::mgh: return volume_detail::read_mgh(bytes);
    case Format::nrrd: return volume_detail::read_nrrd(bytes);
    case Format::mha: return volume_detail::read_metaimage(bytes);
    default: break;
  }
  throw bad_input("{} is not a volume format (NIfTI, Analyze, MGH, NRRD or MetaImage)", format_name(format));
}

Volume VolumeReader::operator()(const Input& in) const {
  if ((in.format == Format::nifti_pair || in.format == Format::analyze) && in.has_companion) {
    if (in.bytes.empty()) throw bad_input("empty input: no {} volume to read", format_name(in.format));
    try {
      const std::string_view image(in.companion);
      return volume_detail::read_nifti(in.bytes, &image);
    } catch (const Error& e) {
      // Name both files: a size mismatch may be either one's fault.
      if (e.status() != Status::bad_input) throw;
      throw Error(e.status(), fmt::format("{} (image file {})", e.what(), in.companion_name));
    }
  }
  return (*this)(in.bytes, in.format);
}

// Values are converted to the stored type by volume_detail::storable_value: rounded to
// the nearest integer and clamped to the type's range for integer types (NaN -> 0).
std::string write_volume(const Volume& volume, Format format, const VolumeWriteOptions& options) {
  const ScalarType type = options.type.value_or(volume.type);
  switch (format) {
    case Format::nifti: return volume_detail::write_nifti(volume, type);
    case Format::nifti2: return volume_detail::write_nifti2(volume, type);
    case Format::mgh: return volume_detail::write_mgh(volume, type);
    case Format::nrrd: return volume_detail::write_nrrd(volume, type, options.compress);
    case Format::mha: return volume_detail::write_metaimage(volume, type, options.compress);
    case Format::nifti_pair:
      throw usage_error("a NIfTI .hdr/.img pair is two files and cannot be written to one stream; name a .hdr "
                        "output file, or use --to nii for a single file");
    case Format::analyze:
      throw usage_error("fest does not write Analyze 7.5, which cannot state orientation; write a NIfTI-1 pair "
                        "(.hdr/.img, --to hdr) instead, which Analyze readers such as SPM also read");
    default: break;
  }
  throw usage_error("cannot write a volume as {} (use nii, nii2, hdr, mgh, mgz, nrrd or mha)", format_name(format));
}

std::string pair_image_path(const std::string& header_path) {
  std::string p = header_path;
  std::string suffix;
  if (p.size() > 3 && (p.compare(p.size() - 3, 3, ".gz") == 0 || p.compare(p.size() - 3, 3, ".GZ") == 0)) {
    suffix = p.substr(p.size() - 3);
    p.resize(p.size() - 3);
  }
  if (p.size() < 5 || (p.compare(p.size() - 4, 4, ".hdr") != 0 && p.compare(p.size() - 4, 4, ".HDR") != 0))
    throw usage_error("a .hdr/.img pair needs an output name ending in .hdr ('{}')", header_path);
  const bool upper = p.compare(p.size() - 4, 4, ".HDR") == 0;
  p.replace(p.size() - 4, 4, upper ? ".IMG" : ".img");
  return p + suffix;
}

void store_volume(const std::string& path, const Volume& volume, const OutputFormat& format,
                  const VolumeWriteOptions& options) {
  if (format.format != Format::nifti_pair) {
    store_output(path, write_volume(volume, format.format, options), format.gzip);
    return;
  }
  if (is_stdio(path))
    throw usage_error("a NIfTI .hdr/.img pair is two files and cannot go to standard output; name a .hdr output file");
  const std::string image_path = pair_image_path(path);
  const volume_detail::NiftiPairBytes pair = volume_detail::write_nifti_pair(volume, options.type.value_or(volume.type));
  // The image first: a reader that finds the header finds its data.
  store_output(image_path, pair.image, format.gzip);
  store_output(path, pair.header, format.gzip);
}

nlohmann::json describe_volume(const Volume& volume) {
  nlohmann::json doc;
  doc["dimensions"] = {volume.dims[0], volume.dims[1], volume.dims[2]};
  if (volume.frames > 1) {
    // The fourth dimension: frames of the series and the step between them.
    doc["frames"] = volume.frames;
    doc["frame_spacing"] = volume.frame_spacing;
  }
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

ValueConversion count_clipped(const Volume& volume, ScalarType type) noexcept {
  ValueConversion c;
  c.total = volume.voxels.size();
  if (type == ScalarType::f64) return c;
  for (double v : volume.voxels) {
    if (std::isnan(v)) continue;
    const double stored = volume_detail::storable_value(v, type);
    if (type == ScalarType::f32) {
      if (std::isfinite(v) && std::fabs(v) > static_cast<double>(std::numeric_limits<float>::max()) &&
          std::fabs(stored) >= static_cast<double>(std::numeric_limits<float>::max()))
        ++c.clipped;
    } else if (stored != std::round(v)) {
      ++c.clipped;  // rounding alone never differs from round(v): only clamping does
    }
  }
  return c;
}

bool rescale_to_type(Volume& volume, ScalarType type) noexcept {
  if (!scalar_type_is_integer(type)) return false;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double v : volume.voxels) {
    if (!std::isfinite(v)) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (!(lo <= hi)) return false;
  const double tmin = volume_detail::storable_value(-std::numeric_limits<double>::infinity(), type);
  const double tmax = volume_detail::storable_value(std::numeric_limits<double>::infinity(), type);
  const double scale = hi > lo ? (tmax - tmin) / (hi - lo) : 0.0;
  for (double& v : volume.voxels) {
    if (std::isnan(v)) continue;
    if (std::isinf(v)) {
      v = v > 0 ? tmax : tmin;
      continue;
    }
    v = tmin + (v - lo) * scale;
  }
  volume.type = type;
  return true;
}

}  // namespace fest::formats

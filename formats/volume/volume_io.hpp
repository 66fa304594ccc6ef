#pragma once
// Volumes: NIfTI-1 and NIfTI-2 (.nii; .nii.gz through formats/gzip), NIfTI/Analyze
// .hdr/.img pairs, FreeSurfer MGH (.mgh, .mgz), NRRD, MetaImage (.mha). 3-D volumes and
// 4-D series (Volume::frames) in every one of them.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

#include "core/volume.hpp"
#include "formats/detect.hpp"
#include "formats/input.hpp"

namespace fest::formats {

struct VolumeWriteOptions {
  bool compress = false;                 // NRRD gzip encoding, MHA CompressedData
  std::optional<ScalarType> type;        // store as this type instead of volume.type
};

// read_volume(bytes, format) reads one file's bytes; read_volume(input) also reads
// .hdr/.img pairs, whose image file formats/input loads beside the header
// (Input::companion). It is one callable object so that `parse(in, read_volume)` picks
// the Input form and every tool reads pairs without change.
struct VolumeReader {
  Volume operator()(std::string_view bytes, Format format) const;
  Volume operator()(const Input& in) const;
};
inline constexpr VolumeReader read_volume{};

// One file's bytes. A .hdr/.img pair (Format::nifti_pair) is two files: write it with
// store_volume or write_nifti_pair_files; Analyze 7.5 is read only.
std::string write_volume(const Volume& volume, Format format, const VolumeWriteOptions& options = {});

// Writes a volume to a path ("-": standard output) in the given output format: one file,
// or for a .hdr/.img pair the image file and then the header file (each atomically;
// gzip-compressed as .hdr.gz/.img.gz when the output says so).
void store_volume(const std::string& path, const Volume& volume, const OutputFormat& format,
                  const VolumeWriteOptions& options = {});

// The image file beside a pair's header: x.hdr -> x.img, x.HDR -> x.IMG, x.hdr.gz ->
// x.img.gz. Throws usage_error when the name does not end in .hdr (or .hdr.gz).
std::string pair_image_path(const std::string& header_path);

nlohmann::json describe_volume(const Volume& volume);

// Value conversion to a stored type (fconv --type, --rescale).
struct ValueConversion {
  std::size_t clipped = 0;  // values outside the type's range (each stored as the nearest bound)
  std::size_t total = 0;
};
// Counts the values that storing as `type` would clip to its range (integer types:
// after rounding; float32: finite values beyond its largest; NaN is not counted).
ValueConversion count_clipped(const Volume& volume, ScalarType type) noexcept;
// Maps the finite value range [lo, hi] of the volume linearly onto the full range of an
// integer type [tmin, tmax]: v' = tmin + (v - lo) * (tmax - tmin) / (hi - lo); a constant
// volume maps to tmin. Float types are left unchanged (they hold every value already).
// Returns false when nothing was changed (a float type, or no finite value).
bool rescale_to_type(Volume& volume, ScalarType type) noexcept;

}  // namespace fest::formats

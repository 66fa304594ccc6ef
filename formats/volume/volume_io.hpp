#pragma once
// Volumes: NIfTI-1 (.nii; .nii.gz through formats/gzip), NRRD, MetaImage (.mha).

#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

#include "core/volume.hpp"
#include "formats/detect.hpp"

namespace fest::formats {

struct VolumeWriteOptions {
  bool compress = false;                 // NRRD gzip encoding, MHA CompressedData
  std::optional<ScalarType> type;        // store as this type instead of volume.type
};

Volume read_volume(std::string_view bytes, Format format);
std::string write_volume(const Volume& volume, Format format, const VolumeWriteOptions& options = {});
nlohmann::json describe_volume(const Volume& volume);

}  // namespace fest::formats

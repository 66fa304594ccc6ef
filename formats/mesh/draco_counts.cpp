#include "formats/mesh/draco_counts.hpp"

#include <cstdint>

#include <draco/compression/config/compression_shared.h>
#include <draco/compression/point_cloud/point_cloud_decoder.h>
#include <draco/core/decoder_buffer.h>
#include <draco/core/varint_decoding.h>
#include <draco/metadata/geometry_metadata.h>
#include <draco/metadata/metadata_decoder.h>

#include "core/error.hpp"

namespace fest::formats::mesh_detail {

namespace {

// The best connectivity coders spend a few bits per triangle and attributes cost more;
// 1024 elements per input byte is far beyond any real file and still bounds what a
// hostile header can make the decoder reserve to a few kilobytes per byte.
constexpr std::uint64_t kMaxElementsPerByte = 1024;

void check_count(std::uint64_t count, std::size_t input_bytes, const char* what) {
  const std::uint64_t limit = kMaxElementsPerByte * input_bytes + 1024;
  if (count > limit)
    throw bad_input("Draco: {} {} cannot be encoded in {} bytes (at most {} plausible)", count, what, input_bytes,
                    limit);
}

std::uint32_t varint(draco::DecoderBuffer& buffer, const char* what) {
  std::uint32_t value = 0;
  if (!draco::DecodeVarint(&value, &buffer)) throw bad_input("Draco: truncated header ({})", what);
  return value;
}

}  // namespace

void check_draco_counts(std::string_view bytes) {
  draco::DecoderBuffer buffer;
  buffer.Init(bytes.data(), bytes.size());
  draco::DracoHeader header{};
  if (!draco::PointCloudDecoder::DecodeHeader(&buffer, &header).ok()) throw bad_input("Draco: malformed header");
  // Draco 1.4 and later write meshes as bitstream 2.2 and point clouds as 2.3; older
  // versions lay their headers out differently and are not read.
  const bool point_cloud = header.encoder_type == draco::POINT_CLOUD;
  const bool supported = header.version_major == 2 && (header.version_minor == 2 || (point_cloud && header.version_minor == 3));
  if (!supported)
    throw bad_input("Draco bitstream version {}.{} is not supported (fest reads 2.2 meshes and 2.2/2.3 point clouds, "
                    "as written by Draco 1.4 and later)",
                    header.version_major, header.version_minor);
  buffer.set_bitstream_version(DRACO_BITSTREAM_VERSION(header.version_major, header.version_minor));
  if (header.flags & METADATA_FLAG_MASK) {
    draco::MetadataDecoder metadata_decoder;
    draco::GeometryMetadata metadata;
    if (!metadata_decoder.DecodeGeometryMetadata(&buffer, &metadata)) throw bad_input("Draco: malformed metadata");
  }
  const std::size_t n = bytes.size();
  if (point_cloud) {
    // Both point-cloud methods (sequential, kd-tree) start with an int32 point count.
    std::int32_t points = 0;
    if (!buffer.Decode(&points)) throw bad_input("Draco: truncated header (point count)");
    if (points < 0) throw bad_input("Draco: negative point count {}", points);
    check_count(static_cast<std::uint64_t>(points), n, "points");
    return;
  }
  if (header.encoder_type != draco::TRIANGULAR_MESH)
    throw bad_input("Draco: unsupported geometry type {}", header.encoder_type);
  if (header.encoder_method == draco::MESH_SEQUENTIAL_ENCODING) {
    check_count(varint(buffer, "face count"), n, "faces");
    check_count(varint(buffer, "point count"), n, "points");
  } else if (header.encoder_method == draco::MESH_EDGEBREAKER_ENCODING) {
    std::uint8_t traversal = 0;
    if (!buffer.Decode(&traversal)) throw bad_input("Draco: truncated header (traversal type)");
    check_count(varint(buffer, "vertex count"), n, "vertices");
    check_count(varint(buffer, "face count"), n, "faces");
    std::uint8_t attribute_data = 0;
    if (!buffer.Decode(&attribute_data)) throw bad_input("Draco: truncated header (attribute data)");
    check_count(varint(buffer, "symbol count"), n, "symbols");
    check_count(varint(buffer, "split symbol count"), n, "split symbols");
  } else {
    throw bad_input("Draco: unknown mesh encoding method {}", header.encoder_method);
  }
}

}  // namespace fest::formats::mesh_detail

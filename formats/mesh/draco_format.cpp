// Draco .drc through the Draco library. Decoding accepts triangle meshes and point
// clouds; positions, normals, colours and texture coordinates are carried over.
// Encoding: lossless (position bits 0) uses sequential coding with no quantization,
// which keeps vertex and face order and stores positions as float32 unless float32 would
// lose precision the input had (then float64, as PLY does; see CoordinatePrecision);
// quantized output lets Draco choose its method from the speed (Edgebreaker below 10),
// and quantizes normals and texture coordinates as draco_encoder does (draco_normal_bits,
// draco_texcoord_bits; 0 = that attribute unquantized), so that equal settings give
// draco_encoder's file sizes.
// Polygons are written as fans (Draco holds triangles); face colours are not kept.

#include <cstring>
#include <memory>

#include <draco/compression/decode.h>
#include <draco/draco_features.h>
#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>
#include <draco/point_cloud/point_cloud.h>

#include "core/error.hpp"
#include "core/polygon_triangulation.hpp"
#include "formats/mesh/mesh_builder.hpp"
#include "formats/mesh/draco_counts.hpp"
#include "formats/mesh/mesh_formats.hpp"

namespace fest::formats::mesh_detail {
namespace {

// Reads one attribute value of point `p` as doubles; false when the attribute does not
// map the point to a stored value (malformed file).
bool attribute_value(const draco::PointAttribute& attribute, draco::PointIndex p, int components, double* out) {
  if (attribute.is_mapping_identity() ? p.value() >= attribute.size()
                                      : p.value() >= attribute.indices_map_size())
    return false;
  draco::AttributeValueIndex index = attribute.mapped_index(p);
  if (index.value() >= attribute.size()) return false;
  return attribute.ConvertValue<double>(index, static_cast<int8_t>(components), out);
}

// Numbers Draco's ConvertValue can read: a DT_BOOL attribute would make it load
// arbitrary bytes as bool (undefined behaviour, found by the fuzzer).
bool is_number_type(draco::DataType type) { return type >= draco::DT_INT8 && type <= draco::DT_FLOAT64; }

bool is_float_type(draco::DataType type) { return type == draco::DT_FLOAT32 || type == draco::DT_FLOAT64; }

Mesh to_fest_mesh(const draco::PointCloud& cloud, const draco::Mesh* triangles) {
  const draco::PointAttribute* position = cloud.GetNamedAttribute(draco::GeometryAttribute::POSITION);
  if (position == nullptr || position->num_components() != 3 || !is_number_type(position->data_type()))
    throw bad_input("Draco: no three-component numeric position attribute");
  const draco::PointAttribute* normal = cloud.GetNamedAttribute(draco::GeometryAttribute::NORMAL);
  const draco::PointAttribute* color = cloud.GetNamedAttribute(draco::GeometryAttribute::COLOR);
  const draco::PointAttribute* texcoord = cloud.GetNamedAttribute(draco::GeometryAttribute::TEX_COORD);
  // Attributes of a shape fest::Mesh cannot hold are left out.
  if (normal && (normal->num_components() != 3 || !is_number_type(normal->data_type()))) normal = nullptr;
  if (color && (color->num_components() < 3 || !is_number_type(color->data_type()))) color = nullptr;
  if (texcoord && (texcoord->num_components() != 2 || !is_number_type(texcoord->data_type()))) texcoord = nullptr;
  const std::uint32_t n_points = cloud.num_points();
  if (n_points > max_element_count) throw bad_input("Draco: {} points are more than fest can hold", n_points);

  Mesh mesh;
  if (normal) mesh.request_vertex_normals();
  if (color) mesh.request_vertex_colors();
  if (texcoord) mesh.request_vertex_texcoords2D();
  const std::size_t n_faces = triangles ? triangles->num_faces() : 0;
  mesh.reserve(n_points, n_points + n_faces, n_faces);
  for (draco::PointIndex p(0); p < n_points; ++p) {
    double v[4] = {0, 0, 0, 0};
    if (!attribute_value(*position, p, 3, v)) throw bad_input("Draco: point {} has no position", p.value());
    Mesh::VertexHandle vh = mesh.add_vertex(Mesh::Point(v[0], v[1], v[2]));
    if (normal) {
      if (!attribute_value(*normal, p, 3, v)) throw bad_input("Draco: point {} has no normal", p.value());
      mesh.set_normal(vh, Mesh::Normal(v[0], v[1], v[2]));
    }
    if (color) {
      if (!attribute_value(*color, p, 3, v)) throw bad_input("Draco: point {} has no colour", p.value());
      Mesh::Color c;
      for (int k = 0; k < 3; ++k)
        c[k] = is_float_type(color->data_type()) ? color_from_unit(v[k]) : color_from_byte_range(v[k]);
      mesh.set_color(vh, c);
    }
    if (texcoord) {
      if (!attribute_value(*texcoord, p, 2, v)) throw bad_input("Draco: point {} has no texture coordinate", p.value());
      mesh.set_texcoord2D(vh, Mesh::TexCoord2D(narrow_to_float(v[0]), narrow_to_float(v[1])));
    }
  }
  MeshBuilder builder(mesh, "Draco");
  for (draco::FaceIndex f(0); f < n_faces; ++f) {
    const draco::Mesh::Face& face = triangles->face(f);
    std::uint32_t indices[3] = {face[0].value(), face[1].value(), face[2].value()};
    builder.add_face(indices, 3, f.value() + 1);
  }
  builder.finish();
  return mesh;
}

template <typename T>
int add_attribute(draco::PointCloud& cloud, draco::GeometryAttribute::Type type, int components,
                  draco::DataType data_type, std::size_t n_points) {
  draco::GeometryAttribute attribute;
  attribute.Init(type, nullptr, static_cast<int8_t>(components), data_type, false,
                 static_cast<int64_t>(sizeof(T) * components), 0);
  return cloud.AddAttribute(attribute, true, static_cast<uint32_t>(n_points));
}

// Copies one per-vertex vector (get(v) returns it) into attribute `id`.
template <typename T, typename Get>
void set_values(draco::PointCloud& cloud, int id, const Mesh& mesh, int components, Get get) {
  draco::PointAttribute* attribute = cloud.attribute(id);
  T value[3];
  for (auto v : mesh.vertices()) {
    const auto data = get(v);
    for (int k = 0; k < components; ++k) value[k] = static_cast<T>(data[k]);
    attribute->SetAttributeValue(draco::AttributeValueIndex(v.idx()), value);
  }
}

}  // namespace

Mesh read_drc(std::string_view bytes) {
  // Draco's own header check first: magic "DRACO", version, geometry type.
  if (bytes.size() < 5 || std::memcmp(bytes.data(), "DRACO", 5) != 0) throw bad_input("Draco: missing DRACO magic");
  draco::DecoderBuffer buffer;
  buffer.Init(bytes.data(), bytes.size());
  auto type = draco::Decoder::GetEncodedGeometryType(&buffer);
  if (!type.ok()) throw bad_input("Draco header: {}", type.status().error_msg_string());
  check_draco_counts(bytes);
  draco::Decoder decoder;
  if (type.value() == draco::TRIANGULAR_MESH) {
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok()) throw bad_input("Draco: {}", decoded.status().error_msg_string());
    std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
    return to_fest_mesh(*mesh, mesh.get());
  }
  if (type.value() == draco::POINT_CLOUD) {
    auto decoded = decoder.DecodePointCloudFromBuffer(&buffer);
    if (!decoded.ok()) throw bad_input("Draco: {}", decoded.status().error_msg_string());
    return to_fest_mesh(*decoded.value(), nullptr);
  }
  throw bad_input("Draco: unsupported geometry type {}", static_cast<int>(type.value()));
}

std::string write_drc(const Mesh& input, const MeshWriteOptions& options) {
  const MeshToWrite written(input);
  const Mesh& mesh = written.mesh;
  const std::size_t n = mesh.n_vertices();
  const bool lossless = options.draco_position_bits == 0;
  // A mesh without faces is a point cloud to Draco (its mesh coders need triangles).
  std::unique_ptr<draco::PointCloud> cloud;
  draco::Mesh* triangles = nullptr;
  const FacesBeside extra = extra_faces_to_write(mesh);
  if (mesh.n_faces() + extra.faces.size() > 0) {
    auto owned = std::make_unique<draco::Mesh>();
    triangles = owned.get();
    cloud = std::move(owned);
  } else {
    cloud = std::make_unique<draco::PointCloud>();
  }
  cloud->set_num_points(static_cast<uint32_t>(n));

  // Quantization works on float32; lossless keeps doubles only where float32 would lose
  // precision the input had (the PLY writer's rule, CoordinatePrecision): most readers of
  // .drc (draco_decoder's PLY output, three.js) handle float32 positions only.
  if (lossless && !write_points_as_float(mesh, options.precision)) {
    int id = add_attribute<double>(*cloud, draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT64, n);
    set_values<double>(*cloud, id, mesh, 3, [&](Mesh::VertexHandle v) { return mesh.point(v); });
  } else {
    int id = add_attribute<float>(*cloud, draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32, n);
    draco::PointAttribute* attribute = cloud->attribute(id);
    for (auto v : mesh.vertices()) {
      const Mesh::Point& p = mesh.point(v);
      float value[3] = {narrow_to_float(p[0]), narrow_to_float(p[1]), narrow_to_float(p[2])};
      attribute->SetAttributeValue(draco::AttributeValueIndex(v.idx()), value);
    }
  }
  // Quantized normals are float32 to Draco's octahedral coder whatever their precision.
  const bool quantize_normals = !lossless && options.draco_normal_bits > 0;
  if (mesh.has_vertex_normals()) {
    if (quantize_normals || write_normals_as_float(mesh, options.precision)) {
      int id = add_attribute<float>(*cloud, draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32, n);
      set_values<float>(*cloud, id, mesh, 3, [&](Mesh::VertexHandle v) { return mesh.normal(v); });
    } else {
      int id = add_attribute<double>(*cloud, draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT64, n);
      set_values<double>(*cloud, id, mesh, 3, [&](Mesh::VertexHandle v) { return mesh.normal(v); });
    }
  }
  if (mesh.has_vertex_colors()) {
    int id = add_attribute<std::uint8_t>(*cloud, draco::GeometryAttribute::COLOR, 3, draco::DT_UINT8, n);
    set_values<std::uint8_t>(*cloud, id, mesh, 3, [&](Mesh::VertexHandle v) { return mesh.color(v); });
  }
  if (mesh.has_vertex_texcoords2D()) {
    int id = add_attribute<float>(*cloud, draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32, n);
    set_values<float>(*cloud, id, mesh, 2, [&](Mesh::VertexHandle v) { return mesh.texcoord2D(v); });
  }
  if (triangles)
    for_each_written_face(mesh, extra, [&](const std::vector<int>& face, const Mesh::Color*, Mesh::FaceHandle) {
      // A fan around the first corner, or ears for a concave polygon.
      std::vector<std::array<double, 3>> positions;
      for (int v : face) {
        const Mesh::Point& p = mesh.point(Mesh::VertexHandle(v));
        positions.push_back({p[0], p[1], p[2]});
      }
      for (const auto& t : triangulate_polygon(positions))
        triangles->AddFace({draco::PointIndex(static_cast<uint32_t>(face[t[0]])),
                            draco::PointIndex(static_cast<uint32_t>(face[t[1]])),
                            draco::PointIndex(static_cast<uint32_t>(face[t[2]]))});
    });

#if defined(DRACO_ATTRIBUTE_VALUES_DEDUPLICATION_SUPPORTED) && defined(DRACO_ATTRIBUTE_INDICES_DEDUPLICATION_SUPPORTED)
  // Quantized output shares equal attribute values and merges points equal in every
  // attribute, as draco_encoder's readers do: a mesh stored one vertex per corner (3DS,
  // STL-like PLY files) then codes its connectivity across the shared positions, and its
  // file is draco_encoder's size rather than several times it. Lossless output keeps
  // every vertex (its promise is the same vertex list back).
  if (!lossless) {
    cloud->DeduplicateAttributeValues();
    cloud->DeduplicatePointIds();
  }
#endif
  draco::Encoder encoder;
  encoder.SetSpeedOptions(options.draco_speed, options.draco_speed);
  if (lossless) encoder.SetEncodingMethod(draco::MESH_SEQUENTIAL_ENCODING);
  else {
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, options.draco_position_bits);
    if (quantize_normals) encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, options.draco_normal_bits);
    if (options.draco_texcoord_bits > 0)
      encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, options.draco_texcoord_bits);
  }
  draco::EncoderBuffer buffer;
  draco::Status status = triangles ? encoder.EncodeMeshToBuffer(*triangles, &buffer)
                                   : encoder.EncodePointCloudToBuffer(*cloud, &buffer);
  if (!status.ok()) throw bad_input("Draco encoder: {}", status.error_msg_string());
  return std::string(buffer.data(), buffer.size());
}

}  // namespace fest::formats::mesh_detail

#pragma once
// Recognising input by its content (never only by its name: a pipe has no
// name) and naming output formats by extension or --to.

#include <string>
#include <string_view>

namespace fest::formats {

enum class Kind { mesh, image, volume, dataset, table, json };

enum class Format {
  // meshes
  ply, obj, off, stl, drc,
  // images
  png, pgm, ppm, pam, pfm, exr, tiff, jpeg,  // jpeg: read only
  // volumes (nifti_pair: a .hdr/.img pair, NIfTI-1 or -2; analyze: Analyze 7.5, read only)
  nifti, nrrd, mha, nifti2, nifti_pair, analyze, mgh,
  // VTK datasets
  vtu, vti, vtp, vtk, vts,
  // tables and documents
  csv, tsv, json,
  // meshes read (not written) through the assimp plugin, loaded only for them
  // (formats/mesh/assimp_format.cpp): glTF 2 (text and binary), COLLADA, FBX, 3DS,
  // DirectX .x, LightWave
  gltf, glb, dae, fbx, threeds, xfile, lwo,
};

// True for the formats fest reads through assimp and does not write.
bool read_only_scene_format(Format f) noexcept;

Kind kind_of(Format f) noexcept;
const char* kind_name(Kind k) noexcept;     // "mesh", "image", ...
const char* format_name(Format f) noexcept; // "ply", "nifti", ... (the --to name)
const char* format_extension(Format f) noexcept;  // ".ply", ".nii", ...

// Recognises a (decompressed) input by its first bytes. Throws Status::bad_input with
// a message that names what was seen when nothing matches. `where` names the input in
// the message.
Format detect_format(std::string_view bytes, const std::string& where = "");

// What an output should be: the format, and whether the whole file is gzip-compressed
// (".nii.gz", ".ply.gz", "--to nii.gz").
struct OutputFormat {
  Format format;
  bool gzip = false;
};

// From a --to name: a format name or extension, with an optional ".gz"/"gz" suffix
// ("off", ".off", "nii.gz", "nifti", "ply"). Throws Status::usage when unknown.
OutputFormat output_format_from_name(std::string_view name);
// From an output path's extension. Throws Status::usage when it has no known extension.
OutputFormat output_format_from_path(std::string_view path);

}  // namespace fest::formats

#pragma once
// Importers for the formats real morphable models come in (facefit convert):
//  * eos / cereal binary (.bin, the Surrey Face Model layout; BFM, LYHM and 4DFM as
//    converted by eos's scripts): u32 class version, then the shape PcaModel: mean,
//    orthonormal_pca_basis and eigenvalues each as i32 rows, i32 cols, rows·cols f32
//    (column-major); eigenvalues are variances (σ = √λ); then the triangle list as u64
//    count and count×3 i32. Everything after (colour and expression models) is ignored.
//  * NumPy .npz (zip of .npy members, stored or deflated): the route for Basel 2009/2017
//    and FLAME via a few lines of Python (man/man5/mmb.5 has the recipe).

#include <string>

#include "core/face_model.hpp"

namespace fest::formats {

face::Model read_eos_model(const std::string& bytes, const std::string& source);

// Reads the .npz at `path`. Key aliases: mean|shapeMU|shape_mean, basis|shapePC|pcaBasis,
// sigma|shapeEV (std devs) or variance|pcaVariance|eigenvalues (→ √), triangles|tl|cells
// (1-based when the smallest index is 1; 3×t or t×3). `warnings` gets notes such as
// "triangles were 1-based".
face::Model read_npz_model(const std::string& path, std::string* warnings);

}  // namespace fest::formats

#pragma once
// Materials for the renderer from the materials side's result (brdffit(1),
// `render --svbrdf`): every triangle takes the BRDF f_C of the cluster most of its
// lumitexels belong to (the per-cluster model of the chapter's Fig. 8.6; the per-lumitexel
// blend weights of the .ltw are not carried to the surface). Triangles without a lumitexel
// (never seen, or dropped) take the majority of their neighbours that have one (sharing a
// vertex), wave after wave outwards; where no neighbour ever has one, the cluster with the
// most lumitexels overall.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "brdffit/lumitexel.hpp"
#include "brdffit/project.hpp"
#include "reflectance/render.hpp"

namespace fest::brdffit {

// Throws bad_input when the projection's lumitexel count differs from the set's, or a
// lumitexel names a triangle beyond `triangles`.
reflectance::SurfaceMaterials materials_from_projection(const Projection& projection, const LumitexelSet& set,
                                                        std::size_t triangles);
// The same with the mesh's triangles (vertex indices), whose neighbours fill the gaps.
reflectance::SurfaceMaterials materials_from_projection(const Projection& projection, const LumitexelSet& set,
                                                        const std::vector<std::array<std::uint32_t, 3>>& triangles);

}  // namespace fest::brdffit

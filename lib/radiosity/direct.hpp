#pragma once
// The direct solution used to validate progressive refinement (docs/radiosity.md §3,
// "direct solve"): the element equations B_e = E_e + rho_e sum_i F_{e->i} B_i, with
// B_i = sum_{e' in i} (A_e'/A_i) B_e', assembled with the same form-factor engine and
// solved densely by LU, (I - K) B = E per channel.

#include <vector>

#include "radiosity/form_factors.hpp"
#include "radiosity/model.hpp"

namespace fest::radiosity {

// B per element index (zero for inactive elements). Throws bad_input above
// `max_elements` active elements (the matrix is dense).
std::vector<Rgb> direct_solve(const Model& model, FormFactors& ff, std::size_t max_elements = 5000);

}  // namespace fest::radiosity

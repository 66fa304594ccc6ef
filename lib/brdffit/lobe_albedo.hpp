#pragma once
// Directional albedo of one isotropic Lafortune lobe, the quantity that makes a fitted
// lobe physically plausible or not. For the lobe L(u, v) = max(0, Cxy (ux vx + uy vy) +
// Cz uz vz)^N and an incident direction u, the directional albedo is
//
//   a(u) = integral over the upper hemisphere of L(u, v) v_z dw_v,
//
// the fraction of the light from u that the lobe reflects. Energy conservation asks
// a(u) <= 1 for every u (Lafortune, Foo, Torrance, Greenberg, SIGGRAPH 1997, the chapter's
// [LFTG97]). The lobe is homogeneous of degree N in (Cxy, Cz): scaling both by s scales
// a(u) by s^N, which is how lafortune_model.cpp projects a lobe back onto the bound.

namespace fest::brdffit {

// log max over u of a(u) for one lobe (-infinity for a lobe that is zero everywhere).
// Computed in the log domain because an unbounded fit can reach Cz^N = 1.3^10000.
// Accurate to about 1e-3 relative (quadrature), enough for a bound.
double lobe_log_max_albedo(double cxy, double cz, double n);

}  // namespace fest::brdffit

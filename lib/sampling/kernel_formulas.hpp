#pragma once
// The closed-form kernel shapes of docs/resample.md "Kernels and their responses" as plain functions, so that the catalogue
// only parses names and the tests can evaluate a shape without going through a name.

namespace fest::sampling {

// sin(pi x)/(pi x), 1 at 0.
double sinc(double x);

// Mitchell–Netravali cubic with parameters (B, C); support 2.
double mitchell_netravali(double b, double c, double x);

// sinc(x) sinc(x/a) for |x| < a, else 0.
double lanczos(double a, double x);

// 4-term Blackman–Harris window of total width w centred on 0; 0 outside (-w/2, w/2).
double blackman_harris(double width, double x);

// sinc(x) I0(beta sqrt(1 - (x/a)^2)) / I0(beta) for |x| < a, else 0.
double kaiser(double a, double beta, double x);

// exp(-x^2 / (2 sigma^2)) for |x| < 3 sigma, else 0 (truncated at 3 sigma).
double truncated_gaussian(double sigma, double x);

}  // namespace fest::sampling

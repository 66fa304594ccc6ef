#pragma once
// The camera response recovered from an exposure series by the method the user chose
// (docs/hdrmerge.md): merge, calibrate and session share it.

#include "commands.hpp"
#include "hdr/debevec.hpp"
#include "hdr/stack.hpp"

namespace fest::hdrmerge_tool {

// Debevec-Malik with `samples` pixels per channel and smoothness `lambda`, or Robertson et al.
hdr::Response recover_response(const hdr::ExposureStack& stack, Method method, int samples, double lambda);

}  // namespace fest::hdrmerge_tool

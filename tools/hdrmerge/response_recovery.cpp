#include "response_recovery.hpp"

#include "hdr/robertson.hpp"

namespace fest::hdrmerge_tool {

hdr::Response recover_response(const hdr::ExposureStack& stack, Method method, int samples, double lambda) {
  if (method == Method::robertson) return hdr::recover_response_robertson(stack);
  hdr::DebevecOptions o;
  o.samples = samples;
  o.lambda = lambda;
  return hdr::recover_response_debevec(stack, o);
}

}  // namespace fest::hdrmerge_tool

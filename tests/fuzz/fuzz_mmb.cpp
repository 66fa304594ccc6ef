// facefit's native model file .mmb (formats/facemodel/mmb, man/man5/mmb.5): any bytes
// either decode to a model that passed the reader's invariant check or throw fest::Error;
// nothing reads outside the input. A model that decodes is written again and must decode
// to the same sizes (the writer takes whatever the reader accepts). Both the strict read
// and the renormalising one (fix_basis) are exercised.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/error.hpp"
#include "formats/facemodel/mmb.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace fest::formats;
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  for (bool fix : {false, true}) {
    MmbReadOptions o;
    o.fix_basis = fix;
    try {
      const fest::face::Model m = parse_mmb(bytes, o);
      double sum = 0;  // touch every basis value: the reader vouched for n x k of them
      for (std::size_t c = 0; c < m.components; ++c)
        for (std::size_t r = 0; r < m.n(); ++r) sum += m.basis_at(r, c);
      (void)sum;
      const fest::face::Model again = parse_mmb(write_mmb(m), o);
      if (again.points != m.points || again.components != m.components || again.triangles != m.triangles ||
          again.eval_mask != m.eval_mask || again.landmarks != m.landmarks)
        std::abort();
    } catch (const fest::Error&) {
    }
  }
  return 0;
}

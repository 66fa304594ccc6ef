#pragma once
// What the processor can run, asked once: the one place where code with a hand-vectorised
// path (lib/sampling's filters, lib/wavelet's lifting and packed slabs) learns whether AVX2 is there. A
// function-local static, so that the answer is ready whenever it is first asked, even
// from another translation unit's static initialiser.

namespace fest {

inline bool cpu_has_avx2() noexcept {
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool has = [] {
    __builtin_cpu_init();  // needed when asked before the constructors have run
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return has;
#else
  return false;
#endif
}

}  // namespace fest

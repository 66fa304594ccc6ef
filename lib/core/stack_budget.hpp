#pragma once
// How deep a recursive interpreter may go on the calling thread's stack.
//
// segbrain's prover and patnet's PaT-Lisp evaluator recurse in C++ once per goal or call.
// A fixed depth limit is right for a Release build with an 8 MiB stack and wrong for a
// smaller thread stack or a sanitizer build (AddressSanitizer's frames are several times
// larger), so both also measure the stack they have used and stop with a message before
// the guard page turns the recursion into SIGSEGV.

#include <cstddef>

namespace fest {

// Bytes of the calling thread's stack an interpreter may use below the frame where it was
// entered: the stack's size less a reserve for the code it calls (an eighth, at least
// 1 MiB; half of a stack under 2 MiB); 4 MiB where the size cannot be read.
std::ptrdiff_t usable_stack_bytes();

// The stack position of the function this is inlined into.
[[gnu::always_inline]] inline const char* stack_position() {
  return static_cast<const char*>(__builtin_frame_address(0));
}

// Arm at the interpreter's outermost entry, then ask at every nested entry. The stack
// grows downwards on every platform fest builds for.
class StackBudget {
 public:
  void arm(const char* entry) {
    base_ = entry;
    budget_ = usable_stack_bytes();
  }
  bool exhausted(const char* here) const { return base_ - here > budget_; }
  std::ptrdiff_t budget_bytes() const { return budget_; }

 private:
  const char* base_ = nullptr;
  std::ptrdiff_t budget_ = 0;
};

}  // namespace fest

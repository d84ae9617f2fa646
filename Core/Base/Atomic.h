#pragma once
// The atomics the solvers need: setting bits of a shared word from many
// threads (the result is the same in any order), and claiming room in a
// shared area (PairListsBuild.h: which thread gets which part may change
// from run to run, what each writes there does not).
#include <cstdint>

#include "Base/HostDevice.h"

namespace soak {

SOAK_INLINE void atomicSetBits(std::uint32_t* word, std::uint32_t bits) {
#if defined(__CUDA_ARCH__)
  atomicOr(word, bits);
#else
  __atomic_fetch_or(word, bits, __ATOMIC_RELAXED);
#endif
}

// Adds v to *counter and returns the value before.
SOAK_INLINE int atomicAddInt(int* counter, int v) {
#if defined(__CUDA_ARCH__)
  return atomicAdd(counter, v);
#else
  return __atomic_fetch_add(counter, v, __ATOMIC_RELAXED);
#endif
}

}  // namespace soak

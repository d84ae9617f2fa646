#pragma once
// The one atomic the solvers need: setting bits of a shared word from many
// threads (the result is the same in any order).
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

}  // namespace soak

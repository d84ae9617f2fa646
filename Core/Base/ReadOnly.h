#pragma once
// loadReadOnly(p): *p for data no thread writes during the kernel (a cloth's
// constraints, rest lengths, stiffnesses). On the GPU it goes through the
// read-only data path (ld.global.nc), which may keep the data in the SM's
// cache across the grid barriers of a coloured solve (Backend/
// ForEachPhased.h): the cloth constraints read the same data in every
// iteration (about 2 % off fig9b's cloth solve on an H100, Doc/
// performance.md). Elsewhere it is a plain load. T is 4, 8 or 16 bytes and aligned to its size.
#include <cstring>

#include "Base/HostDevice.h"

namespace soak {

template <class T>
SOAK_INLINE T loadReadOnly(const T* p) {
#if defined(__CUDA_ARCH__)
  static_assert(sizeof(T) == 4 || sizeof(T) == 8 || sizeof(T) == 16, "loadReadOnly: 4, 8 or 16 bytes");
  static_assert(alignof(T) == sizeof(T), "loadReadOnly: the type must be aligned to its size");
  T value;
  if constexpr (sizeof(T) == 4) {
    const int raw = __ldg(reinterpret_cast<const int*>(p));
    memcpy(&value, &raw, 4);
  } else if constexpr (sizeof(T) == 8) {
    const int2 raw = __ldg(reinterpret_cast<const int2*>(p));
    memcpy(&value, &raw, 8);
  } else {
    const int4 raw = __ldg(reinterpret_cast<const int4*>(p));
    memcpy(&value, &raw, 16);
  }
  return value;
#else
  return *p;
#endif
}

}  // namespace soak

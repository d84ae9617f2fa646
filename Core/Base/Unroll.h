#pragma once
// SOAK_UNROLL: unrolls the loop that follows in device code (the host
// compiler does not know the pragma).
#if defined(__CUDA_ARCH__)
#define SOAK_UNROLL _Pragma("unroll")
#else
#define SOAK_UNROLL
#endif

#pragma once
// SOAK_HD marks functions that run on the CPU and, when compiled by nvcc, on
// the GPU too. Public headers include only this, never CUDA headers, so the
// API compiles with a plain C++ compiler.
#if defined(__CUDACC__)
#define SOAK_HD __host__ __device__
#define SOAK_INLINE __host__ __device__ __forceinline__
#define SOAK_LAMBDA [=] __host__ __device__
#else
#define SOAK_HD
#define SOAK_INLINE inline
#define SOAK_LAMBDA [=]
#endif

#pragma once
// forEach(device, n, f): calls f(i) for i in [0, n) on the chosen device.
//
// The same call site runs an OpenMP loop on the CPU and a kernel on the GPU,
// which is how physics is written once ("one source, two machines"). A file
// that calls forEach with Device::Cuda must be compiled by nvcc: list it with
// soak_physics_sources() in CMake. f must only write to index i (or to
// disjoint places) so that results do not depend on thread count or order.
#include <stdexcept>

#include "Backend/Device.h"
#include "Base/HostDevice.h"
#include "Base/Lanes.h"

namespace soak {

#if defined(__CUDACC__)
template <class F>
__global__ void soakForEachKernel(int n, F f) {
  int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < n) f(i);
}
#endif

constexpr int kForEachBlockSize = 256;

template <class F>
void forEach(Device device, int n, F f, const char* what = "forEach") {
  if (n <= 0) return;
  countLaunch();
  if (device == Device::Cuda) {
#if defined(__CUDACC__)
    int blocks = (n + kForEachBlockSize - 1) / kForEachBlockSize;
    soakForEachKernel<<<blocks, kForEachBlockSize>>>(n, f);
    checkLastLaunch(device, what);
#else
    (void)f;
    throw std::logic_error(std::string(what) +
                           ": this translation unit was not compiled for CUDA (use soak_physics_sources)");
#endif
  } else {
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; ++i) f(i);
  }
}

// forEachLanes(device, n, f): calls f(i, lanes) for i in [0, n), with a
// group of lanes per i on the GPU (Base/Lanes.h) and one on the CPU. For
// passes whose time is a loop over neighbours. The group is as wide as it
// takes to put about a million threads in flight (at most 16 lanes, at
// least minLanes): on the H100, 16 lanes made the passes over a
// 14.4k-vertex cloth 2-4x faster, 4 were best over the 250k-vertex cloth of
// the 1M scale scene, and 1 for its coupling pass over all 1M particles
// (Doc/performance.md has the sweep).
// Lanes per item at least for the passes over neighbour lists (the fluid's,
// the cloth's): a group reads a list's consecutive entries together, which
// paid even at 1M particles on the H100 (fluid.solve 14.0 ms with one lane,
// 12.1 with four).
constexpr int kListLanes = 4;

// The threads a pass's lane groups aim to put in flight, unless the pass
// names its own target (the fluid's list passes and XSPH aim lower: their
// loops are short; Doc/performance.md).
constexpr int kLaneThreads = 1000000;

inline int lanesFor(int n, int minLanes = 1, int threads = kLaneThreads) {
  int lanes = minLanes;
  while (lanes < 16 && static_cast<long long>(n) * lanes < static_cast<long long>(threads)) lanes *= 2;
  return lanes;
}

#if defined(__CUDACC__)
template <class F>
__device__ __forceinline__ void soakRunLanes(int n, int shift, F& f) {
  const long long t = static_cast<long long>(blockIdx.x) * blockDim.x + threadIdx.x;
  const int i = static_cast<int>(t >> shift);
  if (i >= n) return;  // the whole group: i is the same for its lanes
  Lanes l;
  l.size = 1 << shift;
  l.index = static_cast<int>(t & (l.size - 1));
  l.mask = l.size == 32 ? 0xffffffffu : ((1u << l.size) - 1u) << ((threadIdx.x & 31u) & ~unsigned(l.size - 1));
  f(i, l);
}
template <class F>
__global__ void soakForEachLanesKernel(int n, int shift, F f) {
  soakRunLanes(n, shift, f);
}
// The same with at least minBlocks blocks resident per SM (registers capped
// to fit, __launch_bounds__).
template <int minBlocks, class F>
__global__ void __launch_bounds__(kForEachBlockSize, minBlocks) soakForEachLanesKernelBounded(int n, int shift, F f) {
  soakRunLanes(n, shift, f);
}
#endif

// minBlocksPerSm > 0: ask the compiler to fit that many blocks of
// kForEachBlockSize threads on an SM (for passes whose registers would
// otherwise cost occupancy; Doc/performance.md).
template <int minBlocksPerSm = 0, class F>
void forEachLanes(Device device, int n, F f, const char* what = "forEachLanes", int minLanes = 1,
                  int threads = kLaneThreads) {
  if (n <= 0) return;
  countLaunch();
  if (device == Device::Cuda) {
#if defined(__CUDACC__)
    static_assert(kForEachBlockSize % 32 == 0, "groups must not straddle warps");
    const int lanes = lanesFor(n, minLanes, threads);
    int shift = 0;
    while ((1 << shift) < lanes) ++shift;
    const long long launched = static_cast<long long>(n) << shift;
    const int blocks = static_cast<int>((launched + kForEachBlockSize - 1) / kForEachBlockSize);
    if constexpr (minBlocksPerSm > 0)
      soakForEachLanesKernelBounded<minBlocksPerSm><<<blocks, kForEachBlockSize>>>(n, shift, f);
    else
      soakForEachLanesKernel<<<blocks, kForEachBlockSize>>>(n, shift, f);
    checkLastLaunch(device, what);
#else
    (void)f;
    (void)minLanes;
    (void)threads;
    throw std::logic_error(std::string(what) +
                           ": this translation unit was not compiled for CUDA (use soak_physics_sources)");
#endif
  } else {
    (void)minLanes;
    (void)threads;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; ++i) f(i, Lanes{});
  }
}

}  // namespace soak

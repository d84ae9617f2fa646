#pragma once
// forEachPhased(device, phases, f): calls f(k) for every k of a list of
// phases, phase p covering [start[p], start[p + 1]), the whole list `repeat`
// times; all of one phase finishes before the next starts. This is the shape
// of a graph-coloured Gauss-Seidel solve (phases = colours, repeat =
// iterations).
//
// On the CPU each phase is an OpenMP loop, as forEach would run it. On the
// GPU the whole list is one cooperative kernel with a grid-wide barrier
// between phases, instead of one launch per phase: a cloth solve of 4
// sub-steps x 10 iterations x 27 colours was 1080 launches of about 6 us
// each, most of it launch and tail (Doc/performance.md). Where a cooperative
// launch is refused, it falls back to one launch per phase. The order of the
// work within a phase is free, as in forEach; between phases it is fixed, so
// results are the same either way.
#include <algorithm>

#include "Backend/ForEach.h"
#include "Base/Lanes.h"

#if defined(__CUDACC__)
#include <cooperative_groups.h>
#include <cuda_runtime.h>
#endif

namespace soak {

constexpr int kMaxPhases = 120;

struct PhaseList {
  int count = 0;   // phases
  int repeat = 1;  // times the whole list runs
  int start[kMaxPhases + 1] = {};
  // Appends the phase [first, end); false if the list is full.
  bool add(int first, int end) {
    if (count == kMaxPhases) return false;
    start[count] = first;
    start[count + 1] = end;
    ++count;
    return true;
  }
  int widest() const {
    int w = 0;
    for (int p = 0; p < count; ++p) w = std::max(w, start[p + 1] - start[p]);
    return w;
  }
};

#if defined(__CUDACC__)
template <class F>
__global__ void soakPhasedKernel(PhaseList phases, F f) {
  cooperative_groups::grid_group grid = cooperative_groups::this_grid();
  const int first = blockIdx.x * blockDim.x + threadIdx.x, stride = gridDim.x * blockDim.x;
  for (int r = 0; r < phases.repeat; ++r)
    for (int p = 0; p < phases.count; ++p) {
      for (int k = phases.start[p] + first; k < phases.start[p + 1]; k += stride) f(k);
      grid.sync();
    }
}
// The same with a group of 2^shift lanes per item (Base/Lanes.h): the
// group's lanes take the same k, so they stay together through the loops.
template <class F>
__global__ void soakPhasedLanesKernel(PhaseList phases, int shift, F f) {
  cooperative_groups::grid_group grid = cooperative_groups::this_grid();
  const int t = blockIdx.x * blockDim.x + threadIdx.x;
  const int first = t >> shift, stride = (gridDim.x * blockDim.x) >> shift;
  Lanes l;
  l.size = 1 << shift;
  l.index = t & (l.size - 1);
  l.mask = l.size == 32 ? 0xffffffffu : ((1u << l.size) - 1u) << ((threadIdx.x & 31u) & ~unsigned(l.size - 1));
  for (int r = 0; r < phases.repeat; ++r)
    for (int p = 0; p < phases.count; ++p) {
      for (int k = phases.start[p] + first; k < phases.start[p + 1]; k += stride) f(k, l);
      grid.sync();
    }
}

// Blocks of `kernel` that fit on the GPU at once (0 without cooperative
// launches); cached per kernel by the caller.
template <class K>
int coResidentBlocks(K kernel) {
  int perSm = 0, sms = 0, dev = 0, cooperative = 0;
  cudaGetDevice(&dev);
  cudaDeviceGetAttribute(&sms, cudaDevAttrMultiProcessorCount, dev);
  cudaDeviceGetAttribute(&cooperative, cudaDevAttrCooperativeLaunch, dev);
  cudaOccupancyMaxActiveBlocksPerMultiprocessor(&perSm, kernel, kForEachBlockSize, 0);
  return cooperative ? perSm * sms : 0;
}

// Launches `kernel(args)` as one cooperative grid of 256-thread blocks,
// enough for `threads` threads but at most maxBlocks (co-resident). False
// where there is nothing to launch or the GPU refuses; a refusal sets
// maxBlocks to 0, so later calls go straight to the caller's fallback.
// 256 threads a block: 128 was within 3 % on fig9b and fig6b, 512 and 1024
// were 12-15 % slower (H100, Doc/performance.md).
template <class K>
bool launchCooperative(K kernel, long long threads, int& maxBlocks, void** args, Device device, const char* what) {
  const int blocks =
      static_cast<int>(std::min<long long>((threads + kForEachBlockSize - 1) / kForEachBlockSize, maxBlocks));
  if (blocks <= 0) return false;
  countLaunch();
  if (cudaLaunchCooperativeKernel(reinterpret_cast<void*>(kernel), dim3(blocks), dim3(kForEachBlockSize), args, 0,
                                  nullptr) != cudaSuccess) {
    cudaGetLastError();  // clear the refusal
    maxBlocks = 0;
    return false;
  }
  checkLastLaunch(device, what);
  return true;
}
#endif

template <class F>
void forEachPhased(Device device, const PhaseList& phases, F f, const char* what = "forEachPhased") {
  if (phases.count == 0 || phases.repeat <= 0) return;
  if (device == Device::Cuda) {
#if defined(__CUDACC__)
    const int widest = phases.widest();
    if (widest == 0) return;
    static int maxBlocks = coResidentBlocks(soakPhasedKernel<F>);
    PhaseList list = phases;
    void* args[] = {static_cast<void*>(&list), static_cast<void*>(&f)};
    if (launchCooperative(soakPhasedKernel<F>, widest, maxBlocks, args, device, what)) return;
#endif
  }
  if (device == Device::Cpu) {
    // One operation, as the GPU's one cooperative launch (launches()).
    countLaunch();
    for (int r = 0; r < phases.repeat; ++r)
      for (int p = 0; p < phases.count; ++p) {
        const int first = phases.start[p], end = phases.start[p + 1];
#pragma omp parallel for schedule(static)
        for (int k = first; k < end; ++k) f(k);
      }
    return;
  }
  // The GPU without cooperative launches: one launch per phase.
  for (int r = 0; r < phases.repeat; ++r)
    for (int p = 0; p < phases.count; ++p) {
      const int first = phases.start[p];
      forEach(device, phases.start[p + 1] - first, SOAK_LAMBDA(int k) { f(first + k); }, what);
    }
}

// forEachPhasedLanes(device, phases, lanes, f): as forEachPhased, calling
// f(k, lanes) with a group of `lanes` threads per k on the GPU (a power of
// two, at most 32) and one on the CPU, for phases whose time is a loop over
// a list (Base/Lanes.h). Without cooperative launches, one launch per phase.
template <class F>
void forEachPhasedLanes(Device device, const PhaseList& phases, int lanes, F f, const char* what = "forEachPhasedLanes") {
  if (phases.count == 0 || phases.repeat <= 0) return;
  if (device == Device::Cuda) {
#if defined(__CUDACC__)
    const int widest = phases.widest();
    if (widest == 0) return;
    int shift = 0;
    while ((1 << shift) < lanes && shift < 5) ++shift;
    static int maxBlocks = coResidentBlocks(soakPhasedLanesKernel<F>);
    PhaseList list = phases;
    void* args[] = {static_cast<void*>(&list), static_cast<void*>(&shift), static_cast<void*>(&f)};
    if (launchCooperative(soakPhasedLanesKernel<F>, static_cast<long long>(widest) << shift, maxBlocks, args, device,
                          what))
      return;
    for (int r = 0; r < phases.repeat; ++r)
      for (int p = 0; p < phases.count; ++p) {
        const int first = phases.start[p];
        forEachLanes(device, phases.start[p + 1] - first, SOAK_LAMBDA(int k, Lanes l) { f(first + k, l); }, what, lanes);
      }
    return;
#else
    (void)f;
    throw std::logic_error(std::string(what) +
                           ": this translation unit was not compiled for CUDA (use soak_physics_sources)");
#endif
  }
  (void)lanes;
  countLaunch();
  for (int r = 0; r < phases.repeat; ++r)
    for (int p = 0; p < phases.count; ++p) {
      const int first = phases.start[p], end = phases.start[p + 1];
#pragma omp parallel for schedule(static)
      for (int k = first; k < end; ++k) f(k, Lanes{});
    }
}

}  // namespace soak

#pragma once
// forEachPhased(device, phases, state, f): calls f(k, s) for every k of a
// list of phases, phase p covering [start[p], start[p + 1]), the whole list
// `repeat` times; all of one phase finishes before the next starts. This is
// the shape of a graph-coloured Gauss-Seidel solve (phases = colours, repeat =
// iterations). The phases read and write one array of Float4 (`state`, the
// cloth's positions) through s.load(v) and s.store(v, x) only.
//
// On the CPU each phase is an OpenMP loop, as forEach would run it. On the
// GPU there are two kernels, both one launch for the whole list:
//
// - a thread-block cluster (sm_90: up to 16 blocks on neighbouring SMs)
//   holding the state in its distributed shared memory, with the cluster's
//   hardware barrier between phases, when the state fits (up to 8192 entries
//   a block) and the device can run such a cluster;
// - else a cooperative kernel over the whole GPU with a grid-wide barrier
//   between phases and the state in global memory. A cloth solve of 4
//   sub-steps x 10 iterations x 27 colours was 1080 launches of about 6 us
//   each before it (Doc/performance.md), and about 3.2 us a phase in it,
//   most of it the grid barrier and the loads through L2 behind it.
//
// Where neither launch is possible it falls back to one launch per phase. The
// order of the work within a phase is free, as in forEach; between phases it
// is fixed, so results are the same on every path.
#include <algorithm>

#include "Backend/ForEach.h"
#include "Base/Vec3.h"

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

// How a phase sees the state. In the cluster kernel entry v lives in the
// shared memory of the cluster's block v >> shift, at v & (2^shift - 1).
struct PhasedState {
  Float4* global = nullptr;  // the array (CPU, cooperative kernel, per-phase launches)
  Float4* local = nullptr;   // cluster kernel: this block's part in shared memory
  int shift = 0;             // cluster kernel: entries per block = 2^shift

#if defined(__CUDA_ARCH__) && __CUDA_ARCH__ >= 900
  __device__ __forceinline__ Float4* clusterSlot(int v) const {
    return cooperative_groups::this_cluster().map_shared_rank(local, static_cast<unsigned>(v >> shift)) +
           (v & ((1 << shift) - 1));
  }
#endif
  SOAK_INLINE Float4 load(int v) const {
#if defined(__CUDA_ARCH__) && __CUDA_ARCH__ >= 900
    if (local) return *clusterSlot(v);
#endif
    return global[v];
  }
  SOAK_INLINE void store(int v, const Float4& x) const {
#if defined(__CUDA_ARCH__) && __CUDA_ARCH__ >= 900
    if (local) {
      *clusterSlot(v) = x;
      return;
    }
#endif
    global[v] = x;
  }
};

// Which GPU kernel forEachPhased may use (set by benchmarks and tests;
// defined in Device.cpp). clusterBlocks: 0 never uses the cluster kernel,
// -1 picks the largest cluster the device runs (16, else 8, ...), else that
// many blocks; clusterThreads: threads a block (0: the largest that runs).
struct PhasedLaunchPolicy {
  int clusterBlocks = -1;
  int clusterThreads = 0;
  // What the last GPU launch used: its cluster's blocks and threads a block
  // (0 and 0: the cooperative kernel or per-phase launches).
  int lastClusterBlocks = 0;
  int lastClusterThreads = 0;
};
PhasedLaunchPolicy& phasedLaunchPolicy();

// Entries of state one block of the cluster kernel holds at most (128 KiB).
constexpr int kMaxClusterEntriesPerBlock = 8192;

#if defined(__CUDACC__)
template <class F>
__global__ void soakPhasedKernel(PhaseList phases, Float4* state, F f) {
  cooperative_groups::grid_group grid = cooperative_groups::this_grid();
  PhasedState s;
  s.global = state;
  const int first = blockIdx.x * blockDim.x + threadIdx.x, stride = gridDim.x * blockDim.x;
  for (int r = 0; r < phases.repeat; ++r)
    for (int p = 0; p < phases.count; ++p) {
      for (int k = phases.start[p] + first; k < phases.start[p + 1]; k += stride) f(k, s);
      grid.sync();
    }
}

template <class F>
__global__ void soakPhasedClusterKernel(PhaseList phases, Float4* state, int n, int shift, F f) {
#if defined(__CUDA_ARCH__) && __CUDA_ARCH__ >= 900
  extern __shared__ float4 soakPhasedShared[];
  cooperative_groups::cluster_group cluster = cooperative_groups::this_cluster();
  const int rank = static_cast<int>(cluster.block_rank());
  PhasedState s;
  s.global = state;
  s.local = reinterpret_cast<Float4*>(soakPhasedShared);
  s.shift = shift;
  const int base = rank << shift, mine = min(1 << shift, n - base);
  for (int t = threadIdx.x; t < mine; t += blockDim.x) s.local[t] = state[base + t];
  cluster.sync();
  const int first = rank * blockDim.x + threadIdx.x, stride = static_cast<int>(cluster.num_blocks()) * blockDim.x;
  for (int r = 0; r < phases.repeat; ++r)
    for (int p = 0; p < phases.count; ++p) {
      for (int k = phases.start[p] + first; k < phases.start[p + 1]; k += stride) f(k, s);
      cluster.sync();
    }
  for (int t = threadIdx.x; t < mine; t += blockDim.x) state[base + t] = s.local[t];
#endif
}

// Launches the cluster kernel if the device, the build and the state allow;
// false if not (nothing launched).
template <class F>
bool launchPhasedCluster(const PhaseList& phases, Float4* state, int n, F f) {
  const PhasedLaunchPolicy policy = phasedLaunchPolicy();
  if (policy.clusterBlocks == 0 || n <= 0) return false;
  static int usable = -1;  // the device runs sm_90 code of this kernel
  if (usable < 0) {
    int dev = 0, major = 0;
    cudaFuncAttributes attributes{};
    cudaGetDevice(&dev);
    cudaDeviceGetAttribute(&major, cudaDevAttrComputeCapabilityMajor, dev);
    usable = major >= 9 && cudaFuncGetAttributes(&attributes, soakPhasedClusterKernel<F>) == cudaSuccess &&
             attributes.binaryVersion >= 90;
    cudaGetLastError();
  }
  if (!usable) return false;
  auto kernel = soakPhasedClusterKernel<F>;
  const int sizes[] = {16, 8, 4, 2};
  const int threadChoices[] = {1024, 512, 256};
  for (int blocks : sizes) {
    if (policy.clusterBlocks > 0 && blocks != policy.clusterBlocks) continue;
    int shift = 0;
    while ((static_cast<long long>(blocks) << shift) < n) ++shift;
    if ((1 << shift) > kMaxClusterEntriesPerBlock) return false;  // larger clusters were tried first
    const int bytes = static_cast<int>(sizeof(Float4)) << shift;
    for (int threads : threadChoices) {
      if (policy.clusterThreads > 0 && threads != policy.clusterThreads) continue;
      cudaFuncSetAttribute(kernel, cudaFuncAttributeNonPortableClusterSizeAllowed, 1);
      cudaFuncSetAttribute(kernel, cudaFuncAttributeMaxDynamicSharedMemorySize, bytes);
      cudaLaunchAttribute attribute[1];
      attribute[0].id = cudaLaunchAttributeClusterDimension;
      attribute[0].val.clusterDim.x = static_cast<unsigned>(blocks);
      attribute[0].val.clusterDim.y = 1;
      attribute[0].val.clusterDim.z = 1;
      cudaLaunchConfig_t config{};
      config.gridDim = dim3(static_cast<unsigned>(blocks));
      config.blockDim = dim3(static_cast<unsigned>(threads));
      config.dynamicSmemBytes = static_cast<std::size_t>(bytes);
      config.attrs = attribute;
      config.numAttrs = 1;
      int clusters = 0;
      if (cudaOccupancyMaxActiveClusters(&clusters, kernel, &config) != cudaSuccess || clusters < 1) {
        cudaGetLastError();
        continue;
      }
      if (cudaLaunchKernelEx(&config, kernel, phases, state, n, shift, f) == cudaSuccess) {
        phasedLaunchPolicy().lastClusterBlocks = blocks;
        phasedLaunchPolicy().lastClusterThreads = threads;
        return true;
      }
      cudaGetLastError();
    }
  }
  return false;
}
#endif

template <class F>
void forEachPhased(Device device, const PhaseList& phases, Float4* state, int stateCount, F f,
                   const char* what = "forEachPhased") {
  if (phases.count == 0 || phases.repeat <= 0) return;
  if (device == Device::Cuda) {
#if defined(__CUDACC__)
    const int widest = phases.widest();
    if (widest == 0) return;
    if (launchPhasedCluster(phases, state, stateCount, f)) {
      checkLastLaunch(device, what);
      return;
    }
    phasedLaunchPolicy().lastClusterBlocks = phasedLaunchPolicy().lastClusterThreads = 0;
    // 256 threads a block: 128 was within 3 % on fig9b and fig6b, 512 and
    // 1024 were 12-15 % slower (H100, Doc/performance.md).
    constexpr int blockSize = kForEachBlockSize;
    static int maxBlocks = -1;  // co-resident blocks of this kernel on this GPU
    if (maxBlocks < 0) {
      int perSm = 0, sms = 0, dev = 0, cooperative = 0;
      cudaGetDevice(&dev);
      cudaDeviceGetAttribute(&sms, cudaDevAttrMultiProcessorCount, dev);
      cudaDeviceGetAttribute(&cooperative, cudaDevAttrCooperativeLaunch, dev);
      cudaOccupancyMaxActiveBlocksPerMultiprocessor(&perSm, soakPhasedKernel<F>, blockSize, 0);
      maxBlocks = cooperative ? perSm * sms : 0;
    }
    const int blocks = std::min((widest + blockSize - 1) / blockSize, maxBlocks);
    if (blocks > 0) {
      PhaseList list = phases;
      void* args[] = {static_cast<void*>(&list), static_cast<void*>(&state), static_cast<void*>(&f)};
      if (cudaLaunchCooperativeKernel(reinterpret_cast<void*>(soakPhasedKernel<F>), dim3(blocks),
                                      dim3(blockSize), args, 0, nullptr) == cudaSuccess) {
        checkLastLaunch(device, what);
        return;
      }
      cudaGetLastError();  // clear the refusal; fall back below
      maxBlocks = 0;
    }
#endif
  }
  (void)stateCount;
  PhasedState s;
  s.global = state;
  for (int r = 0; r < phases.repeat; ++r)
    for (int p = 0; p < phases.count; ++p) {
      const int first = phases.start[p];
      forEach(device, phases.start[p + 1] - first, SOAK_LAMBDA(int k) { f(first + k, s); }, what);
    }
}

}  // namespace soak

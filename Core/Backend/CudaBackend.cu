// The CUDA half of the backend: memory, synchronisation, and the few
// primitives (sort, scan, reduce) that come from CUB.
#include <cuda_runtime.h>

#include <cub/cub.cuh>
#include <thrust/iterator/transform_iterator.h>
#include <cstdio>
#include <map>
#include <string>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "Backend/CudaBackend.h"
#include "Base/Error.h"

namespace soak::cuda {

namespace {
void check(cudaError_t e, const char* what) {
  if (e != cudaSuccess) throw DeviceError(std::string("CUDA error in ") + what + ": " + cudaGetErrorString(e));
}

// Scratch memory for CUB, grown on demand and kept.
struct Scratch {
  void* ptr = nullptr;
  std::size_t bytes = 0;
  void* get(std::size_t need) {
    if (need > bytes) {
      graphPause();
      if (ptr) cudaFreeAsync(ptr, 0);
      bytes = need + need / 2;
      check(cudaMallocAsync(&ptr, bytes, 0), "scratch allocation");
    }
    return ptr;
  }
};
Scratch& scratch() {
  static Scratch s;
  return s;
}
template <class T>
struct HostValue {
  T* dev = nullptr;
  HostValue() {
    graphPause();
    check(cudaMalloc(&dev, sizeof(T)), "result allocation");
  }
  ~HostValue() { cudaFree(dev); }
  T read() {
    T v{};
    check(cudaMemcpy(&v, dev, sizeof(T), cudaMemcpyDeviceToHost), "reading a reduction");
    return v;
  }
};
__global__ void writeFloat(float* out, float v) { *out = v; }
struct MaxOp {
  __device__ float operator()(float a, float b) const { return a > b ? a : b; }
};
struct MinOp {
  __device__ float operator()(float a, float b) const { return a < b ? a : b; }
};
struct ToDouble {
  __device__ double operator()(float a) const { return double(a); }
};
}  // namespace

bool built() { return true; }

bool available(std::string* why) {
  int count = 0;
  cudaError_t e = cudaGetDeviceCount(&count);
  if (e != cudaSuccess || count == 0) {
    if (why) *why = std::string("no usable CUDA GPU on this machine (") +
                    (e != cudaSuccess ? cudaGetErrorString(e) : "0 devices") + ")";
    cudaGetLastError();
    return false;
  }
  return true;
}

std::string description() {
  int dev = 0;
  cudaDeviceProp p{};
  if (cudaGetDevice(&dev) != cudaSuccess || cudaGetDeviceProperties(&p, dev) != cudaSuccess) return {};
  return std::string(p.name) + " (sm_" + std::to_string(p.major) + std::to_string(p.minor) + ", " +
         std::to_string(p.multiProcessorCount) + " SMs, " + std::to_string(p.totalGlobalMem >> 20) + " MiB)";
}

std::size_t memoryBytes() {
  std::size_t free = 0, total = 0;
  return cudaMemGetInfo(&free, &total) == cudaSuccess ? total : 0;
}
std::size_t freeMemoryBytes() {
  std::size_t free = 0, total = 0;
  return cudaMemGetInfo(&free, &total) == cudaSuccess ? free : 0;
}

// Step graphs (CudaBackend.h): the stepping thread's captures. Each
// segment of a step (the work between two host waits) is captured, and the
// executable graph kept for its place (key, segment, node count) is updated
// with the new capture's parameters; one that cannot be updated (another
// shape: a sub-step more) is instantiated anew.
namespace {
struct StepGraphs {
  bool active = false, capturing = false;
  int key = 0, segment = 0, holds = 0;
  // Inside a device loop: the step's graph (its capture ended where the
  // loop node went in) and the loop's node and condition.
  bool inLoop = false;
  cudaGraph_t outer = nullptr;
  cudaGraphNode_t loopNode = nullptr;
  cudaGraphConditionalHandle loopCondition = 0;
  std::map<std::tuple<int, int, std::size_t>, cudaGraphExec_t> execs;
  StepGraphCounters counters;
};
StepGraphs& stepGraphs() {
  thread_local StepGraphs g;  // a step is captured on the thread that runs it
  return g;
}
constexpr std::size_t kMostKeptGraphs = 64;
}  // namespace

void graphBeginStep(int key) {
  StepGraphs& g = stepGraphs();
  g.active = true;
  g.key = key;
  g.segment = 0;
}

void graphResume() {
  StepGraphs& g = stepGraphs();
  if (!g.active || g.capturing || g.holds > 0) return;
  check(cudaStreamBeginCapture(cudaStreamPerThread, cudaStreamCaptureModeThreadLocal), "beginning a step graph");
  g.capturing = true;
}

void graphPause() {
  StepGraphs& g = stepGraphs();
  if (!g.capturing) return;
  if (g.inLoop) throw std::logic_error("a device loop's body waited for the host, allocated or copied to the host");
  g.capturing = false;
  cudaGraph_t graph = nullptr;
  check(cudaStreamEndCapture(cudaStreamPerThread, &graph), "capturing a step graph");
  std::size_t nodes = 0;
  cudaGraphGetNodes(graph, nullptr, &nodes);
  if (nodes == 0) {
    cudaGraphDestroy(graph);
    return;
  }
  const auto place = std::make_tuple(g.key, g.segment++, nodes);
  auto it = g.execs.find(place);
  bool updated = false;
  if (it != g.execs.end()) {
    cudaGraphExecUpdateResultInfo info{};
    updated = cudaGraphExecUpdate(it->second, graph, &info) == cudaSuccess;
    if (!updated) {
      cudaGetLastError();
      cudaGraphExecDestroy(it->second);
      g.execs.erase(it);
    }
  }
  if (updated) {
    ++g.counters.updates;
  } else {
    if (g.execs.size() >= kMostKeptGraphs) {
      for (auto& e : g.execs) cudaGraphExecDestroy(e.second);
      g.execs.clear();
    }
    cudaGraphExec_t exec = nullptr;
    const cudaError_t e = cudaGraphInstantiate(&exec, graph, 0);
    if (e != cudaSuccess) cudaGraphDestroy(graph);
    check(e, "instantiating a step graph");
    it = g.execs.emplace(place, exec).first;
    ++g.counters.instantiations;
  }
  cudaGraphDestroy(graph);
  g.counters.nodes += nodes;
  ++g.counters.launches;
  check(cudaGraphLaunch(it->second, cudaStreamPerThread), "launching a step graph");
}

void graphEndStep() {
  StepGraphs& g = stepGraphs();
  g.holds = 0;
  graphPause();
  g.active = false;
}

void graphAbandonStep() noexcept {
  StepGraphs& g = stepGraphs();
  if (g.capturing) {
    cudaGraph_t graph = nullptr;
    cudaStreamEndCapture(cudaStreamPerThread, &graph);
    // A loop's body belongs to its node, which belongs to the step's graph.
    if (g.inLoop && g.outer) graph = g.outer;
    if (graph) cudaGraphDestroy(graph);
    cudaGetLastError();
  }
  g.inLoop = false;
  g.outer = nullptr;
  g.capturing = false;
  g.active = false;
  g.holds = 0;
}

void graphHold(bool hold) {
  StepGraphs& g = stepGraphs();
  if (hold) {
    graphPause();
    ++g.holds;
  } else if (g.holds > 0) {
    --g.holds;
  }
}

StepGraphCounters graphCounters() { return stepGraphs().counters; }

// Device loops in a step graph: the capture so far ends, a conditional
// WHILE node goes in after its last work, the body is captured into the
// node's graph, and the capture of the step's graph goes on after the node.
// The condition starts at 1 every launch (cudaGraphCondAssignDefault): a
// loop runs its body at least once.
namespace {
__global__ void advanceLoop(int* index, const int* count, cudaGraphConditionalHandle condition, int inLoopNode) {
  const int next = *index + 1;
  *index = next;
  if (inLoopNode) cudaGraphSetConditional(condition, next < *count ? 1u : 0u);
}
}  // namespace

bool graphLoopBegin() {
  StepGraphs& g = stepGraphs();
  if (g.inLoop) throw std::logic_error("device loops do not nest");
  graphResume();
  if (!g.capturing) return false;
  cudaStreamCaptureStatus status = cudaStreamCaptureStatusNone;
  cudaGraph_t graph = nullptr;
  const cudaGraphNode_t* leaves = nullptr;
  std::size_t leafCount = 0;
  check(cudaStreamGetCaptureInfo(cudaStreamPerThread, &status, nullptr, &graph, &leaves, nullptr, &leafCount),
        "reading a step graph's capture");
  const std::vector<cudaGraphNode_t> after(leaves, leaves + leafCount);
  check(cudaStreamEndCapture(cudaStreamPerThread, &g.outer), "capturing a step graph before a device loop");
  check(cudaGraphConditionalHandleCreate(&g.loopCondition, g.outer, 1, cudaGraphCondAssignDefault),
        "creating a device loop's condition");
  cudaGraphNodeParams params{};
  params.type = cudaGraphNodeTypeConditional;
  params.conditional.handle = g.loopCondition;
  params.conditional.type = cudaGraphCondTypeWhile;
  params.conditional.size = 1;
  check(cudaGraphAddNode(&g.loopNode, g.outer, after.data(), nullptr, after.size(), &params),
        "adding a device loop to a step graph");
  check(cudaStreamBeginCaptureToGraph(cudaStreamPerThread, params.conditional.phGraph_out[0], nullptr, nullptr, 0,
                                      cudaStreamCaptureModeThreadLocal),
        "capturing a device loop's body");
  g.inLoop = true;
  return true;
}

void graphLoopAdvance(int* index, const int* count) {
  StepGraphs& g = stepGraphs();
  advanceLoop<<<1, 1>>>(index, count, g.inLoop ? g.loopCondition : 0, g.inLoop ? 1 : 0);
  check(cudaGetLastError(), "advancing a device loop");
}

void graphLoopEnd() {
  StepGraphs& g = stepGraphs();
  if (!g.inLoop) return;
  cudaGraph_t body = nullptr;
  check(cudaStreamEndCapture(cudaStreamPerThread, &body), "capturing a device loop's body");
  g.inLoop = false;
  check(cudaStreamBeginCaptureToGraph(cudaStreamPerThread, g.outer, &g.loopNode, nullptr, 1,
                                      cudaStreamCaptureModeThreadLocal),
        "resuming a step graph after a device loop");
  g.outer = nullptr;
}

void synchronize() {
  graphPause();
  check(cudaDeviceSynchronize(), "synchronize");
}

// Stream-ordered allocation (cudaMallocAsync on the default stream, where
// all our work runs): freeing a buffer that grew does not wait for the
// device as cudaFree does, so a step that grows a buffer still never waits.
// The pool keeps what is freed instead of returning it at every wait.
void* allocate(std::size_t bytes) {
  static const bool poolKept = [] {
    int dev = 0;
    cudaMemPool_t pool;
    if (cudaGetDevice(&dev) == cudaSuccess && cudaDeviceGetDefaultMemPool(&pool, dev) == cudaSuccess) {
      unsigned long long keep = ~0ull;
      cudaMemPoolSetAttribute(pool, cudaMemPoolAttrReleaseThreshold, &keep);
    }
    cudaGetLastError();
    return true;
  }();
  (void)poolKept;
  graphPause();
  void* p = nullptr;
  cudaError_t e = cudaMallocAsync(&p, bytes, 0);
  if (e != cudaSuccess) {
    cudaGetLastError();
    char b[160];
    std::snprintf(b, sizeof(b), "GPU out of memory allocating %.3g MiB (%s); the GPU has %.3g MiB free of %.3g MiB",
                  double(bytes) / 1048576.0, cudaGetErrorString(e), double(freeMemoryBytes()) / 1048576.0,
                  double(memoryBytes()) / 1048576.0);
    throw DeviceError(b);
  }
  return p;
}
void release(void* p) noexcept {
  try {
    graphPause();
  } catch (...) {
  }
  cudaFreeAsync(p, 0);
}

// Copies between device buffers and fills are stream-ordered (no wait), so
// a step graph captures them; copies from or to the host wait.
void copy(void* dst, const void* src, std::size_t bytes, int kind) {
  if (kind == 2) {
    check(cudaMemcpyAsync(dst, src, bytes, cudaMemcpyDeviceToDevice, 0), "memory copy");
    return;
  }
  graphPause();
  cudaMemcpyKind k = kind == 0 ? cudaMemcpyHostToDevice : cudaMemcpyDeviceToHost;
  check(cudaMemcpy(dst, src, bytes, k), "memory copy");
}
void fill(void* dst, int value, std::size_t bytes) { check(cudaMemsetAsync(dst, value, bytes, 0), "memset"); }
void checkLaunch(const char* what) { check(cudaGetLastError(), what); }

double reduceSum(const float* x, int n) {
  if (n <= 0) return 0.0;
  HostValue<double> out;
  thrust::transform_iterator<ToDouble, const float*, double> in(x, ToDouble{});
  std::size_t bytes = 0;
  cub::DeviceReduce::Sum(nullptr, bytes, in, out.dev, n);
  check(cub::DeviceReduce::Sum(scratch().get(bytes), bytes, in, out.dev, n), "reduceSum");
  return out.read();
}
float reduceMax(const float* x, int n) {
  if (n <= 0) return -3.0e38f;  // the identity, as on the CPU
  HostValue<float> out;
  std::size_t bytes = 0;
  cub::DeviceReduce::Reduce(nullptr, bytes, x, out.dev, n, MaxOp{}, -3.0e38f);
  check(cub::DeviceReduce::Reduce(scratch().get(bytes), bytes, x, out.dev, n, MaxOp{}, -3.0e38f), "reduceMax");
  return out.read();
}
void reduceMaxInto(const float* x, int n, float* out) {
  if (n <= 0) {
    writeFloat<<<1, 1>>>(out, -3.0e38f);  // a kernel, not a copy from the stack: graphs replay it
    check(cudaGetLastError(), "reduceMaxInto");
    return;
  }
  std::size_t bytes = 0;
  cub::DeviceReduce::Reduce(nullptr, bytes, x, out, n, MaxOp{}, -3.0e38f);
  check(cub::DeviceReduce::Reduce(scratch().get(bytes), bytes, x, out, n, MaxOp{}, -3.0e38f), "reduceMaxInto");
}
float reduceMin(const float* x, int n) {
  if (n <= 0) return 3.0e38f;
  HostValue<float> out;
  std::size_t bytes = 0;
  cub::DeviceReduce::Reduce(nullptr, bytes, x, out.dev, n, MinOp{}, 3.0e38f);
  check(cub::DeviceReduce::Reduce(scratch().get(bytes), bytes, x, out.dev, n, MinOp{}, 3.0e38f), "reduceMin");
  return out.read();
}
int exclusiveScan(const int* in, int* out, int n) {
  if (n <= 0) return 0;
  graphPause();
  int last = 0;
  check(cudaMemcpy(&last, in + n - 1, sizeof(int), cudaMemcpyDeviceToHost), "scan");
  std::size_t bytes = 0;
  cub::DeviceScan::ExclusiveSum(nullptr, bytes, in, out, n);
  check(cub::DeviceScan::ExclusiveSum(scratch().get(bytes), bytes, in, out, n), "exclusiveScan");
  int lastOut = 0;
  check(cudaMemcpy(&lastOut, out + n - 1, sizeof(int), cudaMemcpyDeviceToHost), "scan");
  return lastOut + last;
}

void exclusiveScanAsync(const int* in, int* out, int n) {
  if (n <= 0) return;
  std::size_t bytes = 0;
  cub::DeviceScan::ExclusiveSum(nullptr, bytes, in, out, n);
  check(cub::DeviceScan::ExclusiveSum(scratch().get(bytes), bytes, in, out, n), "exclusiveScanAsync");
}

void sortPairs(std::uint32_t* keys, std::uint32_t* values, int n, int keyBits) {
  if (n <= 1) return;
  // Double buffers live in one scratch block: keys', values', then CUB's temp.
  std::size_t pairBytes = std::size_t(n) * sizeof(std::uint32_t);
  cub::DoubleBuffer<std::uint32_t> k(keys, nullptr), v(values, nullptr);
  std::size_t temp = 0;
  cub::DeviceRadixSort::SortPairs(nullptr, temp, k, v, n, 0, keyBits);
  std::size_t align = 256;
  std::size_t off1 = ((pairBytes + align - 1) / align) * align;
  char* base = static_cast<char*>(scratch().get(2 * off1 + temp));
  k.d_buffers[1] = reinterpret_cast<std::uint32_t*>(base);
  v.d_buffers[1] = reinterpret_cast<std::uint32_t*>(base + off1);
  check(cub::DeviceRadixSort::SortPairs(base + 2 * off1, temp, k, v, n, 0, keyBits), "sortPairs");
  if (k.Current() != keys) {
    check(cudaMemcpyAsync(keys, k.Current(), pairBytes, cudaMemcpyDeviceToDevice), "sortPairs copy");
    check(cudaMemcpyAsync(values, v.Current(), pairBytes, cudaMemcpyDeviceToDevice), "sortPairs copy");
  }
}

void* allocatePinned(std::size_t bytes) {
  graphPause();
  void* p = nullptr;
  cudaError_t e = cudaMallocHost(&p, bytes);
  if (e != cudaSuccess) {
    cudaGetLastError();
    throw DeviceError("out of page-locked host memory allocating " + std::to_string(bytes) + " bytes (" +
                      cudaGetErrorString(e) + ")");
  }
  return p;
}
void releasePinned(void* p) noexcept {
  if (!p) return;
  try {
    graphPause();
  } catch (...) {
  }
  cudaFreeHost(p);
}

namespace {
// The compute stream is the stepping thread's default stream (the CUDA
// sources are compiled with --default-stream per-thread, so that a step can
// be captured into a graph). The copy stream is non-blocking: it and the
// compute stream never wait for each other implicitly.
cudaStream_t stream(int which) {
  if (which == 0) return cudaStreamPerThread;
  static cudaStream_t copyStream = [] {
    cudaStream_t s = nullptr;
    check(cudaStreamCreateWithFlags(&s, cudaStreamNonBlocking), "creating the copy stream");
    return s;
  }();
  return copyStream;
}
}  // namespace

void* createFence() {
  graphPause();
  cudaEvent_t e = nullptr;
  check(cudaEventCreateWithFlags(&e, cudaEventDisableTiming), "creating a fence");
  return e;
}
void destroyFence(void* fence) noexcept {
  if (fence) cudaEventDestroy(static_cast<cudaEvent_t>(fence));
}
void recordFence(void* fence, int which) {
  check(cudaEventRecord(static_cast<cudaEvent_t>(fence), stream(which)), "recording a fence");
}
void streamWaitForFence(int which, void* fence) {
  check(cudaStreamWaitEvent(stream(which), static_cast<cudaEvent_t>(fence), 0), "waiting for a fence on a stream");
}
void hostWaitForFence(void* fence) {
  graphPause();
  check(cudaEventSynchronize(static_cast<cudaEvent_t>(fence)), "waiting for a fence");
}
void copyAsync(void* dst, const void* src, std::size_t bytes, int kind, int which) {
  cudaMemcpyKind k = kind == 0 ? cudaMemcpyHostToDevice : kind == 1 ? cudaMemcpyDeviceToHost : cudaMemcpyDeviceToDevice;
  check(cudaMemcpyAsync(dst, src, bytes, k, stream(which)), "asynchronous memory copy");
}

void* createMark() {
  graphPause();
  cudaEvent_t e = nullptr;
  check(cudaEventCreate(&e), "creating a timing event");
  return e;
}
void destroyMark(void* mark) noexcept {
  if (mark) cudaEventDestroy(static_cast<cudaEvent_t>(mark));
}
void recordMark(void* mark) { check(cudaEventRecord(static_cast<cudaEvent_t>(mark), 0), "recording a timing event"); }
double markElapsedMs(void* from, void* to) {
  check(cudaEventSynchronize(static_cast<cudaEvent_t>(to)), "waiting for a timing event");
  float ms = 0.f;
  check(cudaEventElapsedTime(&ms, static_cast<cudaEvent_t>(from), static_cast<cudaEvent_t>(to)), "timing events");
  return double(ms);
}

}  // namespace soak::cuda

#pragma once
// Internal: the CUDA half of the backend. Implemented in CudaBackend.cu when
// the CUDA backend is built, and by CudaBackendStub.cpp (which refuses every
// call) otherwise. Nothing here exposes CUDA types.
#include <cstddef>
#include <cstdint>
#include <string>

#include "Backend/Device.h"

namespace soak::cuda {

bool built();
bool available(std::string* why);
std::string description();
// Total memory of the GPU in bytes (0 if unknown).
std::size_t memoryBytes();
// Memory of the GPU not yet allocated, in bytes (0 if unknown).
std::size_t freeMemoryBytes();
void synchronize();
void* allocate(std::size_t bytes);
void release(void* p) noexcept;
void copy(void* dst, const void* src, std::size_t bytes, int kind);  // 0 h2d, 1 d2h, 2 d2d
void fill(void* dst, int value, std::size_t bytes);
void checkLaunch(const char* what);

double reduceSum(const float* x, int n);
float reduceMax(const float* x, int n);
void reduceMaxInto(const float* x, int n, float* out);
float reduceMin(const float* x, int n);
int exclusiveScan(const int* in, int* out, int n);
void exclusiveScanAsync(const int* in, int* out, int n);
// Stable sort of (key, value) pairs by the low `keyBits` bits of key.
void sortPairs(std::uint32_t* keys, std::uint32_t* values, int n, int keyBits);

// Page-locked host memory: copies from the device into it run
// asynchronously and at full bus speed.
void* allocatePinned(std::size_t bytes);
void releasePinned(void* p) noexcept;
// Fences on a stream (CUDA events without timing). Stream 0 is the compute
// stream, where all of a step's work runs; stream 1 is the copy stream, which
// runs beside it (DownloadQueue.h).
void* createFence();
void destroyFence(void* fence) noexcept;
void recordFence(void* fence, int stream);
// `stream` waits for the fence; the host does not.
void streamWaitForFence(int stream, void* fence);
// The host waits for the fence.
void hostWaitForFence(void* fence);
// A copy queued on `stream` (kind as for copy); the host does not wait.
void copyAsync(void* dst, const void* src, std::size_t bytes, int kind, int stream);

// Step graphs: between graphBeginStep and graphEndStep, the work queued on
// the compute stream is captured into CUDA graphs and launched as one graph
// per segment, a segment ending where the host waits, allocates or copies
// (graphPause, called by those functions; graphResume, called before each
// launch, starts the next). Steps of the same `key` (plain or maintenance)
// reuse their executable graphs, updated with each capture's parameters.
// graphHold(true) pauses and keeps capture off until graphHold(false).
void graphBeginStep(int key);
void graphResume();
void graphPause();
void graphEndStep();
void graphAbandonStep() noexcept;
void graphHold(bool hold);
StepGraphCounters graphCounters();
// A loop whose rounds the device counts (DeviceLoop.h). graphLoopBegin: where
// the step is being captured, adds a conditional WHILE node to the step's
// graph and captures what follows, up to graphLoopEnd, as its body; false
// (nothing changed) where no capture is on. graphLoopAdvance queues the
// kernel that ends a round: ++*index, and inside a loop node the condition
// *index < *count for the next.
bool graphLoopBegin();
void graphLoopAdvance(int* index, const int* count);
void graphLoopEnd();

// Timing marks on the device's queue (CUDA events), for DeviceMarks.
void* createMark();
void destroyMark(void* mark) noexcept;
void recordMark(void* mark);
// Waits for `to`; milliseconds between the two marks.
double markElapsedMs(void* from, void* to);

}  // namespace soak::cuda

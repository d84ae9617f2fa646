// CPU-only build: the CUDA backend is absent and every request for it is refused.
#include "Backend/CudaBackend.h"
#include "Base/Error.h"

namespace soak::cuda {
namespace {
[[noreturn]] void refuse() {
  throw DeviceError("this is a CPU-only build of Soak (configured without the CUDA toolkit); use --device cpu");
}
}  // namespace
bool built() { return false; }
bool available(std::string* why) {
  if (why) *why = "this is a CPU-only build of Soak (configured without the CUDA toolkit)";
  return false;
}
std::string description() { return {}; }
std::size_t memoryBytes() { return 0; }
std::size_t freeMemoryBytes() { return 0; }
void graphBeginStep(int) {}
void graphResume() {}
void graphPause() {}
void graphEndStep() {}
void graphAbandonStep() noexcept {}
void graphHold(bool) {}
StepGraphCounters graphCounters() { return {}; }
bool graphLoopBegin() { return false; }
void graphLoopAdvance(int*, const int*) { refuse(); }
void graphLoopEnd() {}
void synchronize() {}
void* allocate(std::size_t) { refuse(); }
void release(void*) noexcept {}
void copy(void*, const void*, std::size_t, int) { refuse(); }
void fill(void*, int, std::size_t) { refuse(); }
void checkLaunch(const char*) {}
double reduceSum(const float*, int) { refuse(); }
float reduceMax(const float*, int) { refuse(); }
void reduceMaxInto(const float*, int, float*) { refuse(); }
float reduceMin(const float*, int) { refuse(); }
int exclusiveScan(const int*, int*, int) { refuse(); }
void exclusiveScanAsync(const int*, int*, int) { refuse(); }
void sortPairs(std::uint32_t*, std::uint32_t*, int, int) { refuse(); }
void* allocatePinned(std::size_t) { refuse(); }
void releasePinned(void*) noexcept {}
void* createFence() { refuse(); }
void destroyFence(void*) noexcept {}
void recordFence(void*, int) { refuse(); }
void streamWaitForFence(int, void*) { refuse(); }
void hostWaitForFence(void*) { refuse(); }
void copyAsync(void*, const void*, std::size_t, int, int) { refuse(); }
void* createMark() { refuse(); }
void destroyMark(void*) noexcept {}
void recordMark(void*) { refuse(); }
double markElapsedMs(void*, void*) { refuse(); }
}  // namespace soak::cuda

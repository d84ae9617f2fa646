#include "Backend/Device.h"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <unordered_map>

#include "Backend/CudaBackend.h"
#include "Backend/ProcessLimits.h"
#include "Base/Error.h"

namespace soak {

namespace {
// Sizes of live allocations, so deviceBytesInUse is exact.
std::mutex g_mutex;
std::unordered_map<const void*, std::size_t> g_sizes;
std::size_t g_bytes[2] = {0, 0};
std::atomic<unsigned long long> g_hostWaits{0};
std::atomic<unsigned long long> g_launches{0};

void remember(Device d, const void* p, std::size_t bytes) {
  std::lock_guard<std::mutex> lock(g_mutex);
  g_sizes[p] = bytes;
  g_bytes[d == Device::Cuda] += bytes;
}
void forget(Device d, const void* p) {
  std::lock_guard<std::mutex> lock(g_mutex);
  auto it = g_sizes.find(p);
  if (it == g_sizes.end()) return;
  g_bytes[d == Device::Cuda] -= it->second;
  g_sizes.erase(it);
}
}  // namespace

const char* deviceName(Device d) { return d == Device::Cuda ? "cuda" : "cpu"; }

bool cudaBackendBuilt() { return cuda::built(); }
bool cudaDeviceAvailable(std::string* why) { return cuda::available(why); }
std::string cudaDeviceDescription() { return cuda::built() ? cuda::description() : std::string(); }

Device resolveDevice(const std::string& request) {
  if (request == "cpu") return Device::Cpu;
  if (request == "cuda") {
    std::string why;
    if (!cuda::available(&why)) throw DeviceError("--device cuda: " + why);
    return Device::Cuda;
  }
  if (request == "auto") return cuda::available(nullptr) ? Device::Cuda : Device::Cpu;
  throw InputError("unknown device '" + request + "' (allowed: auto, cpu, cuda)");
}

unsigned long long hostWaits() { return g_hostWaits.load(); }
void countHostWait() {
  ++g_hostWaits;
  cuda::graphPause();  // a step graph's segment ends where the host waits
}
unsigned long long launches() { return g_launches.load(std::memory_order_relaxed); }
void countLaunch() {
  g_launches.fetch_add(1, std::memory_order_relaxed);
  cuda::graphResume();  // inside a step graph, the launch is captured
}

void cudaGraphBeginStep(int key) { cuda::graphBeginStep(key); }
void cudaGraphEndStep() { cuda::graphEndStep(); }
void cudaGraphAbandonStep() noexcept { cuda::graphAbandonStep(); }
StepGraphCounters stepGraphCounters() { return cuda::graphCounters(); }

bool beginDeviceLoop(Device d) { return d == Device::Cuda && cuda::graphLoopBegin(); }
void advanceDeviceLoop(Device d, int* index, const int* count) {
  countLaunch();
  if (d == Device::Cuda) {
    cuda::graphLoopAdvance(index, count);
  } else {
    ++*index;
  }
}
void endDeviceLoop(Device d) {
  if (d == Device::Cuda) cuda::graphLoopEnd();
}

void synchronize(Device d) {
  countHostWait();
  if (d == Device::Cuda) cuda::synchronize();
}

std::size_t deviceMemoryBytes(Device d) {
  if (d == Device::Cuda) return cuda::memoryBytes();
  const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && pageSize > 0 ? std::size_t(pages) * std::size_t(pageSize) : 0;
}

MemoryBound deviceMemoryBudget(Device d) {
  if (d == Device::Cpu) return smallestBound(hostMemoryBounds());
  std::vector<MemoryBound> bounds;
  const std::size_t free = cuda::freeMemoryBytes();
  if (free > 0) bounds.push_back({double(free), "the GPU's free memory"});
  const double env = memoryLimitFromEnvironment();
  if (env >= 0.0) bounds.push_back({env, "SOAK_MEMORY_LIMIT"});
  return smallestBound(bounds);
}

void* deviceAllocate(Device d, std::size_t bytes) {
  if (bytes == 0) bytes = 1;
  const double cap = memoryLimitFromEnvironment();
  if (cap >= 0.0 && double(deviceBytesInUse(d)) + double(bytes) > cap) {
    char b[200];
    std::snprintf(b, sizeof(b),
                  "allocating %.3g MiB on the %s would take the run's arrays to %.3g MiB, past SOAK_MEMORY_LIMIT "
                  "(%.3g MiB)",
                  double(bytes) / 1048576.0, d == Device::Cuda ? "GPU" : "host",
                  (double(deviceBytesInUse(d)) + double(bytes)) / 1048576.0, cap / 1048576.0);
    throw DeviceError(b);
  }
  void* p = nullptr;
  if (d == Device::Cuda) {
    p = cuda::allocate(bytes);
  } else {
    p = std::aligned_alloc(64, ((bytes + 63) / 64) * 64);
    if (!p) throw DeviceError("out of host memory allocating " + std::to_string(bytes) + " bytes");
  }
  remember(d, p, bytes);
  return p;
}

void deviceFree(Device d, void* p) noexcept {
  if (!p) return;
  forget(d, p);
  if (d == Device::Cuda) cuda::release(p);
  else std::free(p);
}

std::size_t deviceBytesInUse(Device d) {
  std::lock_guard<std::mutex> lock(g_mutex);
  return g_bytes[d == Device::Cuda];
}

void copyHostToDevice(Device d, void* dst, const void* src, std::size_t bytes) {
  countHostWait();
  if (d == Device::Cuda) cuda::copy(dst, src, bytes, 0);
  else std::memcpy(dst, src, bytes);
}
void copyDeviceToHost(Device d, void* dst, const void* src, std::size_t bytes) {
  countHostWait();
  if (d == Device::Cuda) cuda::copy(dst, src, bytes, 1);
  else std::memcpy(dst, src, bytes);
}
void copyDeviceToDevice(Device d, void* dst, const void* src, std::size_t bytes) {
  countLaunch();
  if (d == Device::Cuda) cuda::copy(dst, src, bytes, 2);
  else std::memmove(dst, src, bytes);
}
void fillBytes(Device d, void* dst, int value, std::size_t bytes) {
  countLaunch();
  if (d == Device::Cuda) cuda::fill(dst, value, bytes);
  else std::memset(dst, value, bytes);
}
void checkLastLaunch(Device d, const char* what) {
  if (d == Device::Cuda) cuda::checkLaunch(what);
}

}  // namespace soak

#pragma once
#include <cstddef>
#include <string>

#include "Backend/ProcessLimits.h"

namespace soak {

// Where physics runs. Chosen at run time (--device auto|cpu|cuda).
enum class Device { Cpu, Cuda };

const char* deviceName(Device d);

// True when this build has the CUDA backend compiled in.
bool cudaBackendBuilt();
// True when the CUDA backend is built and a usable GPU is present. When it is
// not, `why` (if given) says why in one line.
bool cudaDeviceAvailable(std::string* why = nullptr);
// Human-readable name of the GPU (empty without one).
std::string cudaDeviceDescription();

// "auto" -> Cuda if available else Cpu; "cpu"; "cuda" (DeviceError if unavailable).
Device resolveDevice(const std::string& request);

// Waits for all queued device work (no-op on CPU).
void synchronize(Device d);

// How many times the host has waited for the device so far: synchronize,
// copies to or from host memory, and the primitives that return a value
// (reductions, exclusiveScan). Device memory is allocated and freed in
// stream order (no wait: CudaBackend.cu). Counted on
// both devices, so that a CPU test can check that a step never waits
// (Simulation::step between maintenance steps; Doc/design.md).
unsigned long long hostWaits();
void countHostWait();

// How many operations the host has put on the device's queue so far: one
// per forEach, forEachLanes or forEachPhased call (one kernel on the GPU),
// per device-to-device copy or fill, and per primitive (a CUB sort or scan
// is 2-5 kernels; counted as one). Counted on both devices; soak-bench
// prints it per step, the measure of what launch costs weigh.
unsigned long long launches();
void countLaunch();

// Raw memory on a device. Errors throw DeviceError, and so does a request
// that would take the run's arrays past SOAK_MEMORY_LIMIT.
void* deviceAllocate(Device d, std::size_t bytes);
void deviceFree(Device d, void* p) noexcept;
void copyHostToDevice(Device d, void* dst, const void* src, std::size_t bytes);
void copyDeviceToHost(Device d, void* dst, const void* src, std::size_t bytes);
void copyDeviceToDevice(Device d, void* dst, const void* src, std::size_t bytes);
void fillBytes(Device d, void* dst, int value, std::size_t bytes);

// Total memory of the device in bytes: the GPU's, or the machine's RAM for
// the CPU (0 if unknown).
std::size_t deviceMemoryBytes(Device d);
// What a run's arrays may take on the device, and what says so: on the CPU
// the smallest of the machine's memory and this process's limits
// (ProcessLimits.h), on the GPU its free memory; SOAK_MEMORY_LIMIT caps both.
// bytes < 0 when nothing is known.
MemoryBound deviceMemoryBudget(Device d);
// Bytes of device memory currently allocated through deviceAllocate (per device).
std::size_t deviceBytesInUse(Device d);

// Step graphs (GPU; CudaBackend.h): between begin and end, the kernels a
// step queues are captured into CUDA graphs, one per stretch of work between
// two host waits, and replayed; `key` keeps plain (0) and maintenance (1)
// steps' graphs apart. abandon ends a capture an exception left open. The
// counters: graphs launched, updated in place, instantiated, and their nodes.
void cudaGraphBeginStep(int key);
void cudaGraphEndStep();
void cudaGraphAbandonStep() noexcept;
struct StepGraphCounters {
  unsigned long long launches = 0, updates = 0, instantiations = 0, nodes = 0;
};
StepGraphCounters stepGraphCounters();

// The pieces of repeatOnDevice (DeviceLoop.h): begin is true where the
// rounds stay on the device (a step graph being captured on the GPU).
bool beginDeviceLoop(Device d);
void advanceDeviceLoop(Device d, int* index, const int* count);
void endDeviceLoop(Device d);

// Throws DeviceError naming `what` if the last kernel launch failed (CUDA only).
void checkLastLaunch(Device d, const char* what);

}  // namespace soak

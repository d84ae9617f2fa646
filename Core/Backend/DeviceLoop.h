#pragma once
// repeatOnDevice(device, index, count, known, body): body's work *count times,
// where *count (device memory) is written by work already queued, so that
// the host need not know it.
//
// Inside a step graph on the GPU (CudaBackend.h) the rounds are a CUDA
// conditional WHILE node: body() is captured once, and the device runs it
// round after round, without a host wait. Elsewhere (the CPU, a GPU step
// run stage by stage) the host queues the rounds: `known` of them where
// the caller knows the count (> 0), else as many as it reads from *count,
// a wait on the GPU. Either way *index is the round under way (it must be 0 when
// the first starts: the work that writes *count sets it) for the body's
// kernels to read, and advances after each round. *count must be at least
// 1: a loop node runs its body once before it reads the condition.
// countMayChange: the body may set *index and *count back (a redo of the
// rounds, Cloth/StrainRedo.h); where the host queues the rounds it then
// reads both again after the last it knew of (a second wait on the GPU).
// The body may only queue work on the device: a host wait, an allocation
// or a copy to the host inside a loop node is a logic_error.
#include "Backend/Device.h"

namespace soak {

// Returns the rounds where the host read them, -1 where they stayed on the
// device.
template <class Body>
int repeatOnDevice(Device d, int* index, const int* count, int known, Body&& body, bool countMayChange = false) {
  if (beginDeviceLoop(d)) {
    body();
    advanceDeviceLoop(d, index, count);
    endDeviceLoop(d);
    return -1;
  }
  int rounds = known;
  if (rounds <= 0) copyDeviceToHost(d, &rounds, count, sizeof(int));
  for (int r = 0; r < rounds; ++r) {
    body();
    advanceDeviceLoop(d, index, count);
    if (countMayChange && r + 1 == rounds) {
      int at[2] = {0, 0};  // *index and *count: one read where they lie side by side
      if (count == index + 1) {
        copyDeviceToHost(d, at, index, 2 * sizeof(int));
      } else {
        copyDeviceToHost(d, &at[0], index, sizeof(int));
        copyDeviceToHost(d, &at[1], count, sizeof(int));
      }
      rounds = r + 1 + (at[1] > at[0] ? at[1] - at[0] : 0);
    }
  }
  return rounds;
}

}  // namespace soak

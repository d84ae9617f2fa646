#pragma once
// Turns: a counter per vertex of the updates done to it, for a coloured
// solve whose constraints wait for their own inputs instead of for a
// barrier between colours (Backend/ForEachPhased.h, forEachPhasedInTurns).
// A constraint whose turn on vertex v is t waits until v's counter reaches
// t, reads and writes v, then moves the counter past t. Each vertex then sees
// its constraints in the same order as with a barrier after every colour,
// so the results are the same bits (Cloth/ConstraintTurns.h builds the
// turns; Doc/design.md, "Cloth constraints in turns").
//
// On the GPU the wait polls the counters with relaxed loads at device scope,
// then an acquire fence makes visible what was written before the matching
// release; passing a turn is a release fence and relaxed stores. On the CPU
// the phases run one after the other, so a turn has always come when it is
// asked for; the counters are kept all the same.
#include "Base/HostDevice.h"

#if defined(__CUDACC__)
#include <cuda/atomic>
#include <cstdio>
#endif

namespace soak {

// Polls before a wait gives up (GPU): several seconds of spinning. A turn
// that never comes is a bug in the turns; the kernel then stops with an
// error instead of hanging.
constexpr long long kMaxTurnPolls = 1ll << 24;

// Waits until counter[at[a]] >= turn[a] for a in [0, n).
SOAK_INLINE void waitForTurns(const int* counter, const int* at, const int* turn, int n, int sleepNs = 0) {
#if defined(__CUDA_ARCH__)
  for (long long polls = 0;; ++polls) {
    bool come = true;
    for (int a = 0; a < n; ++a) {
      cuda::atomic_ref<int, cuda::thread_scope_device> c(const_cast<int&>(counter[at[a]]));
      come = come && c.load(cuda::memory_order_relaxed) >= turn[a];
    }
    if (come) break;
    if (sleepNs > 0) __nanosleep(sleepNs);
    if (polls == kMaxTurnPolls) {
      printf("soak: a turn never came (vertex %d, turn %d)\n", at[0], turn[0]);
      __trap();
    }
  }
  cuda::atomic_thread_fence(cuda::memory_order_acquire, cuda::thread_scope_device);
#else
  (void)counter, (void)at, (void)turn, (void)n, (void)sleepNs;
#endif
}

// Sets counter[at[a]] = next[a] for a in [0, n), after everything this
// thread wrote before.
SOAK_INLINE void passTurns(int* counter, const int* at, const int* next, int n) {
#if defined(__CUDA_ARCH__)
  cuda::atomic_thread_fence(cuda::memory_order_release, cuda::thread_scope_device);
  for (int a = 0; a < n; ++a) {
    cuda::atomic_ref<int, cuda::thread_scope_device> c(counter[at[a]]);
    c.store(next[a], cuda::memory_order_relaxed);
  }
#else
  for (int a = 0; a < n; ++a) counter[at[a]] = next[a];
#endif
}

}  // namespace soak

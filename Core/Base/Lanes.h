#pragma once
// Lanes: several GPU threads sharing one particle's neighbour loop.
//
// A pass that sums over a particle's neighbours is a chain of dependent
// loads (cell range, candidate, its position...) run by one thread. Where a
// pass has few particles (a 14.4k-vertex cloth on 132 SMs) the chain's
// latency is the pass's time: fig9b's vertex-triangle contact took 682 us a
// launch. With `Lanes`, a group of `size` adjacent threads of a warp takes
// the same particle; lane k visits the k-th, (k + size)-th... candidate of
// each cell or list, and the partial sums are combined with laneSum (a
// butterfly of warp shuffles: every lane ends with the same bits, so the
// result does not depend on which lane writes it).
//
// On the CPU (and wherever a pass is not split) a group is one lane: the loops
// then visit candidates in the order a plain loop over the cell or list
// would, with the same results. Every lane of a group must reach each laneSum/laneAny, so a pass
// may return early only on conditions that are the same for the whole group
// (those of the particle itself), and writes a per-particle result from the
// leader only.
#include "Base/HostDevice.h"
#include "Base/Vec3.h"

namespace soak {

struct Lanes {
  int index = 0;        // this thread's lane within its group
  int size = 1;         // lanes per particle (a power of two, at most 32)
  unsigned mask = 1u;   // the group's lanes within the warp (for the shuffles)
  SOAK_INLINE bool leader() const { return index == 0; }
};

// Sum over the group of a float or an int.
template <class T>
SOAK_INLINE T laneSum(const Lanes& l, T v) {
#if defined(__CUDA_ARCH__)
  for (int o = l.size / 2; o > 0; o /= 2) v += __shfl_xor_sync(l.mask, v, o, l.size);
#else
  (void)l;
#endif
  return v;
}

SOAK_INLINE Vec3 laneSum(const Lanes& l, Vec3 v) {
  return Vec3(laneSum(l, v.x), laneSum(l, v.y), laneSum(l, v.z));
}

// The group's votes as bits, lane k's vote in bit k (one lane: b, without
// a warp vote: a thread of forEach holds Lanes{}, whose mask is not its own).
SOAK_INLINE unsigned laneBallot(const Lanes& l, bool b) {
#if defined(__CUDA_ARCH__)
  if (l.size == 1) return b ? 1u : 0u;
  return (__ballot_sync(l.mask, b) & l.mask) >> (__ffs(l.mask) - 1);
#else
  (void)l;
  return b ? 1u : 0u;
#endif
}

// Votes of the lanes before this one (for ranking what a round keeps).
SOAK_INLINE int lanesBefore(const Lanes& l, unsigned votes) {
#if defined(__CUDA_ARCH__)
  return __popc(votes & ((1u << l.index) - 1u));
#else
  (void)l;
  (void)votes;
  return 0;
#endif
}

SOAK_INLINE int voteCount(unsigned votes) {
#if defined(__CUDA_ARCH__)
  return __popc(votes);
#else
  int c = 0;
  for (; votes; votes &= votes - 1u) ++c;
  return c;
#endif
}

// Whether any lane of the group passes true.
SOAK_INLINE bool laneAny(const Lanes& l, bool b) {
#if defined(__CUDA_ARCH__)
  if (l.size == 1) return b;
  return __any_sync(l.mask, b) != 0;
#else
  (void)l;
  return b;
#endif
}

// Lane `src`'s value, on every lane of the group (every lane must call it).
template <class T>  // float, int
SOAK_INLINE T laneFrom(const Lanes& l, T v, int src) {
#if defined(__CUDA_ARCH__)
  if (l.size == 1) return v;
  return __shfl_sync(l.mask, v, src, l.size);
#else
  (void)l;
  (void)src;
  return v;
#endif
}

SOAK_INLINE Vec3 laneFrom(const Lanes& l, Vec3 v, int src) {
  return Vec3(laneFrom(l, v.x, src), laneFrom(l, v.y, src), laneFrom(l, v.z, src));
}

// The sum of v over this lane and the lanes before it in the group.
SOAK_INLINE int laneInclusiveScan(const Lanes& l, int v) {
#if defined(__CUDA_ARCH__)
  for (int o = 1; o < l.size; o *= 2) {
    const int before = __shfl_up_sync(l.mask, v, o, l.size);
    if (l.index >= o) v += before;
  }
#else
  (void)l;
#endif
  return v;
}

// The lowest lane whose vote is set (votes: laneBallot's, not zero).
SOAK_INLINE int firstVote(unsigned votes) {
#if defined(__CUDA_ARCH__)
  return __ffs(votes) - 1;
#else
  int k = 0;
  for (; !(votes & 1u); votes >>= 1) ++k;
  return k;
#endif
}

}  // namespace soak

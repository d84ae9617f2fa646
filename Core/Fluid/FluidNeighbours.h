#pragma once
// Neighbour lists for the fluid solve, built once per step.
//
// Querying the grid in every density pass would visit 27 cells of about 8
// candidates each, most beyond h, for each of 2 passes x Water.iterations.
// The lists keep only the pairs that can matter: for a
// water particle, every water or cloth particle within (1 + skin) h_ij; for a
// moving cloth particle, every water particle within it. Each pass still
// applies its own r < h_ij test at the current positions. The list keeps
// the grid's visiting order, so sums come out in the same order: results
// are the same as with the grid query, unless a particle moves more than
// skin * h within one step's iterations. A huge skin keeps every grid
// candidate, and then the result is bit-identical to querying the grid in
// every pass (a test compares; Doc/performance.md gives the speed).
#include "Backend/Buffer.h"
#include "Base/HostDevice.h"
#include "Neighbours/GridView.h"
#include "Neighbours/PairLists.h"
#include "Particles/ParticleState.h"

namespace soak {

struct FluidNeighbourView {
  const int* start = nullptr;  // first entry of particle i
  const int* count = nullptr;  // entries of particle i
  const int* index = nullptr;  // neighbour slots
  // Entries the index buffer holds. Its size is set from the host on
  // maintenance steps only (Simulation.h); between them a particle whose
  // entries would run past it has no list and queries the grid instead.
  int capacity = 0;
  const int* phase = nullptr;
  const Float4* predicted = nullptr;
  GridView grid;
};

// True when the pair (i, j) belongs in i's list, distance aside: a water
// particle lists water and cloth, a moving cloth particle lists water.
SOAK_INLINE bool fluidPairKind(int phaseI, bool movingI, int phaseJ) {
  if (isWater(phaseI)) return isWater(phaseJ) || isCloth(phaseJ);
  return isCloth(phaseI) && movingI && isWater(phaseJ);
}

// Calls f(j) for the listed neighbours of i (with `lanes`: this lane's
// share, every lanes.size-th from lanes.index; Base/Lanes.h). Without a
// list (past the capacity) the grid's candidates of the listed kinds, in
// the grid's order: what a list of infinite skin would hold. Both walk
// ranges of entries (one range of the list, or the 27 cells' buckets) in
// one loop with one call of f, so that the passes' bodies are compiled once
// (with the grid walk as a second loop around a second copy of f, the two
// fluid passes took 63-64 registers instead of 46-47).
template <class F>
SOAK_INLINE void forEachListedNeighbour(const FluidNeighbourView& n, int i, const Lanes& lanes, F&& f) {
  const int s = n.start[i], e = s + n.count[i];
  const bool listed = e <= n.capacity;
  const GridView& g = n.grid;
  const std::uint32_t centre = listed ? 0u : g.slotKey[i];
  const int phi = n.phase[i];
  const bool moving = n.predicted[i].w > 0.f;
  const int ranges = listed ? 1 : 27;
  for (int r = 0; r < ranges; ++r) {
    std::uint32_t first = std::uint32_t(s), end = std::uint32_t(e), key = 0;
    if (!listed) {
      key = packCellKey(int(centre & 1023u) + r % 3 - 1, int((centre >> 10) & 1023u) + (r / 3) % 3 - 1,
                        int((centre >> 20) & 1023u) + r / 9 - 1);
      const BucketRange b = g.range[bucketOfKey(key, g.bucketMask)];
      first = b.start;
      end = b.end;
    }
    for (std::uint32_t k = first + std::uint32_t(lanes.index); k < end; k += std::uint32_t(lanes.size)) {
      int j;
      if (listed) {
        j = n.index[k];
      } else {
        if (g.cellKey[k] != key) continue;
        j = slotOfEntry(g, k);
        if (!fluidPairKind(phi, moving, n.phase[j])) continue;
      }
      f(j);
    }
  }
}

// The fluid's lists use PairLists' sizing (kept by checkpoints).
using FluidListSizing = PairListSizing;

class FluidNeighbours {
 public:
  explicit FluidNeighbours(Device d) : lists_(d), device_(d) {}
  // Builds the lists from the predicted positions (after the grid build),
  // keeping pairs within (1 + skin) h_ij (Water.neighbourSkin). With
  // `sizeExactly` (a maintenance step) the buffer is sized to hold them all
  // and a headroom; otherwise nothing waits for the device and lists past
  // the buffer's capacity are left out (the passes query the grid).
  void build(ParticleView p, GridView g, float skin, bool sizeExactly);
  FluidNeighbourView view() const { return view_; }
  // The index buffer's size and headroom (a download).
  FluidListSizing sizing() const { return lists_.sizing(); }
  void setSizing(const FluidListSizing& s) { lists_.setSizing(s); }
  // Particles of the last build without a list (a download; for tests).
  int particlesWithoutList() const { return lists_.itemsWithoutList(); }
  // The lists as the host sees them (downloads; for tests).
  std::vector<std::vector<int>> download() const { return lists_.download(); }

 private:
  PairLists lists_;
  FluidNeighbourView view_;
  Device device_;
};

}  // namespace soak

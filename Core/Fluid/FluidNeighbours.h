#pragma once
// Neighbour lists for the fluid solve, built once per step.
//
// The density iterations used to query the grid in every pass: 27 cells of
// about 8 candidates each, most beyond h, for each of 2 passes x
// Water.iterations. The lists keep only the pairs that can matter: for a
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
#include "Particles/ParticleState.h"

namespace soak {

struct FluidNeighbourView {
  const int* start = nullptr;  // first entry of particle i
  const int* count = nullptr;  // entries of particle i
  const int* index = nullptr;  // neighbour slots
};

// Calls f(j) for the listed neighbours of i (with `lanes`: this lane's
// share, every lanes.size-th from lanes.index; Base/Lanes.h).
template <class F>
SOAK_INLINE void forEachListedNeighbour(const FluidNeighbourView& n, int i, const Lanes& lanes, F&& f) {
  const int s = n.start[i], e = s + n.count[i];
  for (int k = s + lanes.index; k < e; k += lanes.size) f(n.index[k]);
}

template <class F>
SOAK_INLINE void forEachListedNeighbour(const FluidNeighbourView& n, int i, F&& f) {
  forEachListedNeighbour(n, i, Lanes{}, f);
}

class FluidNeighbours {
 public:
  explicit FluidNeighbours(Device d) : start_(d), count_(d), index_(d), device_(d) {}
  // Builds the lists from the predicted positions (after the grid build),
  // keeping pairs within (1 + skin) h_ij (Water.neighbourSkin).
  void build(ParticleView p, GridView g, float skin);
  FluidNeighbourView view() const { return {start_.data(), count_.data(), index_.data()}; }

 private:
  Buffer<int> start_, count_, index_;
  Device device_;
};

}  // namespace soak

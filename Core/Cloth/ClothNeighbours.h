#pragma once
// Cloth-cloth neighbour lists for the passes that run while the cloth stays
// where its solve left it (the wetting stages, from the porosity update to
// the sticking forces: they move water, or move cloth only after their last
// query).
//
// Walking the 27 cells around a cloth particle in the cloth's grid visits,
// in a sheet with the paper's 1 cm vertex spacing and 4 cm cells, 150-300
// candidates, of which about 50 lie within h. The lists keep,
// once per step, every cloth particle within max(h_ij, th_i + th_j) (the
// pair support of the SPH passes and the touching distance of Eq. 20), in
// the grid's order. Each pass still applies its own test, so its sums come
// out in the same order and with the same bits as walking the grid (one
// lane; with lane groups each lane takes every k-th entry of the list
// instead of every k-th of each cell, so GPU sums group differently).
#include "Cloth/ForEachClothParticle.h"
#include "Neighbours/GridView.h"
#include "Neighbours/PairLists.h"
#include "Particles/ParticleState.h"

namespace soak {

struct ClothNeighbourView {
  PairListView lists;   // items: the cloth particles in slot order (ClothSlots)
  GridView grid;        // the cloth's grid: for items without a list
  const int* slot = nullptr;  // item -> particle slot
};

// Calls f(j) for the cloth particles listed for item v (with `lanes`: this
// lane's share). An item without a list (past the buffer's capacity) walks
// the 27 cells of the cloth grid instead: every cloth particle the list
// would hold, and farther ones, in the same order.
template <class F>
SOAK_INLINE void forEachClothNeighbour(const ClothNeighbourView& n, int v, const Lanes& lanes, F&& f) {
  if (!n.lists.listed(v)) {
    forEachCandidate(n.grid, n.grid.slotKey[n.slot[v]], lanes, f);
    return;
  }
  const int s = n.lists.start[v], e = s + n.lists.count[v];
  for (int k = s + lanes.index; k < e; k += lanes.size) f(n.lists.index[k]);
}

class ClothNeighbours {
 public:
  explicit ClothNeighbours(Device d) : lists_(d), device_(d) {}
  // From the predicted positions, over the cloth grid `g` (valid since the
  // neighbours stage); `thickness` per vertex. With `sizeExactly` (a
  // maintenance step) the buffer is sized for all lists (PairLists.h).
  // `lanes`: a group of GPU lanes per item (false: one thread, as a
  // reference for tests; the lists are the same).
  void build(ParticleView p, GridView g, ClothSlots cloth, const float* thickness, bool sizeExactly,
             bool lanes = true);
  ClothNeighbourView view() const { return view_; }
  PairListSizing sizing() const { return lists_.sizing(); }
  void setSizing(const PairListSizing& s) { lists_.setSizing(s); }
  int itemsWithoutList() const { return lists_.itemsWithoutList(); }
  std::vector<std::vector<int>> download() const { return lists_.download(); }

 private:
  PairLists lists_;
  ClothNeighbourView view_;
  Device device_;
};

}  // namespace soak

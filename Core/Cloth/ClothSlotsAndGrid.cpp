// The cloth's place among the particles after each neighbour sort: its
// slots (by vertex and in grid order) and a grid over the cloth particles
// alone (ClothSystem::updateSlots, buildGrid).
#include "Backend/ForEach.h"
#include "Backend/Primitives.h"
#include "Base/Atomic.h"
#include "Cloth/ClothSystem.h"

namespace soak {

void ClothSystem::updateSlots(ParticleView p) {
  int* slot = dSlot_.data();
  dClothFlag_.resize(std::size_t(p.count));
  dClothOffset_.resize(std::size_t(p.count));
  int* flag = dClothFlag_.data();
  forEach(device_, p.count, SOAK_LAMBDA(int i) {
    const bool cloth = isCloth(p.phase[i]);
    flag[i] = cloth ? 1 : 0;
    if (cloth) slot[p.id[i]] = i;
  }, "cloth.slots");
  // The cloth's slots in particle (grid cell) order: the cloth passes walk
  // these, so that a warp's lanes are all cloth and query the same cells.
  int* offset = dClothOffset_.data();
  exclusiveScanAsync(device_, flag, offset, p.count);
  int* ordered = dClothSlots_.data();
  forEach(device_, p.count, SOAK_LAMBDA(int i) {
    if (flag[i]) ordered[offset[i]] = i;
  }, "cloth.slots.order");
}

void ClothSystem::buildGrid(GridView g) {
  const int* ordered = dClothSlots_.data();
  // The cloth's grid: the same buckets as the full grid, its entries the
  // ordered slots (already sorted by bucket, as the particles are).
  const std::size_t buckets = std::size_t(g.bucketMask) + 1;
  dGridRange_.resize(buckets);
  dGridRange_.fillZero();
  BucketRange* range = dGridRange_.data();
  std::uint32_t* key = dGridKey_.data();
  const int n = vertexCount();
  forEach(device_, n, SOAK_LAMBDA(int k) {
    const std::uint32_t kk = g.slotKey[ordered[k]];
    key[k] = kk;
    const std::uint32_t b = bucketOfKey(kk, g.bucketMask);
    if (k == 0 || bucketOfKey(g.slotKey[ordered[k - 1]], g.bucketMask) != b) range[b].start = std::uint32_t(k);
    if (k == n - 1 || bucketOfKey(g.slotKey[ordered[k + 1]], g.bucketMask) != b) range[b].end = std::uint32_t(k + 1);
  }, "cloth.grid");
  // Near bits (GridView.h): each cell that holds cloth sets the bits of the
  // 27 cells around it, once per run of its entries (a cell's entries are
  // adjacent unless its bucket holds another cell too; then it sets them
  // again, to the same effect).
  dGridNear_.resize((buckets + 31) / 32);
  dGridNear_.fillZero();
  std::uint32_t* near = dGridNear_.data();
  const std::uint32_t mask = g.bucketMask;
  forEach(device_, n, SOAK_LAMBDA(int k) {
    const std::uint32_t kk = key[k];
    if (k > 0 && key[k - 1] == kk) return;
    const int c[3] = {int(kk & 1023u), int((kk >> 10) & 1023u), int((kk >> 20) & 1023u)};
    std::uint32_t spread[3][3];
    spreadAround(c, spread);
    for (int dz = 0; dz < 3; ++dz)
      for (int dy = 0; dy < 3; ++dy)
        for (int dx = 0; dx < 3; ++dx) {
          const std::uint32_t b = (spread[0][dx] | spread[1][dy] | spread[2][dz]) & mask;
          atomicSetBits(&near[b >> 5], 1u << (b & 31u));
        }
  }, "cloth.grid.near");
  clothGrid_ = g;
  clothGrid_.range = range;
  clothGrid_.cellKey = key;
  clothGrid_.slot = ordered;
  clothGrid_.nearBits = near;
}

}  // namespace soak

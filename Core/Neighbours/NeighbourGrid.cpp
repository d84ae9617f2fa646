#include "Neighbours/NeighbourGrid.h"

#include <algorithm>
#include <vector>

#include "Backend/ForEach.h"
#include "Backend/Primitives.h"
#include "Base/Error.h"

namespace soak {

NeighbourGrid::NeighbourGrid(Device device)
    : device_(device),
      range_(device),
      cellKey_(device),
      bucket_(device),
      order_(device),
      sortedKeys_(device) {}

namespace {
// Smallest b with 2^b >= n (at least 1, at most 30: 3 x 10 key bits).
int bucketBitsFor(int n) {
  int b = 1;
  while (b < 30 && (1 << b) < n) ++b;
  return b;
}
}  // namespace

void NeighbourGrid::build(ParticleState& particles, float cellSize) {
  if (!(cellSize > 0.f) || !std::isfinite(cellSize))
    throw InputError("neighbour search: cell size must be positive and finite");
  const int n = particles.count();
  cellSize_ = cellSize;
  bucketBits_ = bucketBitsFor(n);
  const std::uint32_t buckets = 1u << bucketBits_;
  const std::uint32_t mask = buckets - 1u;
  const float inv = 1.f / cellSize;

  range_.resize(buckets);
  cellKey_.resize(n);
  bucket_.resize(n);
  order_.resize(n);
  range_.fillZero();
  if (n == 0) return;

  ParticleView p = particles.view();
  std::uint32_t* key = cellKey_.data();
  std::uint32_t* bucket = bucket_.data();
  std::uint32_t* order = order_.data();
  // Removed slots (Particles/Phase.h) go past the last bucket: sorted to the
  // end, in no bucket, never a candidate.
  forEach(device_, n, SOAK_LAMBDA(int i) {
    Float4 x = p.predicted[i];
    key[i] = cellKeyOf(x.xyz(), inv);
    bucket[i] = isRemoved(p.phase[i]) ? buckets : bucketOfKey(key[i], mask);
    order[i] = static_cast<std::uint32_t>(i);
  }, "grid.keys");

  if (device_ == Device::Cuda) sortCuda(n);
  else sortCpu(n);

  // Reorder the particle data itself (not only an index): neighbour loops
  // then read memory that is close together.
  particles.gather(order);
  // Keys follow the same order.
  sortedKeys_.resize(n);
  std::uint32_t* sk = sortedKeys_.data();
  const std::uint32_t* ck = key;
  forEach(device_, n, SOAK_LAMBDA(int i) { sk[i] = ck[order[i]]; }, "grid.sortKeys");
  cellKey_.swap(sortedKeys_);

  BucketRange* range = range_.data();
  const std::uint32_t* sb = bucket;
  forEach(device_, n, SOAK_LAMBDA(int i) {
    std::uint32_t b = sb[i];
    if (b == buckets) return;
    if (i == 0 || sb[i - 1] != b) range[b].start = static_cast<std::uint32_t>(i);
    if (i == n - 1 || sb[i + 1] != b) range[b].end = static_cast<std::uint32_t>(i + 1);
  }, "grid.ranges");
}

// Stable counting sort of slots by bucket (host memory).
void NeighbourGrid::sortCpu(int n) {
  const std::uint32_t buckets = (1u << bucketBits_) + 1u;  // the last: removed slots
  std::vector<std::uint32_t> offset(buckets + 1, 0);
  std::uint32_t* bucket = bucket_.data();
  for (int i = 0; i < n; ++i) ++offset[bucket[i] + 1];
  for (std::uint32_t b = 0; b < buckets; ++b) offset[b + 1] += offset[b];
  std::vector<std::uint32_t> sortedBucket(n);
  std::uint32_t* order = order_.data();
  for (int i = 0; i < n; ++i) {
    std::uint32_t dst = offset[bucket[i]]++;
    order[dst] = static_cast<std::uint32_t>(i);
    sortedBucket[dst] = bucket[i];
  }
  std::copy(sortedBucket.begin(), sortedBucket.end(), bucket);
}

// Stable radix sort of (bucket, slot) pairs on the GPU.
// One bit more than the buckets need, for the removed slots' bucket.
void NeighbourGrid::sortCuda(int n) { sortPairs(device_, bucket_.data(), order_.data(), n, bucketBits_ + 1); }

GridView NeighbourGrid::view() const {
  GridView g;
  g.invCellSize = 1.f / cellSize_;
  g.bucketMask = (1u << bucketBits_) - 1u;
  g.range = range_.data();
  g.cellKey = cellKey_.data();
  g.slotKey = cellKey_.data();
  return g;
}

std::size_t NeighbourGrid::bytes() const {
  return range_.capacity() * sizeof(BucketRange) +
         (cellKey_.capacity() + bucket_.capacity() + order_.capacity() + sortedKeys_.capacity()) *
             sizeof(std::uint32_t);
}

void countNeighbours(Device device, const GridView& grid, ParticleView p, int* count) {
  forEach(device, p.count, SOAK_LAMBDA(int i) {
    const Vec3 xi = p.predicted[i].xyz();
    const float hi = p.radius[i];
    int c = 0;
    // Every radius is at most the cell size: cells a cell size away or more
    // hold no neighbour. Within a cell the test is branch-free (the slot
    // itself and slots of other cells sharing the bucket count 0), which on
    // the CPU lets the compiler vectorise it.
    forEachCellWithin(grid, xi, 1.f, [&](std::uint32_t key, std::uint32_t first, std::uint32_t end) {
      for (std::uint32_t j = first; j < end; ++j) {
        const float r = maxf(hi, p.radius[j]);
        const bool near = lengthSquared(xi - p.predicted[j].xyz()) < r * r;
        c += int(near & (grid.cellKey[j] == key) & (j != std::uint32_t(i)));
      }
    });
    count[i] = c;
  }, "countNeighbours");
}

}  // namespace soak

#pragma once
#include <cstdint>

#include "Backend/Buffer.h"
#include "Neighbours/GridView.h"
#include "Particles/ParticleState.h"

namespace soak {

// Builds the cell-sorted neighbourhood structure (see GridView.h).
//
// build() computes each particle's cell from its predicted position, sorts
// particles by bucket (stable, so equal inputs give equal orders on every
// device), reorders every particle array of `particles` into that order, and
// records where each bucket starts and ends. After build(), slot i of every
// particle array is the i-th particle in cell order.
class NeighbourGrid {
 public:
  explicit NeighbourGrid(Device device = Device::Cpu);

  // cellSize must be >= the largest support radius used in queries.
  void build(ParticleState& particles, float cellSize);

  GridView view() const;
  float cellSize() const { return cellSize_; }
  int bucketBits() const { return bucketBits_; }
  // order()[i] = the slot (before build) of the particle now in slot i.
  const std::uint32_t* order() const { return order_.data(); }
  std::size_t bytes() const;

 private:
  void sortCpu(int n);
  void sortCuda(int n);

  Device device_;
  float cellSize_ = 1.f;
  int bucketBits_ = 1;
  Buffer<BucketRange> range_;
  Buffer<std::uint32_t> cellKey_, bucket_, order_, sortedKeys_;
};

// Neighbours of every particle: count[i] = #{ j != i : |x_i - x_j| < max(h_i, h_j) }
// with x the predicted positions. Used by tests and the benchmark.
void countNeighbours(Device device, const GridView& grid, ParticleView particles, int* count);

}  // namespace soak

#include "Fluid/FluidNeighbours.h"

#include "Backend/ForEach.h"
#include "Backend/Primitives.h"
#include "Fluid/SphKernels.h"

namespace soak {

namespace {
// Calls f(j) for the pairs the fluid passes can use (see FluidNeighbours.h).
template <class F>
SOAK_INLINE void forEachFluidCandidate(const ParticleView& p, const GridView& g, int i, float reach, F&& f) {
  const int phi = p.phase[i];
  const Float4 xi4 = p.predicted[i];
  const bool moving = xi4.w > 0.f;
  if (!isWater(phi) && !(isCloth(phi) && moving)) return;
  const Vec3 xi = xi4.xyz();
  const float hi = p.radius[i];
  forEachCandidate(g, g.slotKey[i], [&](int j) {
    if (!fluidPairKind(phi, moving, p.phase[j])) return;
    const float h = pairSupport(hi, p.radius[j]) * reach;
    if (lengthSquared(xi - p.predicted[j].xyz()) < h * h) f(j);
  });
}
}  // namespace

void FluidNeighbours::build(ParticleView p, GridView g, float skin, bool sizeExactly) {
  const float reach = 1.f + skin;
  const int n = p.count;
  start_.resize(std::size_t(n));
  count_.resize(std::size_t(n));
  int* count = count_.data();
  forEach(device_, n, SOAK_LAMBDA(int i) {
    int c = 0;
    forEachFluidCandidate(p, g, i, reach, [&](int) { ++c; });
    count[i] = c;
  }, "fluid.neighbours.count");
  if (overflow_.size() == 0) {
    overflow_.resize(1);
    overflow_.fillZero();
  }
  if (sizeExactly) {
    const int total = exclusiveScan(device_, count, start_.data(), n);
    // Particles went without a list since the last sizing: the pairs grow
    // faster than the headroom, so double it (up to as many again as now).
    if (overflow_.download()[0] != 0) {
      headroomEighths_ = headroomEighths_ < 8 ? 2 * headroomEighths_ : 8;
      overflow_.fillZero();
    }
    // Room for more than now (1/8 at first), so that lists growing until the
    // next sizing still fit; the old contents are not needed.
    const std::size_t entries = std::size_t(total > 0 ? total : 1);
    if (entries > index_.size()) {
      index_ = Buffer<int>(device_);
      index_.resize(entries + entries * std::size_t(headroomEighths_) / 8);
    }
  } else {
    exclusiveScanAsync(device_, count, start_.data(), n);
  }
  const int capacity = int(index_.size());
  const int* start = start_.data();
  int* index = index_.data();
  int* overflow = overflow_.data();
  forEach(device_, n, SOAK_LAMBDA(int i) {
    int k = start[i];
    if (k + count[i] > capacity) {  // no room: the passes query the grid (FluidNeighbours.h)
      *overflow = 1;
      return;
    }
    forEachFluidCandidate(p, g, i, reach, [&](int j) { index[k++] = j; });
  }, "fluid.neighbours.fill");
  view_ = {start, count, index, capacity, p.phase, p.predicted, g};
}

FluidListSizing FluidNeighbours::sizing() const {
  FluidListSizing s;
  s.capacity = int(index_.size());
  s.headroomEighths = headroomEighths_;
  s.overflowed = overflow_.size() > 0 && overflow_.download()[0] != 0;
  return s;
}

void FluidNeighbours::setSizing(const FluidListSizing& s) {
  index_ = Buffer<int>(device_);
  index_.resize(std::size_t(s.capacity > 0 ? s.capacity : 0));
  headroomEighths_ = s.headroomEighths;
  overflow_.resize(1);
  overflow_.upload({s.overflowed ? 1 : 0});
}

int FluidNeighbours::particlesWithoutList() const {
  const std::vector<int> start = start_.download(), count = count_.download();
  int without = 0;
  for (std::size_t i = 0; i < start.size(); ++i) without += start[i] + count[i] > view_.capacity ? 1 : 0;
  return without;
}

}  // namespace soak

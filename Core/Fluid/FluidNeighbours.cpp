#include "Fluid/FluidNeighbours.h"

#include "Backend/ForEach.h"
#include "Backend/Primitives.h"
#include "Fluid/SphKernels.h"

namespace soak {

namespace {
// Calls f(j, take) for the grid candidates of particle i, where take says
// whether the fluid passes can use the pair (see FluidNeighbours.h). With
// several lanes, lane k takes the k-th entry of each round of lanes.size
// entries of a cell, and every lane is called in every round (j = -1,
// take = false past a cell's end), so that the lanes can rank the pairs
// they take and write them in the grid's order. Returns false (and calls
// nothing) for a particle that has no list.
template <class F>
SOAK_INLINE bool forEachFluidCandidate(const ParticleView& p, const GridView& g, int i, float reach,
                                       const Lanes& lanes, F&& f) {
  const int phi = p.phase[i];
  const Float4 xi4 = p.predicted[i];
  const bool water = isWater(phi);
  if (!water && !(isCloth(phi) && xi4.w > 0.f)) return false;
  const Vec3 xi = xi4.xyz();
  const float hi = p.radius[i];
  const std::uint32_t centre = g.slotKey[i];
  const std::uint32_t cx = centre & 1023u, cy = (centre >> 10) & 1023u, cz = (centre >> 20) & 1023u;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const std::uint32_t key = ((cx + dx) & 1023u) | (((cy + dy) & 1023u) << 10) | (((cz + dz) & 1023u) << 20);
        const std::uint32_t b = bucketOfKey(key, g.bucketMask);
        const std::uint32_t s = g.start[b], e = g.end[b];
        for (std::uint32_t round = s; round < e; round += std::uint32_t(lanes.size)) {
          const std::uint32_t entry = round + std::uint32_t(lanes.index);
          int j = -1;
          bool take = false;
          if (entry < e && g.cellKey[entry] == key) {
            j = slotOfEntry(g, entry);
            const int phj = p.phase[j];
            if (water ? (isWater(phj) || isCloth(phj)) : isWater(phj)) {
              const float h = pairSupport(hi, p.radius[j]) * reach;
              take = lengthSquared(xi - p.predicted[j].xyz()) < h * h;
            }
          }
          f(j, take);
        }
      }
  return true;
}
}  // namespace

void FluidNeighbours::build(ParticleView p, GridView g, float skin) {
  const float reach = 1.f + skin;
  const int n = p.count;
  start_.resize(std::size_t(n));
  count_.resize(std::size_t(n));
  int* count = count_.data();
  forEachLanes(device_, n, SOAK_LAMBDA(int i, Lanes lanes) {
    int c = 0;
    const bool listed = forEachFluidCandidate(p, g, i, reach, lanes, [&](int, bool take) { c += take ? 1 : 0; });
    c = listed ? laneSum(lanes, c) : 0;
    if (lanes.leader()) count[i] = c;
  }, "fluid.neighbours.count");
  const int total = exclusiveScan(device_, count, start_.data(), n);
  // Room for 1/8 more than now, so that a growing list does not double the
  // buffer (Buffer::resize grows geometrically); the old contents are not needed.
  const std::size_t entries = std::size_t(total > 0 ? total : 1);
  if (entries > index_.capacity()) {
    index_ = Buffer<int>(device_);
    index_.reserve(entries + entries / 8);
  }
  index_.resize(entries);
  const int* start = start_.data();
  int* index = index_.data();
  forEachLanes(device_, n, SOAK_LAMBDA(int i, Lanes lanes) {
    int k = start[i];
    const unsigned below = (1u << lanes.index) - 1u;  // the lanes before this one
    forEachFluidCandidate(p, g, i, reach, lanes, [&](int j, bool take) {
      const unsigned taken = laneBallot(lanes, take);
      if (take) index[k + bitCount(taken & below)] = j;
      k += bitCount(taken);
    });
  }, "fluid.neighbours.fill");
}

}  // namespace soak

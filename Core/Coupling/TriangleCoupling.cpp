#include "Coupling/TriangleCoupling.h"

#include "Backend/ForEach.h"

namespace soak {

void snapshotTriangles(Device d, ParticleView p, ClothView c, const int* onlyIf) {
  forEach(d, c.triangleCount, SOAK_LAMBDA(int k) {
    if (onlyIf && !*onlyIf) return;
    const ClothTriangle t = c.firstVertexTriangles[k];
    const int sa = c.vertexSlot[t.v[0]], sb = c.vertexSlot[t.v[1]], sc = c.vertexSlot[t.v[2]];
    c.triangleSnapshot[k] = makeTriangleSnapshot(p.position[sa].xyz(), p.position[sb].xyz(), p.position[sc].xyz(),
                                                 p.predicted[sa].xyz(), p.predicted[sb].xyz(), p.predicted[sc].xyz());
  }, "cloth.triangleSnapshot");
}

namespace {

// One pass of Eq. 21 for water particle i (projectWaterOutOfCloth). With
// kRounds, by its group of lanes in rounds; without, its lanes look for a
// due correction and one lane walks the candidates.
template <bool kRounds>
struct WaterTrianglePass {
  ParticleView p;
  GridView g;
  ClothView c;
  const float* vertexStiffness;
  int passes;
  int* movedFlag;
  bool first;

  SOAK_INLINE void operator()(int i, const Lanes& lanes) const {
    if (!isWater(p.phase[i])) return;
    if (!first && !movedFlag[i]) return;  // uncorrected last pass: uncorrected again
    const Vec3 x0 = p.position[i].xyz();
    const Vec3 start = p.predicted[i].xyz();
    // Every cell the path and the triangles around it can touch: a fast
    // particle (a falling block lands at 3 m/s, 4.5 cm a step, more than a
    // cell) can cross cloth that lies around where it started.
    const auto correction = [&](int k, Vec3 x) {
      const float dist = 0.5f * c.thickness[c.firstVertexTriangles[k].v[0]];
      return triangleCouplingCorrection(x0, x, c.triangleSnapshot[k], dist);
    };
    // The pass's share of triangle k's correction.
    const auto shareOf = [&](int k) {
      const ClothTriangle t = c.firstVertexTriangles[k];
      float kappa = 1.f;
      if (vertexStiffness)
        kappa = (vertexStiffness[t.v[0]] + vertexStiffness[t.v[1]] + vertexStiffness[t.v[2]]) / 3.f;
      // Eq. 5: the per-pass share of a constraint of stiffness kappa.
      return 1.f - powf(1.f - minf(maxf(kappa, 0.f), 1.f), 1.f / float(passes));
    };
    Vec3 x = start;
    bool moved = false;
    if constexpr (kRounds) {
      // The one-lane pass (below) by the group: in rounds, each lane takes
      // the next entry of the box's cells' buckets and, for a cloth
      // candidate, looks for its first triangle that corrects the particle
      // where it is now; the lowest lane with one gives the pass's next
      // correction (every triangle before it was looked at from the same
      // place and gave none), every lane adds it, and the next round starts
      // at that entry, after that triangle. The same corrections in the
      // same order as one lane: the same bits. Most particles get none, and
      // their pass is one look at each candidate, shared by the lanes.
      // The box's cells go lanes.size at a time, their buckets laid end to
      // end (CellBatch), so a round takes the next entries across cells.
      const PathBox box(g, x0, start, triangleReach(c.maxEdgeLength, 0.5f * c.maxThickness));
      const CellBox cells(g, box.lo, box.hi);
      for (int base = 0; base < cells.count; base += lanes.size) {
        std::uint32_t bucket = 0, key = 0;
        const bool has = base + lanes.index < cells.count;
        if (has) key = cells.cell(g, base + lanes.index, bucket);
        const CellBatch batch(g, lanes, has, key, bucket);
        const int total = batch.total;
        int next = 0;
        int skip = 0;  // triangles of the round's first entry already taken
        while (next < total) {
          const int at = next + lanes.index;
          std::uint32_t cellKey = 0;
          const std::uint32_t m = batch.entry(lanes, at, cellKey);
          int hit = -1;
          Vec3 corr(0.f, 0.f, 0.f);
          float share = 0.f;
          if (at < total && g.cellKey[m] == cellKey) {
            const int j = slotOfEntry(g, m);
            if (isCloth(p.phase[j]) && box.near(p.predicted[j].xyz())) {
              const int v = p.id[j];
              const int firstTriangle = c.firstVertexTriangleStart[v], last = c.firstVertexTriangleStart[v + 1];
              for (int k = firstTriangle + (lanes.index == 0 ? skip : 0); k < last && hit < 0; ++k) {
                corr = correction(k, x);
                if (isZero(corr)) continue;
                hit = k - firstTriangle;
                share = shareOf(k);
              }
            }
          }
          const unsigned votes = laneBallot(lanes, hit >= 0);
          if (votes == 0u) {
            next += lanes.size;
            skip = 0;
            continue;
          }
          const int lane = firstVote(votes);
          // Corrections and shares cross lanes apart, so that x takes the
          // product as the one-lane pass does (the same contraction).
          x += laneFrom(lanes, corr, lane) * laneFrom(lanes, share, lane);
          moved = true;
          next += lane;
          skip = laneFrom(lanes, hit, lane) + 1;
        }
      }
      if (!lanes.leader()) return;
    } else {
      if (lanes.size > 1) {
        // The lanes look for any triangle that corrects the particle where
        // it is; if none does, the one-lane pass would not move it either.
        bool due = false;
        forEachTriangleNearPath(g, p, c, x0, start, lanes, [&](int k, int) {
          if (!due) due = !isZero(correction(k, start));
        });
        if (!laneAny(lanes, due)) {
          if (lanes.leader()) movedFlag[i] = 0;
          return;
        }
        if (!lanes.leader()) return;
      }
      forEachTriangleNearPath(g, p, c, x0, start, Lanes{}, [&](int k, int) {
        const Vec3 corr = correction(k, x);
        if (isZero(corr)) return;
        x += corr * shareOf(k);
        moved = true;
      });
    }
    if (moved) p.predicted[i] = Float4(x, p.predicted[i].w);
    movedFlag[i] = moved ? 1 : 0;
  }
};

// Blocks of 256 threads the coupling kernels keep resident per SM
// (registers capped to fit; see projectWaterOutOfCloth).
constexpr int kCouplingBlocks = 4;

}  // namespace

void projectWaterOutOfCloth(Device d, ParticleView p, GridView g, ClothView c, const float* vertexStiffness,
                            int passes, int* movedFlag, int minLanes, int exactLanes) {
  if (c.triangleCount == 0) return;
  snapshotTriangles(d, p, c);  // the passes move water only
  // Two kernels: the rounds where the pass gets groups of lanes (fewer than
  // about a million particles on the GPU), the look for a due correction
  // and one lane's walk elsewhere (one lane: the larger scenes, the CPU).
  // Compiled into one kernel with the rounds, the one-lane walk took 79
  // registers instead of 72 and `coupling` at 1M 3.34-3.36 ms instead of
  // 3.02-3.05 on the H100. Both kernels are held to 64 registers (4 blocks
  // of 256 threads an SM): the one-lane kernel at 1M 3.07 -> 2.85 ms, 4M
  // 18.8 -> 17.2, 5 blocks (48 registers) gained less, 3 nothing; the
  // rounds (82 registers) on fig9b 0.170-0.177 -> 0.159-0.162 ms, 3 blocks
  // nothing (Doc/performance.md).
  // exactLanes: that many lanes a particle whatever the count (lanesFor
  // with one thread in view returns minLanes).
  const int threads = exactLanes > 0 ? 1 : kLaneThreads;
  if (exactLanes > 0) minLanes = exactLanes;
  const bool rounds = d == Device::Cuda && lanesFor(p.count, minLanes, threads) > 1;
  for (int pass = 0; pass < passes; ++pass) {
    const bool first = pass == 0;
    if (rounds) {
      const WaterTrianglePass<true> f{p, g, c, vertexStiffness, passes, movedFlag, first};
      forEachLanes<kCouplingBlocks>(d, p.count, f, "coupling.triangles", minLanes, threads);
    } else {
      const WaterTrianglePass<false> f{p, g, c, vertexStiffness, passes, movedFlag, first};
      forEachLanes<kCouplingBlocks>(d, p.count, f, "coupling.triangles", minLanes, threads);
    }
  }
}

}  // namespace soak

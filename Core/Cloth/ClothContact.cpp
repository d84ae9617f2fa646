#include "Cloth/ClothContact.h"

#include "Backend/ForEach.h"
#include "Cloth/ForEachClothParticle.h"
#include "Coupling/TriangleCoupling.h"
#include "Physics/Integrate.h"

namespace soak {

// Blocks of 256 threads the two contact kernels keep resident per SM
// (registers capped to fit): both are latency-bound walks of their
// candidates, and more resident warps hide more of it. H100, both at 4
// against uncapped (the vertex-triangle kernel had 92 registers, 21 %
// occupancy on fig9b): `cloth.solve` fig9b 1.68-1.72 -> 1.58-1.60 ms,
// fig6b 1.76-1.88 -> 1.62-1.73, 1M 2.64 -> 2.44; the same bits
// (Doc/performance.md).
constexpr int kContactBlocks = 4;

void resolveClothContacts(Device d, ParticleView p, ClothContactView n, Float4* scratch, int passes,
                          const int* onlyIf) {
  const ClothSlots cloth = clothSlots(n.cloth);
  const ClothView c = n.cloth;
  // Each pass reads the cloth's x* from one buffer and writes them to the
  // other (x* and scratch in turn), so that no launch of its own adds the
  // corrections: an even number of passes ends in x*.
  Float4* const own = p.predicted;
  for (int pass = 0; pass < passes; ++pass) {
    const Float4* in = pass % 2 == 0 ? own : scratch;
    Float4* out = pass % 2 == 0 ? scratch : own;
    forEachClothItemLanes<kContactBlocks>(d, cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
      if (onlyIf && !*onlyIf) return;
      const Float4 xi4 = in[i];
      if (xi4.w == 0.f) {
        if (lanes.leader()) out[i] = xi4;
        return;
      }
      const Vec3 xi = xi4.xyz();
      const float thi = c.thickness[p.id[i]];
      Vec3 sum(0.f, 0.f, 0.f);
      int count = 0;
      const int vi = p.id[i];
      const Vec3 resti = c.restPosition[vi];
      // The candidates: cloth particles other than i (ClothContactLists.h).
      forEachContactCandidate(n, v, i, lanes, [&](int j) {
        const int vj = p.id[j];
        const float contact = 0.5f * (thi + c.thickness[vj]);
        const Float4 xj4 = in[j];
        const Vec3 xij = xi - xj4.xyz();
        // The pair's normal is taken from the positions at the start of the
        // (sub-)step, so a fast layer cannot tunnel through and be pushed out
        // the wrong side.
        const Vec3 xij0 = p.position[i].xyz() - p.position[j].xyz();
        const float r0sq = lengthSquared(xij0);
        if (r0sq >= 4.f * contact * contact && lengthSquared(xij) >= contact * contact) return;
        if (p.phase[j] == p.phase[i] && lengthSquared(resti - c.restPosition[vj]) < 1.44f * contact * contact) return;
        const Vec3 nrm = r0sq > 1e-18f ? xij0 / sqrtf(r0sq) : normalizedOrZero(xij);
        const float along = dot(xij, nrm);
        if (along >= contact || lengthSquared(xij - nrm * along) >= contact * contact) return;
        sum += nrm * ((contact - along) * xi4.w / (xi4.w + xj4.w));
        ++count;
      });
      sum = laneSum(lanes, sum);
      count = laneSum(lanes, count);
      if (!lanes.leader()) return;
      const Vec3 delta = count > 0 ? sum / float(count) : Vec3(0.f, 0.f, 0.f);
      out[i] = isZero(delta) ? xi4 : Float4(xi + delta, xi4.w);
    }, "cloth.contact");
  }
  if (passes % 2 == 1)
    forEachClothParticle(d, cloth, SOAK_LAMBDA(int i) {
      if (!onlyIf || *onlyIf) own[i] = scratch[i];
    }, "cloth.contact.copy");
}

namespace {
SOAK_INLINE bool touchesOneRing(const ClothView& c, int v, const ClothTriangle& t) {
  for (int k = c.vertexTriangleStart[v]; k < c.vertexTriangleStart[v + 1]; ++k) {
    const ClothTriangle r = c.triangles[c.vertexTriangles[k]];
    for (int a = 0; a < 3; ++a)
      if (r.v[a] == t.v[0] || r.v[a] == t.v[1] || r.v[a] == t.v[2]) return true;
  }
  return false;
}
}  // namespace

void resolveVertexTriangleContacts(Device d, ParticleView p, ClothContactView n, const int* onlyIf) {
  const ClothView c = n.cloth;
  if (c.triangleCount == 0) return;
  snapshotTriangles(d, p, c, onlyIf);
  const ClothSlots cloth = clothSlots(c);
  forEachClothItemLanes<kContactBlocks>(d, cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
    if (onlyIf && !*onlyIf) return;
    const Float4 xi4 = p.predicted[i];
    if (xi4.w == 0.f) return;
    const int vi = p.id[i];
    const Vec3 x0 = p.position[i].xyz(), start = xi4.xyz();
    const float dist = 0.5f * c.thickness[vi];
    // The same side test as water (Eq. 21); the vertex takes the whole correction.
    const auto correction = [&](int k, Vec3 x) {
      const ClothTriangle t = c.firstVertexTriangles[k];
      if (t.v[0] == vi || t.v[1] == vi || t.v[2] == vi) return Vec3(0.f, 0.f, 0.f);
      return triangleCouplingCorrection(x0, x, c.triangleSnapshot[k], dist, 0.f);
    };
    // The pass reads no other vertex's x*, only the triangles' snapshot (a
    // candidate's place too: TrianglePath::nearTriangles), so each vertex
    // writes its own correction in place: x* plus the correction x - x*.
    const auto write = [&](Vec3 x) {
      const Vec3 dx = x - start;
      if (!isZero(dx)) p.predicted[i] = Float4(start + dx, xi4.w);
    };
    // A triangle that shares a vertex with one of the vertex's own
    // triangles is its own surface, not another layer.
    const auto ownSurface = [&](int k, int j) {
      return p.phase[j] == p.phase[i] && touchesOneRing(c, vi, c.firstVertexTriangles[k]);
    };
    if (lanes.size > 1 && n.lists.listed(v)) {
      // The sequential pass below, by the group: in rounds, each lane takes
      // the next candidate in the list and looks for its first triangle
      // that would correct the vertex where it is now; the lowest lane with
      // one gives the pass's next correction (every triangle before it was
      // looked at from the same place and gave none), every lane adds it,
      // and the next round starts just after it. The same corrections in
      // the same order as one lane: the same bits. Most vertices get none,
      // and their pass is one look at each candidate shared by the lanes.
      const TrianglePath path(c, x0, start);
      const int end = n.lists.start[v] + n.lists.count[v];
      Vec3 x = start;
      int next = n.lists.start[v], skip = 0;  // the round's first entry; triangles of it already taken
      while (next < end) {
        const int m = next + lanes.index;
        int hit = -1;
        Vec3 corr(0.f, 0.f, 0.f);
        if (m < end) {
          const int j = n.lists.index[m];
          const int vj = p.id[j];
          const int first = c.firstVertexTriangleStart[vj], last = c.firstVertexTriangleStart[vj + 1];
          if (path.nearTriangles(c, first, last)) {
            for (int k = first + (lanes.index == 0 ? skip : 0); k < last && hit < 0; ++k) {
              const Vec3 ck = correction(k, x);
              if (isZero(ck) || ownSurface(k, j)) continue;
              hit = k - first;
              corr = ck;
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
        x += laneFrom(lanes, corr, lane);
        next += lane;
        skip = laneFrom(lanes, hit, lane) + 1;
      }
      if (lanes.leader()) write(x);
      return;
    }
    // One lane (the CPU), or an item without a list: its leader alone.
    if (!lanes.leader()) return;
    Vec3 x = start;
    forEachCandidateTriangleNearPath(n, p, v, i, x0, start, Lanes{}, [&](int k, int j) {
      const Vec3 corr = correction(k, x);
      if (isZero(corr) || ownSurface(k, j)) return;  // the one-ring test only where a correction is due
      x += corr;
    });
    write(x);
  }, "cloth.vertexTriangle");
}

}  // namespace soak

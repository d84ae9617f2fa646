#include "Cloth/CrossingGuard.h"

#include "Backend/ForEach.h"
#include "Cloth/ForEachClothParticle.h"
#include "Coupling/TriangleCoupling.h"

namespace soak {

namespace {
constexpr int kEdgesAtOnce = 4;  // a vertex's own edges tested in one walk of its candidates
}  // namespace

void revertNewCrossings(Device d, ParticleView p, ClothContactView n, int* flag, int rounds, const int* onlyIf) {
  const ClothView c = n.cloth;
  if (c.triangleCount == 0 || rounds <= 0) return;
  const ClothSlots cloth = clothSlots(c);
  // found[r]: 1 once round r has found a crossing. A round after the first
  // runs only if the one before found one (its launches return at once
  // otherwise: no vertex moved, so nothing new can have crossed).
  int* const found = flag + p.count;
  // A triangle can hold an edge of vertex i only if its first vertex lies
  // within an edge and a triangle's diagonal of i (1 + sqrt 2 longest
  // edges), with room for 10 % stretch.
  const float near = 2.7f * c.maxEdgeLength;
  for (int round = 0; round < rounds; ++round) {
    const int* const go = round > 0 ? found + round - 1 : onlyIf;  // round 0: where the contacts run
    int* const foundNow = found + round;
    // The triangles as they are now (and at the sub-step's start): the
    // test below reads one place per triangle and rejects most on their
    // plane alone.
    snapshotTriangles(d, p, c, go);
    // Flags every vertex of a new crossing: each edge is tested from its
    // first vertex against the triangles of that vertex's candidates (each
    // triangle from its first vertex). Flags are only set to 1, so the
    // result does not depend on the order of the writes.
    forEachClothItemLanes(d, cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
      if (go && !*go) return;
      const int vi = p.id[i];
      const int eEnd = c.firstVertexEdgeStart[vi + 1];
      const Vec3 xi = p.predicted[i].xyz();
      for (int chunk = c.firstVertexEdgeStart[vi]; chunk < eEnd; chunk += kEdgesAtOnce) {
        const int edges = eEnd - chunk < kEdgesAtOnce ? eEnd - chunk : kEdgesAtOnce;
        int other[kEdgesAtOnce], otherSlot[kEdgesAtOnce];
        Vec3 end[kEdgesAtOnce];
        for (int e = 0; e < edges; ++e) {
          other[e] = c.firstVertexEdgeOther[chunk + e];
          otherSlot[e] = c.vertexSlot[other[e]];
          end[e] = p.predicted[otherSlot[e]].xyz();
        }
        forEachContactCandidate(n, v, i, lanes, [&](int j) {
          // Its triangles all start at j: first the one test at j's place
          // (slots in the list's order), then its triangles.
          if (lengthSquared(p.predicted[j].xyz() - xi) > near * near) return;
          const int vj = p.id[j];
          const int tEnd = c.firstVertexTriangleStart[vj + 1];
          for (int k = c.firstVertexTriangleStart[vj]; k < tEnd; ++k) {
            const TriangleSnapshot& s = c.triangleSnapshot[k];
            const Vec3 a = s.a(), nrm = s.n();
            const float si = dot(xi - a, nrm);
            for (int e = 0; e < edges; ++e) {
              if (!(si * dot(end[e] - a, nrm) < 0.f)) continue;  // both ends on one side of the plane
              if (!segmentCrossesTriangle(xi, end[e], a, s.b(), s.c())) continue;
              const ClothTriangle t = c.firstVertexTriangles[k];
              if (t.v[0] == vi || t.v[1] == vi || t.v[2] == vi || t.v[0] == other[e] || t.v[1] == other[e] ||
                  t.v[2] == other[e])
                continue;
              if (segmentCrossesTriangle(p.position[i].xyz(), p.position[otherSlot[e]].xyz(), s.a0(), s.b0(),
                                         s.c0()))
                continue;  // crossed at the start already: not this sub-step's doing
              flag[i] = 1;
              flag[otherSlot[e]] = 1;
              flag[c.vertexSlot[t.v[0]]] = 1;
              flag[c.vertexSlot[t.v[1]]] = 1;
              flag[c.vertexSlot[t.v[2]]] = 1;
              *foundNow = 1;
            }
          }
        });
      }
    }, "cloth.crossingGuard");
    forEachClothParticle(d, cloth, SOAK_LAMBDA(int i) {
      if (go && !*go) return;
      if (!flag[i]) return;
      flag[i] = 0;
      const Float4 x = p.predicted[i];
      if (x.w != 0.f) p.predicted[i] = Float4(p.position[i].xyz(), x.w);
    }, "cloth.crossingGuard.revert");
  }
  // Ready for the next sub-step.
  forEach(d, rounds, SOAK_LAMBDA(int r) { found[r] = 0; }, "cloth.crossingGuard.reset");
}

}  // namespace soak

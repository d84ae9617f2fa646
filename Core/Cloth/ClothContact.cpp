#include "Cloth/ClothContact.h"

#include "Backend/ForEach.h"
#include "Cloth/ForEachClothParticle.h"
#include "Coupling/TriangleCoupling.h"
#include "Physics/Integrate.h"

namespace soak {

void resolveClothContacts(Device d, ParticleView p, ClothContactView n, Vec3* delta, int passes) {
  const ClothSlots cloth = clothSlots(n.cloth);
  const ClothView c = n.cloth;
  for (int pass = 0; pass < passes; ++pass) {
    forEachClothItemLanes(d, cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
      const Float4 xi4 = p.predicted[i];
      if (xi4.w == 0.f) {
        if (lanes.leader()) delta[i] = Vec3(0.f, 0.f, 0.f);
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
        const Float4 xj4 = p.predicted[j];
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
      if (lanes.leader()) delta[i] = count > 0 ? sum / float(count) : Vec3(0.f, 0.f, 0.f);
    }, "cloth.contact");
    applyCorrectionsAt(d, p, cloth.slot, cloth.count, delta, "cloth.contact.apply");
  }
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

void resolveVertexTriangleContacts(Device d, ParticleView p, ClothContactView n, Vec3* delta) {
  const ClothView c = n.cloth;
  if (c.triangleCount == 0) return;
  snapshotTriangles(d, p, c);
  const ClothSlots cloth = clothSlots(c);
  forEachClothItemLanes(d, cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
    const Float4 xi4 = p.predicted[i];
    if (xi4.w == 0.f) {
      if (lanes.leader()) delta[i] = Vec3(0.f, 0.f, 0.f);
      return;
    }
    const int vi = p.id[i];
    const Vec3 x0 = p.position[i].xyz(), start = xi4.xyz();
    const float dist = 0.5f * c.thickness[vi];
    // The same side test as water (Eq. 21); the vertex takes the whole correction.
    const auto correction = [&](int k, Vec3 x) {
      const ClothTriangle t = c.firstVertexTriangles[k];
      if (t.v[0] == vi || t.v[1] == vi || t.v[2] == vi) return Vec3(0.f, 0.f, 0.f);
      return triangleCouplingCorrection(x0, x, c.triangleSnapshot[k], dist, 0.f);
    };
    // A triangle that shares a vertex with one of the vertex's own
    // triangles is its own surface, not another layer.
    const auto ownSurface = [&](int k, int j) {
      return p.phase[j] == p.phase[i] && touchesOneRing(c, vi, c.firstVertexTriangles[k]);
    };
    // With several lanes, they first look for any triangle of another layer
    // that would correct the vertex where it is; if none would, neither
    // would the sequential pass below (its corrections are taken at the
    // vertex's current position, which then never changes). Corrections
    // are rare: most vertices stop here. One lane (the CPU) goes straight on.
    if (lanes.size > 1) {
      bool due = false;
      forEachCandidateTriangleNearPath(n, p, v, i, x0, start, lanes, [&](int k, int j) {
        if (!due) due = !isZero(correction(k, start)) && !ownSurface(k, j);
      });
      const bool any = laneAny(lanes, due);
      if (!lanes.leader()) return;
      if (!any) {
        delta[i] = Vec3(0.f, 0.f, 0.f);
        return;
      }
    }
    Vec3 x = start;
    forEachCandidateTriangleNearPath(n, p, v, i, x0, start, Lanes{}, [&](int k, int j) {
      const Vec3 corr = correction(k, x);
      if (isZero(corr) || ownSurface(k, j)) return;  // the one-ring test only where a correction is due
      x += corr;
    });
    delta[i] = x - start;
  }, "cloth.vertexTriangle");
  applyCorrectionsAt(d, p, cloth.slot, cloth.count, delta, "cloth.vertexTriangle.apply");
}

}  // namespace soak

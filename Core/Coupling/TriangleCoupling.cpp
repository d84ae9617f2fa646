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

void projectWaterOutOfCloth(Device d, ParticleView p, GridView g, ClothView c, const float* vertexStiffness,
                            int passes, int* movedFlag, int minLanes) {
  if (c.triangleCount == 0) return;
  snapshotTriangles(d, p, c);  // the passes move water only
  for (int pass = 0; pass < passes; ++pass) {
    const bool first = pass == 0;
    forEachLanes(d, p.count, SOAK_LAMBDA(int i, Lanes lanes) {
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
      // With several lanes, they first look for any triangle that corrects
      // the particle where it is; if none does, the sequential pass below
      // would not move it either (each correction is taken at the
      // particle's current position, and that never changes). One lane (the
      // CPU) goes straight on.
      if (lanes.size > 1) {
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
      Vec3 x = start;
      bool moved = false;
      forEachTriangleNearPath(g, p, c, x0, start, Lanes{}, [&](int k, int) {
        const Vec3 corr = correction(k, x);
        if (isZero(corr)) return;
        const ClothTriangle t = c.firstVertexTriangles[k];
        float kappa = 1.f;
        if (vertexStiffness)
          kappa = (vertexStiffness[t.v[0]] + vertexStiffness[t.v[1]] + vertexStiffness[t.v[2]]) / 3.f;
        // Eq. 5: the per-pass share of a constraint of stiffness kappa.
        const float share = 1.f - powf(1.f - minf(maxf(kappa, 0.f), 1.f), 1.f / float(passes));
        x += corr * share;
        moved = true;
      });
      if (moved) p.predicted[i] = Float4(x, p.predicted[i].w);
      movedFlag[i] = moved ? 1 : 0;
    }, "coupling.triangles", minLanes);
  }
}

}  // namespace soak

#include "Coupling/TriangleCoupling.h"

#include "Backend/ForEach.h"

namespace soak {

void projectWaterOutOfCloth(Device d, ParticleView p, GridView g, ClothView c, const float* vertexStiffness,
                            int passes) {
  if (c.triangleCount == 0) return;
  for (int pass = 0; pass < passes; ++pass) {
    forEach(d, p.count, SOAK_LAMBDA(int i) {
      if (!isWater(p.phase[i])) return;
      const Vec3 x0 = p.position[i].xyz();
      Vec3 x = p.predicted[i].xyz();
      bool moved = false;
      // Every cell the path and the triangles around it can touch: a fast
      // particle (a falling block lands at 3 m/s, 4.5 cm a step, more than a
      // cell) can cross cloth that lies around where it started.
      forEachTriangleNearPath(g, p, c, x0, x, [&](const ClothTriangle& t, int) {
        const int sa = c.vertexSlot[t.v[0]], sb = c.vertexSlot[t.v[1]], sc = c.vertexSlot[t.v[2]];
        const float dist = 0.5f * c.thickness[t.v[0]];
        const Vec3 corr = triangleCouplingCorrection(x0, x, p.position[sa].xyz(), p.position[sb].xyz(),
                                                     p.position[sc].xyz(), p.predicted[sa].xyz(),
                                                     p.predicted[sb].xyz(), p.predicted[sc].xyz(), dist);
        if (corr.x == 0.f && corr.y == 0.f && corr.z == 0.f) return;
        float kappa = 1.f;
        if (vertexStiffness)
          kappa = (vertexStiffness[t.v[0]] + vertexStiffness[t.v[1]] + vertexStiffness[t.v[2]]) / 3.f;
        // Eq. 5: the per-pass share of a constraint of stiffness kappa.
        const float share = 1.f - powf(1.f - fminf(fmaxf(kappa, 0.f), 1.f), 1.f / float(passes));
        x += corr * share;
        moved = true;
      });
      if (moved) p.predicted[i] = Float4(x, p.predicted[i].w);
    }, "coupling.triangles");
  }
}

}  // namespace soak

#include "Cloth/ClothSolve.h"

#include "Backend/ForEach.h"

namespace soak {

void moveAttachedVertices(Device d, ParticleView p, ClothView c, const Collider* colliders) {
  forEach(d, c.vertexCount, SOAK_LAMBDA(int v) {
    const int k = c.attachCollider[v];
    if (k < 0) return;
    const int i = c.vertexSlot[v];
    p.predicted[i] = Float4(c.restPosition[v] + colliders[k].displacement, p.predicted[i].w);
  }, "cloth.attach");
}

void solveClothConstraints(Device d, ParticleView p, ClothView c, const std::vector<int>& stretchColours,
                           const std::vector<int>& bendColours, int iterations, float dt) {
  for (int it = 0; it < iterations; ++it) {
    // Tethers: unilateral, only the free vertex moves (its pins do not).
    forEach(d, c.vertexCount, SOAK_LAMBDA(int v) {
      const int i = c.vertexSlot[v];
      Float4 x = p.predicted[i];
      if (x.w == 0.f) return;
      Vec3 q = x.xyz();
      for (int k = 0; k < kTethers; ++k) {
        const int pin = c.tetherPin[v * kTethers + k];
        if (pin < 0) break;
        const Vec3 anchor = p.predicted[c.vertexSlot[pin]].xyz();
        const Vec3 d = q - anchor;
        const float len = length(d), maxLen = c.tetherLength[v * kTethers + k];
        if (len > maxLen) q = anchor + d * (maxLen / len);
      }
      p.predicted[i] = Float4(q, x.w);
    }, "cloth.tethers");
    for (std::size_t col = 0; col + 1 < stretchColours.size(); ++col) {
      const int first = stretchColours[col];
      forEach(d, stretchColours[col + 1] - first, SOAK_LAMBDA(int k) {
        const int e = first + k;
        const int a = c.vertexSlot[c.edges[e].a], b = c.vertexSlot[c.edges[e].b];
        const Float4 xa = p.predicted[a], xb = p.predicted[b];
        Vec3 da, db;
        projectStretch(xa.xyz(), xa.w, xb.xyz(), xb.w, c.edgeRest[e], c.edgeStiffness[e], dt, c.edgeLambda[e], da,
                       db);
        p.predicted[a] = Float4(xa.xyz() + da, xa.w);
        p.predicted[b] = Float4(xb.xyz() + db, xb.w);
      }, "cloth.stretch");
    }
    for (std::size_t col = 0; col + 1 < bendColours.size(); ++col) {
      const int first = bendColours[col];
      forEach(d, bendColours[col + 1] - first, SOAK_LAMBDA(int k) {
        const int b = first + k;
        int slot[4];
        Vec3 x[4], dx[4];
        float w[4];
        for (int a = 0; a < 4; ++a) {
          slot[a] = c.vertexSlot[c.bends[b].v[a]];
          const Float4 q = p.predicted[slot[a]];
          x[a] = q.xyz();
          w[a] = q.w;
        }
        projectBend(x, w, c.bendRest[b], c.bendStiffness[b], dt, c.bendLambda[b], dx);
        for (int a = 0; a < 4; ++a) p.predicted[slot[a]] = Float4(x[a] + dx[a], w[a]);
      }, "cloth.bend");
    }
  }
}

}  // namespace soak

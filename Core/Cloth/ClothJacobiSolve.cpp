// The Jacobi-Chebyshev cloth solve (ClothJacobi.h): one parallel phase per
// iteration over the vertices of the chebyshev cloths.
#include "Backend/ForEach.h"
#include "Base/ReadOnly.h"
#include "Cloth/ClothSolve.h"

namespace soak {

namespace {
// Vertex v's position x limited by its tethers (pins' positions from `at`).
SOAK_INLINE Vec3 clampToTethers(const ClothView& c, int v, const Float4* at, Vec3 x) {
  const TetherPins pins = loadReadOnly(reinterpret_cast<const TetherPins*>(c.tetherPin) + v);
  if (pins.pin[0] < 0) return x;
  const TetherLengths lengths = loadReadOnly(reinterpret_cast<const TetherLengths*>(c.tetherLength) + v);
  for (int t = 0; t < kTethers && pins.pin[t] >= 0; ++t) x = clampToTether(x, at[pins.pin[t]].xyz(), lengths.length[t]);
  return x;
}
}  // namespace

void solveClothJacobi(Device d, ParticleView p, ClothView c, int iterations, float h, float rho) {
  const int n = c.jacobiVertexCount;
  if (n == 0 || iterations <= 0) return;
  // Iterates in vertex order: x_k in `current`, x_{k-1} in `previous`; an
  // iteration writes x_{k+1} over x_{k-1} (each vertex reads only its own
  // x_{k-1}) and the two swap.
  Float4* current = c.vertexScratch;
  Float4* previous = c.jacobiPrevious;
  Float4* target = c.jacobiTarget;
  forEach(d, n, SOAK_LAMBDA(int k) {
    const int v = c.jacobiVertices[k];
    const Float4 x = p.predicted[c.vertexSlot[v]];
    current[v] = x;
    target[v] = x;
  }, "cloth.jacobi.gather");
  // Bending: one averaged Jacobi pass of Eq. 9's projections.
  if (c.anyJacobiBends) {
    const Float4* x = current;
    Float4* bent = previous;
    forEach(d, n, SOAK_LAMBDA(int k) {
      const int v = c.jacobiVertices[k];
      const Float4 xv = x[v];
      Vec3 sum(0.f, 0.f, 0.f);
      int count = 0;
      if (xv.w != 0.f)
        for (int r = c.bendRefStart[v], end = c.bendRefStart[v + 1]; r < end; ++r) {
          const JacobiBendRef ref = loadReadOnly(c.bendRefs + r);
          const ClothBend bend = loadReadOnly(c.jacobiBends + ref.bend);
          Vec3 q[4];
          float w[4];
          for (int a = 0; a < 4; ++a) {
            const Float4 xa = x[bend.v[a]];
            q[a] = xa.xyz();
            w[a] = xa.w;
          }
          addBendCorrection(sum, count, q, w, ref.role, loadReadOnly(c.jacobiBendRest + ref.bend),
                            loadReadOnly(c.jacobiBendStiffness + ref.bend));
        }
      bent[v] = count > 0 ? Float4(xv.xyz() + sum * (1.f / float(count)), xv.w) : xv;
    }, "cloth.jacobi.bend");
    previous = current;
    current = bent;
  }
  const float invH2 = 1.f / (h * h);
  float omega = 1.f;
  for (int it = 1; it <= iterations; ++it) {
    omega = chebyshevWeight(it, rho, omega);
    const float w = omega;
    const bool first = it == 1;
    const Float4* x = current;
    Float4* next = previous;
    forEach(d, n, SOAK_LAMBDA(int k) {
      const int v = c.jacobiVertices[k];
      const Float4 xv = x[v];
      if (xv.w == 0.f) {  // pinned or attached: stays where it was put
        next[v] = xv;
        return;
      }
      const Vec3 xi = xv.xyz();
      JacobiSums s;
      for (int e = c.springStart[v], end = c.springStart[v + 1]; e < end; ++e) {
        const JacobiSpring sp = loadReadOnly(c.springs + e);
        addStretchTerm(s, xi, x[sp.other].xyz(), sp.rest, sp.stiffness, sp.unilateral != 0);
      }
      Vec3 xhat = jacobiMinimum(s, target[v].xyz(), invH2 / xv.w);
      // Tethers as hard limits on the Jacobi step's result: their pins do
      // not move during the solve, so the projection needs no other
      // vertex's new position and costs no phase; it carries the pins' hold
      // across the sheet in one iteration (Kim et al. 2012).
      xhat = clampToTethers(c, v, x, xhat);
      // Chebyshev: x_{k+1} = omega (xhat - x_{k-1}) + x_{k-1}.
      const Vec3 before = first ? xhat : next[v].xyz();
      const Vec3 out = before + (xhat - before) * w;
      next[v] = Float4(out, xv.w);
    }, "cloth.jacobi");
    previous = current;
    current = next;
  }
  forEach(d, n, SOAK_LAMBDA(int k) {
    const int v = c.jacobiVertices[k];
    const Float4 x = current[v];
    p.predicted[c.vertexSlot[v]] = x.w == 0.f ? x : Float4(clampToTethers(c, v, current, x.xyz()), x.w);
  }, "cloth.jacobi.scatter");
}

}  // namespace soak

#pragma once
// The cloth constraints of Section 3.2 as stateless projections: given the
// positions and inverse masses of the vertices, return their corrections.
// PBD (Eq. 4 with the per-iteration stiffness of Eq. 5) or XPBD (compliance).
#include "Base/HostDevice.h"
#include "Base/Vec3.h"

namespace soak {

// Stiffness of one constraint. compliance < 0 selects PBD with the
// per-iteration factor kPrime = 1 - (1 - k)^(1/n_s) (Eq. 5); compliance >= 0
// selects XPBD with alpha = compliance (m/N for stretch, 1/(N m) for bend).
struct alignas(8) ConstraintStiffness {
  float kPrime = 1.f;
  float compliance = -1.f;
};

// k made `scale` times as stiff (scale in [0, 1]: softer): PBD's kPrime
// times it, XPBD's compliance over it.
SOAK_INLINE ConstraintStiffness scaledStiffness(ConstraintStiffness k, float scale) {
  if (k.compliance < 0.f) k.kPrime *= scale;
  else k.compliance = scale > 1e-6f ? k.compliance / scale : 1e30f;
  return k;
}

// Mean of a per-vertex factor over a bend's four vertices (1 without one).
SOAK_INLINE float bendScaleOf(const float* perVertex, const int v[4]) {
  return perVertex ? 0.25f * (perVertex[v[0]] + perVertex[v[1]] + perVertex[v[2]] + perVertex[v[3]]) : 1.f;
}

// Eq. 5: the stiffness applied in each of n_s iterations.
SOAK_INLINE float perIterationStiffness(float k, int iterations) {
  return 1.f - powf(1.f - minf(maxf(k, 0.f), 1.f), 1.f / float(iterations > 0 ? iterations : 1));
}

// The multiplier s such that dx_i = s * w_i * grad_i C. `lambda` is the
// XPBD multiplier of this constraint (unused for PBD).
SOAK_INLINE float constraintScale(float C, float sumWGrad2, ConstraintStiffness k, float dt, float& lambda) {
  if (k.compliance < 0.f) {
    if (sumWGrad2 < 1e-20f) return 0.f;
    return -k.kPrime * C / sumWGrad2;
  }
  const float alpha = k.compliance / (dt * dt);
  const float denom = sumWGrad2 + alpha;
  if (denom < 1e-20f) return 0.f;
  const float dLambda = (-C - alpha * lambda) / denom;
  lambda += dLambda;
  return dLambda;
}

// Eq. 8: C = |x1 - x2| - l0. Writes the corrections of both ends.
SOAK_INLINE void projectStretch(Vec3 x1, float w1, Vec3 x2, float w2, float l0, ConstraintStiffness k, float dt,
                                float& lambda, Vec3& dx1, Vec3& dx2) {
  dx1 = dx2 = Vec3(0.f, 0.f, 0.f);
  Vec3 d = x1 - x2;
  float len = length(d);
  if (len < 1e-12f || w1 + w2 == 0.f) return;
  Vec3 n = d / len;  // grad_1 C = n, grad_2 C = -n
  float s = constraintScale(len - l0, w1 + w2, k, dt, lambda);
  dx1 = n * (s * w1);
  dx2 = n * (-s * w2);
}

// Eq. 9: C = acos(n1 . n2) - phi0 for triangles (x1, x3, x2) and (x1, x2, x4),
// n1 = (x2 - x1) x (x3 - x1) / |..|, n2 = (x2 - x1) x (x4 - x1) / |..|.
// The q_i are Mueller et al. 2007's (Appendix A) vectors, which are -grad_i d
// for d = n1 . n2, so grad_i C = q_i / sqrt(1 - d^2) (checked by a test that
// drives the angle to its rest value). Returns false where the gradient is
// undefined (a degenerate triangle, or the pair flat or folded flat).
SOAK_INLINE bool bendGradient(const Vec3 x[4], float phi0, float& C, Vec3 grad[4]) {
  const Vec3 p2 = x[1] - x[0], p3 = x[2] - x[0], p4 = x[3] - x[0];
  Vec3 c23 = cross(p2, p3), c24 = cross(p2, p4);
  float l23 = length(c23), l24 = length(c24);
  if (l23 < 1e-12f || l24 < 1e-12f) return false;
  Vec3 n1 = c23 / l23, n2 = c24 / l24;
  float d = minf(1.f, maxf(-1.f, dot(n1, n2)));
  C = acosf(d) - phi0;
  float sinAngle = sqrtf(maxf(1.f - d * d, 0.f));
  if (sinAngle < 1e-6f) return false;
  grad[2] = (cross(p2, n2) + cross(n1, p2) * d) / l23;
  grad[3] = (cross(p2, n1) + cross(n2, p2) * d) / l24;
  grad[1] = -(cross(p3, n2) + cross(n1, p3) * d) / l23 - (cross(p4, n1) + cross(n2, p4) * d) / l24;
  grad[0] = -grad[1] - grad[2] - grad[3];
  for (int a = 0; a < 4; ++a) grad[a] = grad[a] * (1.f / sinAngle);
  return true;
}

SOAK_INLINE void projectBend(const Vec3 x[4], const float w[4], float phi0, ConstraintStiffness k, float dt,
                             float& lambda, Vec3 dx[4]) {
  for (int a = 0; a < 4; ++a) dx[a] = Vec3(0.f, 0.f, 0.f);
  float C = 0.f;
  Vec3 q[4];
  if (!bendGradient(x, phi0, C, q)) return;
  float sum = 0.f;
  for (int a = 0; a < 4; ++a) sum += w[a] * lengthSquared(q[a]);
  float s = constraintScale(C, sum, k, dt, lambda);
  for (int a = 0; a < 4; ++a) dx[a] = q[a] * (s * w[a]);
}

}  // namespace soak

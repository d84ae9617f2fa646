#pragma once
// The cloth solve of Cloth.model="chebyshev": Jacobi iterations on the
// implicit-Euler energy of the cloth, accelerated by Chebyshev's
// semi-iterative method (Wang 2015, "A Chebyshev semi-iterative approach
// for accelerating projective and position-based dynamics").
//
// One sub-step of length h minimises
//   E(x) = sum_i m_i / (2 h^2) |x_i - y_i|^2 + sum_c k_c / 2 C_c(x)^2
// over the cloth positions x, where y is the predicted (inertial) position
// and the C_c are the stretch constraints of Section 3.2 (Eq. 8) and the
// stretch limits (unilateral; ClothSystem::add), plus a stiff unilateral
// term per collider the vertex is inside (addColliderTerms). Each iteration moves every vertex,
// from the same iterate, to the minimum of its own energy with the others
// held (a Jacobi step), with each term's curvature taken as isotropic, as
// Projective Dynamics does (Bouaziz et al. 2014):
//   x_i <- (m_i/h^2 y_i + sum_c w_c t_c) / (m_i/h^2 + sum_c w_c),
//   t_c = x_i - C_c grad_i C_c / |grad_i C_c|^2,  w_c = k_c |grad_i C_c|^2.
// For a stretch edge t_c is x_j + l0 (x_i - x_j)/|x_i - x_j|, the spring's
// local projection. The step reads only the previous iterate, so all
// vertices of all Jacobi cloths update in one parallel phase, and the
// Chebyshev weights omega_k (chebyshevWeight) take it from Jacobi's
// 1 - O(1/kappa) per iteration to 1 - O(1/sqrt(kappa)). The tethers limit
// each iterate (their pins do not move during the solve).
//
// Bending (Eq. 9) is not a term of the iterations: against inextensible
// stretch its share of a vertex's weighted step is about 1e-5, so it would
// never act (measured: the same strain and shape with and without it, at
// five times the cost on the CPU). It is one Jacobi pass of the paper's PBD
// bend projections per sub-step before the iterations, each vertex moving
// by the mean of its bends' shares, with the paper's stiffness.
#include "Base/HostDevice.h"
#include "Base/Vec3.h"
#include "Cloth/ClothConstraints.h"
#include "Physics/Collider.h"

namespace soak {

// One stretch edge as its vertex sees it: the other end and its rest
// length, in 8 bytes (a phase reads every spring of the cloth, so their
// size is the phase's traffic). A unilateral one (a stretch limit), which
// only pulls when longer than its rest length, holds the rest length
// negated. The stiffness is the cloth's, the same for all of a vertex's
// springs, loaded once a vertex (ClothView::springStiffness).
struct alignas(8) JacobiSpring {
  int other = 0;
  float rest = 0.f;  // < 0: unilateral, with rest length -rest
};
SOAK_INLINE JacobiSpring makeSpring(int other, float rest, bool unilateral) {
  return JacobiSpring{other, unilateral ? -rest : rest};
}
// One bend (Eq. 9) as one of its four vertices sees it: the bend's index in
// the Jacobi bend arrays and which of its vertices this one is (0-3).
struct alignas(8) JacobiBendRef {
  int bend = 0;
  int role = 0;
};

// Stiffness k of a constraint from its compliance alpha (k = 1/alpha);
// compliance 0 (inextensible) is taken as kStiffest, far above any inertia
// term m/h^2 of a cloth vertex (1e-2 kg at h = 1e-4 s: 1e6 N/m).
constexpr float kStiffest = 1e9f;
SOAK_INLINE float stiffnessFromCompliance(float compliance) {
  return compliance > 1.f / kStiffest ? 1.f / compliance : kStiffest;
}

// The weights of Chebyshev's method for spectral radius rho of the plain
// iteration (Wang 2015, Eq. 12): omega_1 = 1, omega_2 = 2 / (2 - rho^2),
// omega_{k+1} = 4 / (4 - rho^2 omega_k). `iteration` counts from 1.
// x_{k+1} = omega_{k+1} (xhat_{k+1} - x_{k-1}) + x_{k-1}.
SOAK_INLINE float chebyshevWeight(int iteration, float rho, float previous) {
  if (iteration <= 1) return 1.f;
  if (iteration == 2) return 2.f / (2.f - rho * rho);
  return 4.f / (4.f - rho * rho * previous);
}

// When the weights apply (Simulation.clothSpectralRadius and
// clothChebyshevDelay): the first `delay` iterations of a sub-step are
// plain Jacobi steps (weight 1), and the weights for rho count from the
// one after, as Wang 2015 starts its weights after S iterations. The first iterations
// of a sub-step move the vertices from the predicted positions onto the
// tethers, the colliders and the stretch limits that pull, a set that
// changes from one iteration to the next; extrapolated, those moves come
// back as motion at the sub-step's end. Without the delay a hanging sheet
// keeps moving from rho 0.8 (kinetic energy 3e-3 of its peak after 5 s,
// 7e-2 at 0.95); with two plain iterations it comes to rest at 0.95
// (3e-6), where the weights take a loaded sheet's worst p99 strain from
// 3.7 % at 0.6 to 2.6 % (Doc/model.md, "Cloth solvers").
struct ChebyshevSchedule {
  float rho = 0.95f;
  int delay = 2;
  // The weight of iteration `iteration` (from 1), `previous` the one before.
  float weight(int iteration, float previous) const {
    return iteration <= delay ? 1.f : chebyshevWeight(iteration - delay, rho, previous);
  }
};

// Accumulates one term of the vertex's energy: target t with weight w.
struct JacobiSums {
  Vec3 weighted{0.f, 0.f, 0.f};
  float weight = 0.f;
  SOAK_HD void add(Vec3 target, float w) {
    weighted += target * w;
    weight += w;
  }
};

// The stretch term of edge (x_i, x_j) at rest length l0 (Eq. 8), or of a
// stretch limit (unilateral: nothing while not longer than l0). Whether a
// limit pulls is decided on the squared length, so the slack ones (most of
// a sheet's about 20 a vertex) cost no square root.
SOAK_INLINE void addStretchTerm(JacobiSums& s, Vec3 xi, Vec3 xj, float rest, float stiffness, bool unilateral) {
  const Vec3 d = xi - xj;
  const float len2 = lengthSquared(d);
  if (len2 < 1e-24f || (unilateral && len2 <= rest * rest)) return;
  s.add(xj + d * (rest / sqrtf(len2)), stiffness);
}

// The term of spring sp, of stiffness k (its cloth's).
SOAK_INLINE void addSpringTerm(JacobiSums& s, Vec3 xi, Vec3 xj, JacobiSpring sp, float k) {
  addStretchTerm(s, xi, xj, fabsf(sp.rest), k, sp.rest < 0.f);
}

// Weight of a collider's term: a contact is as hard as a constraint gets,
// so it outweighs the about 30 stretch terms (each kStiffest) a vertex of
// a sheet may have, and the solve bends the sheet around the collider
// instead of leaving the projection after it to stretch the sheet.
constexpr float kColliderWeight = 100.f * kStiffest;

// The colliders as terms of the energy: for each collider that x_i lies
// inside (closer than the margin r to its surface), a unilateral term
// with target x_i projected onto the surface at margin r (frictionless; the
// projection after the solve applies friction). Without them the solve
// pulls a draped sheet into the collider and the projection after it
// stretches the sheet out again: on the small fig9b the largest per-frame
// 99th-percentile strain is 7.4 % without them and 5.4 % with them
// (Doc/design.md, "A step's cloth stage").
// `before`: the colliders as colliderBefore places them for the sub-step.
SOAK_INLINE void addColliderTerms(JacobiSums& s, Vec3 xi, float r, const Collider* colliders, int count,
                                  float before = 0.f) {
  for (int c = 0; c < count; ++c) {
    Vec3 normal;
    const float gap = colliderDistance(colliderBefore(colliders[c], before), xi, normal) - r;
    if (gap < 0.f) s.add(xi - normal * gap, kColliderWeight);
  }
}

// Vertex `role`'s share of the PBD projection of bend x[0..3] (Eq. 9 with
// the per-sub-step stiffness kPrime of Eq. 5), w the inverse masses; adds
// it to `sum` and counts it (the bend pass averages its bends' shares).
SOAK_INLINE void addBendCorrection(Vec3& sum, int& count, const Vec3 x[4], const float w[4], int role, float phi0,
                                   float kPrime) {
  float C = 0.f;
  Vec3 grad[4];
  if (!bendGradient(x, phi0, C, grad)) return;
  float sumW = 0.f;
  for (int a = 0; a < 4; ++a) sumW += w[a] * lengthSquared(grad[a]);
  if (sumW < 1e-20f) return;
  sum += grad[role] * (-kPrime * C / sumW * w[role]);
  ++count;
}

// A tether: the vertex at most maxLength from its pin (unilateral), applied
// as a projection of the vertex's new position.
SOAK_INLINE Vec3 clampToTether(Vec3 x, Vec3 anchor, float maxLength) {
  const Vec3 d = x - anchor;
  const float len = length(d);
  return len <= maxLength || len < 1e-12f ? x : anchor + d * (maxLength / len);
}

// The Jacobi step's result for a vertex with inertia m/h^2 and predicted y.
SOAK_INLINE Vec3 jacobiMinimum(const JacobiSums& s, Vec3 y, float inertia) {
  return (y * inertia + s.weighted) / (inertia + s.weight);
}

}  // namespace soak

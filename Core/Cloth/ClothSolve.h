#pragma once
// The cloth stages of the step (stateless over particle and cloth arrays).
#include <functional>
#include <vector>

#include "Cloth/ClothSystem.h"
#include "Cloth/SubstepClock.h"
#include "Physics/Collider.h"

namespace soak {

// `iterations` rounds of stretch (Eq. 8) and bend (Eq. 9) projections, one
// colour at a time (Gauss-Seidel between colours, parallel within one),
// with the sub-step's length as XPBD's time step.
void solveClothConstraints(Device d, ParticleView p, ClothView c, const std::vector<int>& stretchColours,
                           const std::vector<int>& bendColours, int iterations, SubstepTime t);

// `iterations` Jacobi-Chebyshev iterations (ClothJacobi.h) over the vertices
// of the chebyshev cloths, for the sub-step under way (t), with the
// Chebyshev weights of `chebyshev`. One dependent phase per iteration.
// The colliders are terms of the energy (ClothJacobi.h, addColliderTerms),
// with each particle's collision radius times collisionRadiusScale as margin.
// With substepStart (per particle slot, the sub-step's start), the result is
// then projected out of the colliders with friction over the sub-step's
// motion from there, as substepCloth does for the other cloths.
void solveClothJacobi(Device d, ParticleView p, ClothView c, int iterations, SubstepTime t, ChebyshevSchedule chebyshev,
                      const Collider* colliders, int colliderCount, float collisionRadiusScale,
                      const Float4* substepStart);

// The cloth contact passes of a (sub-)step, each run with a view whose
// `position` is the sub-step's start or, where the passes skip sub-steps
// (SubstepTime::contactsIn), the end of the last sub-step that ran them:
// the x0 of the contact tests. They run where the clock's contactsDue is 1.
struct ClothContactPasses {
  std::function<void(ParticleView)> separate;  // particle contact: layers pushed apart to their thickness
  std::function<void(ParticleView)> uncross;   // vertex-triangle contact: no vertex crosses a triangle
};

// Buffers of the cloth sub-steps, per particle slot (one sub-step uses none).
struct ClothSubstepScratch {
  Float4* start = nullptr;      // position (and inverse mass) at the start of the sub-step
  Vec3* velocity = nullptr;     // velocity through the sub-steps
  Vec3* velocityFix = nullptr;  // out: end velocity minus (x* - x) / dt; 0 for non-cloth particles
  Float4* contactStart = nullptr;  // the place at the end of the last sub-step that ran the contact passes
  // The velocity the step's first sub-step starts from, kept for a redo of
  // the step's sub-steps (StrainRedo.h); null where no redo can come.
  Vec3* firstVelocity = nullptr;
};

// Work queued after each sub-step, inside the sub-step loop (the strain
// redo's check, StrainRedo.h); empty for none.
using SubstepCheck = std::function<void()>;

// The velocity a cloth vertex leaves the step with: its last sub-step's,
// at most `margin` faster than its mean over the step (0: no limit). The
// last sub-step's velocity is its last motion over h = dt / count: where
// contacts and the solve push a vertex back and forth every sub-step (a
// vertex held between layers), that motion is a fraction of a thickness
// either way and its velocity grows as the sub-steps shorten, up to 15 m/s
// in fig6b's folds at 32 sub-steps (5-15 times the vertex's mean speed),
// where it set the sheet flailing (Doc/model.md, "The end velocity's
// limit"). Smooth motion leaves the step at most a dt / 2 faster than its
// mean under an acceleration a, so the limit only slows vertices that
// gained more; it never speeds one up.
SOAK_INLINE Vec3 clothEndVelocity(Vec3 last, Vec3 mean, float margin) {
  if (margin <= 0.f) return last;
  const float cap = length(mean) + margin, speed = length(last);
  return speed > cap ? last * (cap / speed) : last;
}

// The cloth part of one step in the clock's sub-steps of h = dt / count
// (Macklin et al. 2019, "Small steps in physics simulation"): each sub-step
// integrates gravity over h, moves attached vertices along their collider's
// path, separates touching layers (contacts.separate), runs `iterations`
// constraint rounds with time step h, projects the cloth out of the
// colliders and keeps vertices from crossing triangles (contacts.uncross).
// Separating before the solve leaves the solve's result, not a contact
// push, as the sub-step's shape, and the crossing test stays the last word
// (Doc/design.md, "A step's cloth stage"). With one sub-step (the
// paper's PBD scenes) the free vertices start from the predict stage's x*,
// both contact passes follow the constraints and every particle is
// projected out of the colliders, as the paper's single pass does. The
// strain left by too few iterations grows with the step squared, so K
// sub-steps of n iterations leave far less than one step of K n
// (Doc/model.md, "Cloth sub-steps"). Writes the cloth's predicted positions
// and velocityFix, which finalize adds to (x* - x) / dt so that a cloth
// particle leaves the step with its last sub-step's velocity, no more than
// speedUpMargin (m/s; 0: no limit) faster than its mean over the step
// (Simulation.clothAccelerationLimit).
// The count is the clock's (SubstepClock.h; written on the device, its
// `substep` 0): the sub-steps run as a device loop (Backend/DeviceLoop.h),
// so on the GPU the host need not know it. knownSubsteps: the count where
// the host knows it, else 0; 1 is the paper's single pass. With
// scratch.firstVelocity and a check that may set the clock back (a redo,
// StrainRedo.h), the sub-steps run again from the step's start.
void substepCloth(Device d, ParticleView p, ClothSystem& cloth, const Collider* colliders, int colliderCount,
                  float collisionRadiusScale, Vec3 gravity, SubstepTime t, int knownSubsteps,
                  int iterations, ChebyshevSchedule chebyshev, ClothSubstepScratch scratch,
                  const ClothContactPasses& contacts, const SubstepCheck& check = {}, float speedUpMargin = 0.f);

}  // namespace soak

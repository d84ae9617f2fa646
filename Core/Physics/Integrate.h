#pragma once
// The explicit parts of the step (Algorithm 1, lines 2-3 and the velocity
// update of PBD): stateless functions over particle arrays.
#include "Backend/Device.h"
#include "Physics/Collider.h"
#include "Particles/ParticleState.h"

namespace soak {

// Collision radius as a fraction of the support radius (h = 2 r0, so a
// particle's collision sphere has radius r0 / 2).
constexpr float kCollisionRadiusScale = 0.25f;

// v += dt * g ; x* = x + dt * v  (particles with inverse mass 0 stay put).
// `accel`, if given, is an extra per-particle acceleration added to gravity.
void predictPositions(Device d, ParticleView p, Vec3 gravity, float dt, const Vec3* accel = nullptr);

// Projects predicted positions out of every collider; collision radius of a
// particle is `radiusScale` times its support radius. `clothFrictionScale`
// (per cloth vertex, by the particle's id; null: 1) multiplies the
// colliders' friction against cloth particles. `waterOnly`: cloth
// particles are left where they are (the cloth solve has projected them).
void projectColliders(Device d, ParticleView p, const Collider* colliders, int colliderCount, float radiusScale,
                      float dt, const float* clothFrictionScale = nullptr, bool waterOnly = false);

// x* += delta for each of the `count` particles whose slots are listed in
// `slots` (the cloth's, say) that moves (inverse mass > 0): the second half
// of a Jacobi pass whose corrections were gathered into `delta`.
void applyCorrectionsAt(Device d, ParticleView p, const int* slots, int count, const Vec3* delta, const char* what);

// v = (x* - x) / dt (+ velocityFix, where given: the cloth sub-steps' end
// velocity minus their mean); x = x*.
void updateVelocities(Device d, ParticleView p, float dt, const Vec3* velocityFix = nullptr);

}  // namespace soak

#include "Physics/Integrate.h"

#include "Backend/ForEach.h"
#include "Particles/Phase.h"

namespace soak {

void predictPositions(Device d, ParticleView p, Vec3 gravity, float dt, const Vec3* accel) {
  forEach(d, p.count, SOAK_LAMBDA(int i) {
    Float4 x = p.position[i];
    if (x.w == 0.f) {
      p.predicted[i] = x;
      return;
    }
    Vec3 a = gravity;
    if (accel) a += accel[i];
    Vec3 v = p.velocity[i] + a * dt;
    p.velocity[i] = v;
    p.predicted[i] = Float4(x.xyz() + v * dt, x.w);
  }, "predict");
}

void projectColliders(Device d, ParticleView p, const Collider* colliders, int colliderCount, float radiusScale,
                      float dt, const float* clothFrictionScale, bool waterOnly) {
  if (colliderCount == 0) return;
  forEach(d, p.count, SOAK_LAMBDA(int i) {
    Float4 xp = p.predicted[i];
    if (xp.w == 0.f || (waterOnly && isCloth(p.phase[i]))) return;
    const Vec3 x = p.position[i].xyz();
    const float r = radiusScale * p.radius[i];
    const float friction = clothFrictionScale && isCloth(p.phase[i]) ? clothFrictionScale[p.id[i]] : 1.f;
    p.predicted[i] = Float4(projectOutOfColliders(colliders, colliderCount, x, xp.xyz(), r, dt, friction), xp.w);
  }, "colliders");
}

namespace {
// x*_i += delta_i if particle i moves and has a correction.
SOAK_INLINE void applyCorrection(const ParticleView& p, int i, const Vec3* delta) {
  const Vec3 dx = delta[i];
  const Float4 x = p.predicted[i];
  if (x.w > 0.f && (dx.x != 0.f || dx.y != 0.f || dx.z != 0.f)) p.predicted[i] = Float4(x.xyz() + dx, x.w);
}
}  // namespace

void applyCorrectionsAt(Device d, ParticleView p, const int* slots, int count, const Vec3* delta, const char* what) {
  forEach(d, count, SOAK_LAMBDA(int k) { applyCorrection(p, slots[k], delta); }, what);
}

void updateVelocities(Device d, ParticleView p, float dt, const Vec3* velocityFix) {
  const float inv = 1.f / dt;
  forEach(d, p.count, SOAK_LAMBDA(int i) {
    Float4 x = p.position[i];
    Float4 xp = p.predicted[i];
    Vec3 v = (xp.xyz() - x.xyz()) * inv;
    if (velocityFix) v += velocityFix[i];
    p.velocity[i] = x.w == 0.f ? Vec3(0.f, 0.f, 0.f) : v;
    p.position[i] = xp;
  }, "finalize");
}

}  // namespace soak

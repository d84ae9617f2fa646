#pragma once
// Static or scripted colliders as position constraints (C(x) >= 0 with the
// particle's collision radius as margin), solved by projection.
#include "Base/HostDevice.h"
#include "Base/Vec3.h"

namespace soak {

enum ColliderShape : int { kColliderPlane = 0, kColliderBox = 1, kColliderSphere = 2 };

struct Collider {
  int shape = kColliderPlane;
  Vec3 a;             // plane: point; box: min corner; sphere: centre
  Vec3 b;             // plane: unit normal; box: max corner
  float radius = 0.f; // sphere radius
  float friction = 0.f;  // fraction of tangential motion removed on contact, [0, 1]
  int inside = 0;     // box/sphere: 1 keeps particles inside (a container)
  Vec3 velocity;      // for moving colliders: surface velocity (friction is relative to it)
  Vec3 displacement;  // for moving colliders: translation from the scene's placement
};

// Signed distance from p to the collider surface, positive in the allowed
// region, and the outward normal of the allowed region at the closest point.
SOAK_INLINE float colliderDistance(const Collider& c, Vec3 p, Vec3& normal) {
  if (c.shape == kColliderPlane) {
    normal = c.b;
    return dot(p - c.a, c.b);
  }
  if (c.shape == kColliderSphere) {
    Vec3 d = p - c.a;
    float len = length(d);
    Vec3 n = len > 1e-12f ? d / len : Vec3(0.f, 1.f, 0.f);
    if (c.inside) {
      normal = -n;
      return c.radius - len;
    }
    normal = n;
    return len - c.radius;
  }
  // Box.
  Vec3 center = (c.a + c.b) * 0.5f;
  Vec3 half = (c.b - c.a) * 0.5f;
  Vec3 q = p - center;
  Vec3 d(fabsf(q.x) - half.x, fabsf(q.y) - half.y, fabsf(q.z) - half.z);
  if (c.inside) {
    // Allowed region is the interior: distance to the nearest face, normal inwards.
    float dx = -d.x, dy = -d.y, dz = -d.z;
    if (dx <= dy && dx <= dz) {
      normal = Vec3(q.x > 0.f ? -1.f : 1.f, 0.f, 0.f);
      return dx;
    }
    if (dy <= dz) {
      normal = Vec3(0.f, q.y > 0.f ? -1.f : 1.f, 0.f);
      return dy;
    }
    normal = Vec3(0.f, 0.f, q.z > 0.f ? -1.f : 1.f);
    return dz;
  }
  float outside = length(maxVec(d, Vec3(0.f, 0.f, 0.f)));
  if (outside > 0.f) {
    Vec3 clamped = maxVec(d, Vec3(0.f, 0.f, 0.f));
    Vec3 s(q.x >= 0.f ? 1.f : -1.f, q.y >= 0.f ? 1.f : -1.f, q.z >= 0.f ? 1.f : -1.f);
    normal = normalizedOrZero(Vec3(clamped.x * s.x, clamped.y * s.y, clamped.z * s.z));
    return outside;
  }
  // Inside the solid box: push out through the nearest face.
  if (d.x >= d.y && d.x >= d.z) {
    normal = Vec3(q.x >= 0.f ? 1.f : -1.f, 0.f, 0.f);
    return d.x;
  }
  if (d.y >= d.z) {
    normal = Vec3(0.f, q.y >= 0.f ? 1.f : -1.f, 0.f);
    return d.y;
  }
  normal = Vec3(0.f, 0.f, q.z >= 0.f ? 1.f : -1.f);
  return d.z;
}

// The collider `before` seconds before where the step put it, moved back
// along its velocity: a scripted collider is placed at its path's end-of-step
// point, and a cloth sub-step that ends a fraction `along` into the step sees
// it at dt (1 - along) before that, so that it moves v h each sub-step, as
// the friction below assumes, instead of the whole step's motion in the
// first sub-step (a kick of v dt / h that grows with the sub-steps).
// before <= 0: the collider as placed.
SOAK_INLINE Collider colliderBefore(const Collider& c, float before) {
  if (before <= 0.f) return c;
  Collider moved = c;
  const Vec3 back = c.velocity * before;
  moved.a = c.a - back;
  if (c.shape == kColliderBox) moved.b = c.b - back;  // a plane's b is its normal
  moved.displacement = c.displacement - back;
  return moved;
}

// Projects predicted position xp (previous position x) out of the collider
// with margin r; applies Coulomb-like friction by removing a fraction of the
// tangential displacement. Returns the corrected position.
// frictionScale multiplies the collider's friction (at most 1 in all).
SOAK_INLINE Vec3 projectOutOfCollider(const Collider& c, Vec3 x, Vec3 xp, float r, float dt,
                                      float frictionScale = 1.f) {
  Vec3 n;
  Vec3 corrected;
  if (c.shape == kColliderBox && c.inside) {
    // Exact projection onto the box shrunk by r: clamp each axis (corners too).
    corrected = minVec(maxVec(xp, c.a + Vec3(r, r, r)), c.b - Vec3(r, r, r));
    Vec3 push = corrected - xp;
    if (lengthSquared(push) == 0.f) return xp;
    n = normalizedOrZero(push);
  } else {
    float dist = colliderDistance(c, xp, n);
    if (dist >= r) return xp;
    corrected = xp + n * (r - dist);
  }
  // Friction on the displacement relative to the collider's surface motion.
  Vec3 disp = corrected - x - c.velocity * dt;
  Vec3 tangential = disp - n * dot(disp, n);
  return corrected - tangential * fminf(c.friction * frictionScale, 1.f);
}

// Every collider in turn (each sees the previous one's correction).
// Each collider as colliderBefore places it `before` seconds back (cloth sub-steps; 0: as placed).
SOAK_INLINE Vec3 projectOutOfColliders(const Collider* colliders, int count, Vec3 x, Vec3 xp, float r, float dt,
                                       float frictionScale = 1.f, float before = 0.f) {
  for (int c = 0; c < count; ++c)
    xp = projectOutOfCollider(colliderBefore(colliders[c], before), x, xp, r, dt, frictionScale);
  return xp;
}

}  // namespace soak

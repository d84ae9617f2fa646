#include "Cloth/ClothStep.h"

#include "Cloth/ClothContact.h"
#include "Cloth/ClothSolve.h"
#include "Physics/Integrate.h"

namespace soak {

ClothStep::ClothStep(Device d)
    : device_(d), contactDelta_(d), contactLists_(d), substepStart_(d), substepVelocity_(d), velocityFix_(d) {}

void ClothStep::run(ParticleView p, ClothSystem& cloth, const Collider* colliders, int colliderCount,
                    const ClothStepSettings& s) {
  const ClothView c = cloth.view();
  contactDelta_.resize(p.count);
  // The pairs that may touch during the step, once (ClothContactLists.h).
  contactLists_.build(p, cloth.grid(), c, s.dt, s.sizeLists);
  auto contacts = [&](ParticleView view) {
    resolveClothContacts(device_, view, contactLists_.view(), contactDelta_.data(), s.contactPasses);
    resolveVertexTriangleContacts(device_, view, contactLists_.view(), contactDelta_.data());
  };
  substepped_ = s.substeps > 1;
  if (substepped_) {
    substepStart_.resize(p.count);
    substepVelocity_.resize(p.count);
    velocityFix_.resize(p.count);
    substepCloth(device_, p, cloth, colliders, colliderCount, s.collisionRadiusScale, s.gravity, s.dt, s.substeps,
                 s.iterations, s.spectralRadius, {substepStart_.data(), substepVelocity_.data(), velocityFix_.data()},
                 contacts);
    return;
  }
  moveAttachedVertices(device_, p, c, colliders);
  cloth.resetMultipliers();
  solveClothConstraints(device_, p, c, cloth.edgeColourStart(), cloth.bendColourStart(), s.iterations, s.dt);
  solveClothJacobi(device_, p, c, s.iterations, s.dt, s.spectralRadius);
  // Colliders first, so that contact sees a layer resting on the floor where it is.
  projectColliders(device_, p, colliders, colliderCount, s.collisionRadiusScale, s.dt, c.frictionScale);
  contacts(p);
}

}  // namespace soak

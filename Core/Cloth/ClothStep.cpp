#include "Cloth/ClothStep.h"

#include "Cloth/AdaptiveSubsteps.h"
#include "Cloth/ClothContact.h"
#include "Cloth/ClothSolve.h"
#include "Cloth/CrossingGuard.h"

namespace soak {

ClothStep::ClothStep(Device d)
    : device_(d), contactScratch_(d), contactLists_(d), crossingFlag_(d), substepStart_(d), substepVelocity_(d),
      velocityFix_(d), vertexTravel_(d) {}

void ClothStep::run(ParticleView p, ClothSystem& cloth, const Collider* colliders, int colliderCount,
                    const ClothStepSettings& s) {
  const ClothView c = cloth.view();
  int substeps = s.substeps;
  if (s.substepTravel > 0.f) {
    vertexTravel_.resize(std::size_t(c.vertexCount));
    const float perStep = clothTravelPerStep(device_, p, c, s.dt, vertexTravel_.data());
    substeps = substepsForTravel(perStep, s.substepTravel, s.substeps, s.maxSubsteps);
  }
  lastSubsteps_ = substeps;
  phasesTaken_ += cloth.constraintPhasesPerStep(s.iterations, substeps);
  contactScratch_.resize(p.count);
  if (s.crossingGuardRounds > 0 && crossingFlag_.size() != std::size_t(p.count + s.crossingGuardRounds)) {
    crossingFlag_.resize(std::size_t(p.count + s.crossingGuardRounds));
    crossingFlag_.fillZero();
  }
  // The pairs that may touch during the step, once (ClothContactLists.h).
  contactLists_.build(p, cloth.grid(), c, s.dt, s.sizeLists);
  ClothContactPasses contacts;
  contacts.separate = [&](ParticleView view) {
    resolveClothContacts(device_, view, contactLists_.view(), contactScratch_.data(), s.contactPasses);
  };
  contacts.uncross = [&](ParticleView view) {
    resolveVertexTriangleContacts(device_, view, contactLists_.view());
    revertNewCrossings(device_, view, contactLists_.view(), crossingFlag_.data(), s.crossingGuardRounds);
  };
  substepped_ = substeps > 1;  // one sub-step ends with the velocity (x* - x) / dt: nothing to fix
  if (substepped_) {
    substepStart_.resize(p.count);
    substepVelocity_.resize(p.count);
    velocityFix_.resize(p.count);
  }
  substepCloth(device_, p, cloth, colliders, colliderCount, s.collisionRadiusScale, s.gravity, s.dt, substeps,
               s.iterations, s.spectralRadius, float(s.substeps) / float(substeps),
               {substepStart_.data(), substepVelocity_.data(), velocityFix_.data()}, contacts);
}

}  // namespace soak

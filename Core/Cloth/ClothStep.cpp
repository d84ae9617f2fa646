#include "Cloth/ClothStep.h"

#include <cstring>

#include "Cloth/AdaptiveSubsteps.h"
#include "Cloth/ClothContact.h"
#include "Cloth/ClothSolve.h"
#include "Cloth/CrossingGuard.h"

namespace soak {

ClothStep::ClothStep(Device d)
    : device_(d), contactScratch_(d), contactLists_(d), crossingFlag_(d), substepStart_(d), substepVelocity_(d),
      velocityFix_(d), vertexTravel_(d), maxTravel_(d), travelDownload_(d) {}

ClothStep::~ClothStep() = default;

void ClothStep::measureTravel(ParticleView p, ClothSystem& cloth, float dt) {
  const ClothView c = cloth.view();
  vertexTravel_.resize(std::size_t(c.vertexCount));
  maxTravel_.resize(1);
  measureClothTravel(device_, p, c, dt, vertexTravel_.data(), maxTravel_.data());
  travelMeasured_ = travelDownload_.download({{maxTravel_.data(), sizeof(float)}});
}

float ClothStep::takeTravel(ParticleView p, ClothSystem& cloth, float dt) {
  if (!travelMeasured_) measureTravel(p, cloth, dt);  // a step whose predict stage did not queue it
  travelMeasured_->wait();
  float travel = 0.f;
  std::memcpy(&travel, travelMeasured_->part(0), sizeof(float));
  travelDownload_.recycle(std::move(travelMeasured_));
  return travel;
}

void ClothStep::run(ParticleView p, ClothSystem& cloth, const Collider* colliders, int colliderCount,
                    const ClothStepSettings& s) {
  const ClothView c = cloth.view();
  contactScratch_.resize(p.count);
  if (s.crossingGuardRounds > 0 && crossingFlag_.size() != std::size_t(p.count + s.crossingGuardRounds)) {
    crossingFlag_.resize(std::size_t(p.count + s.crossingGuardRounds));
    crossingFlag_.fillZero();
  }
  // The pairs that may touch during the step, once (ClothContactLists.h).
  contactLists_.build(p, cloth.grid(), c, s.dt, s.sizeLists);
  // The sub-steps, once the device has work queued past predict (AdaptiveSubsteps.h).
  int substeps = s.substeps;
  if (s.substepTravel > 0.f)
    substeps = substepsForTravel(takeTravel(p, cloth, s.dt), s.substepTravel, s.substeps, s.maxSubsteps);
  lastSubsteps_ = substeps;
  phasesTaken_ += cloth.constraintPhasesPerStep(s.iterations, substeps);
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

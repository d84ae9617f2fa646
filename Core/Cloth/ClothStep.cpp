#include "Cloth/ClothStep.h"

#include <algorithm>
#include <cstring>

#include "Cloth/AdaptiveSubsteps.h"
#include "Cloth/ClothContact.h"
#include "Cloth/ClothSolve.h"
#include "Cloth/CrossingGuard.h"

namespace soak {

ClothStep::ClothStep(Device d)
    : device_(d), contactScratch_(d), contactLists_(d), crossingFlag_(d), substepStart_(d), substepVelocity_(d),
      velocityFix_(d), vertexTravel_(d), maxTravel_(d), strainFlags_(d), strainScan_(d), strainCounts_(d),
      travelDownload_(d) {}

ClothStep::~ClothStep() = default;

void ClothStep::measureTravel(ParticleView p, ClothSystem& cloth, float dt, float strainTarget) {
  const ClothView c = cloth.view();
  vertexTravel_.resize(std::size_t(c.vertexCount));
  maxTravel_.resize(1);
  measureClothTravel(device_, p, c, dt, vertexTravel_.data(), maxTravel_.data());
  const ClothSystem::EdgeList edges = cloth.strainEdges();
  strainQueued_ = strainTarget > 0.f && edges.count > 0;
  if (!strainQueued_) {
    travelMeasured_ = travelDownload_.download({{maxTravel_.data(), sizeof(float)}});
    return;
  }
  strainFlags_.resize(2 * std::size_t(edges.count));
  strainScan_.resize(2 * std::size_t(edges.count));
  strainCounts_.resize(2);
  measureClothStrain(device_, p, c.vertexSlot, edges.edges, edges.rest, edges.count, strainTarget,
                     strainFlags_.data(), strainScan_.data(), strainCounts_.data());
  travelMeasured_ = travelDownload_.download(
      {{maxTravel_.data(), sizeof(float)}, {strainCounts_.data(), 2 * sizeof(int)}});
}

ClothStep::Measured ClothStep::takeMeasured(ParticleView p, ClothSystem& cloth, float dt, float strainTarget) {
  if (!travelMeasured_) measureTravel(p, cloth, dt, strainTarget);  // a step whose predict stage did not queue it
  travelMeasured_->wait();
  Measured m;
  std::memcpy(&m.travel, travelMeasured_->part(0), sizeof(float));
  m.strain = strainQueued_;
  if (m.strain) {
    int counts[2];
    std::memcpy(counts, travelMeasured_->part(1), sizeof(counts));
    m.above = counts[0];
    m.aboveQuarter = counts[1];
  }
  travelDownload_.recycle(std::move(travelMeasured_));
  return m;
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
  if (s.substepTravel > 0.f) {
    const Measured m = takeMeasured(p, cloth, s.dt, s.strainTarget);
    substeps = substepsForTravel(m.travel, s.substepTravel, s.substeps, s.maxSubsteps);
    if (m.strain) {
      strainSubsteps_ = substepsForStrain(strainSubsteps_, m.above, m.aboveQuarter, cloth.strainEdges().count,
                                          s.substeps, std::min(s.maxSubsteps, kStrainSubstepsFactor * s.substeps));
      substeps = std::max(substeps, strainSubsteps_.substeps);
    }
  }
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

#include "Cloth/ClothStep.h"

#include <algorithm>

#include "Cloth/AdaptiveSubsteps.h"
#include "Cloth/ClothContact.h"
#include "Cloth/ClothSolve.h"
#include "Cloth/CrossingGuard.h"

namespace soak {

ClothStep::ClothStep(Device d)
    : device_(d), contactScratch_(d), contactLists_(d), crossingFlag_(d), substepStart_(d), contactStart_(d),
      substepVelocity_(d), velocityFix_(d), firstVelocity_(d), clock_(d), vertexTravel_(d), maxTravel_(d), strainFlags_(d),
      strainScan_(d), strainCounts_(d) {
  clock_.upload({SubstepClock{}});
}

ClothStep::~ClothStep() = default;

SubstepClock ClothStep::readClock() const { return clock_.download()[0]; }

void ClothStep::setStrainSubsteps(StrainSubsteps s) {
  SubstepClock k = readClock();
  k.strain = s;
  clock_.upload({k});
}

void ClothStep::measureTravel(ParticleView p, ClothSystem& cloth, float dt, float strainTarget, int fewest,
                              bool stretchOnly) {
  const ClothView c = cloth.view();
  vertexTravel_.resize(std::size_t(c.vertexCount));
  maxTravel_.resize(1);
  measureClothTravel(device_, p, c, dt, vertexTravel_.data(), maxTravel_.data());
  travelQueued_ = true;
  const ClothSystem::EdgeList edges = cloth.strainEdges();
  strainQueued_ = strainTarget > 0.f && edges.count > 0;
  if (!strainQueued_) return;
  strainFlags_.resize(2 * std::size_t(edges.count));
  strainScan_.resize(2 * std::size_t(edges.count));
  strainCounts_.resize(2);
  measureClothStrain(device_, p, c.vertexSlot, edges.edges, edges.rest, edges.count, strainTarget, fewest,
                     stretchOnly, clock_.data(), strainFlags_.data(), strainScan_.data(), strainCounts_.data());
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
  // The sub-steps, chosen on the device (AdaptiveSubsteps.h).
  const bool bySpeed = s.substepTravel > 0.f;
  if (bySpeed && !travelQueued_)  // a predict stage that did not
    measureTravel(p, cloth, s.dt, s.strainTarget, s.substeps, s.strainStretchOnly);
  SubstepChoice choice;
  choice.fewest = s.substeps;
  choice.travel = bySpeed ? s.substepTravel : 0.f;
  choice.most = s.maxSubsteps;
  choice.strainFirst = std::max(s.substeps, s.strainFirstSubsteps);
  const int strainMost = s.strainMaxSubsteps > 0 ? s.strainMaxSubsteps : kStrainSubstepsFactor * choice.strainFirst;
  choice.strainMost = std::min(s.maxSubsteps, strainMost);
  choice.strainEdges = cloth.strainEdges().count;
  choice.contactsBySpeed = s.contactsBySpeed;
  const bool strainRule = bySpeed && strainQueued_;
  chooseClothSubsteps(device_, clock_.data(), maxTravel_.data(), strainRule ? strainCounts_.data() : nullptr, choice);
  travelQueued_ = strainQueued_ = false;
  phasesPerSubstep_ = cloth.constraintPhasesPerStep(s.iterations, 1);
  // The count where the host knows it. One sub-step is the paper's single
  // pass: where the count may be 1, the host reads it.
  int known = bySpeed ? 0 : s.substeps;
  if (bySpeed && s.substeps < 2) known = readClock().substeps;
  const bool oneSubstep = known == 1;
  ClothContactPasses contacts;
  const int* due = &clock_.data()->contactsDue;  // SubstepTime::contactsIn, written by each sub-step
  contacts.separate = [&](ParticleView view) {
    resolveClothContacts(device_, view, contactLists_.view(), contactScratch_.data(), s.contactPasses, due);
  };
  contacts.uncross = [&](ParticleView view) {
    resolveVertexTriangleContacts(device_, view, contactLists_.view(), due);
    revertNewCrossings(device_, view, contactLists_.view(), crossingFlag_.data(), s.crossingGuardRounds, due);
  };
  substepped_ = !oneSubstep;  // one sub-step ends with the velocity (x* - x) / dt: nothing to fix
  if (substepped_) {
    substepStart_.resize(p.count);
    contactStart_.resize(p.count);
    substepVelocity_.resize(p.count);
    velocityFix_.resize(p.count);
  }
  // The strain redo (StrainRedo.h), where the strain rule chooses the count.
  const bool redo = substepped_ && strainRule && s.strainRedo > 0.f;
  SubstepCheck check;
  if (redo) {
    firstVelocity_.resize(p.count);
    const ClothSystem::EdgeList edges = cloth.strainEdges();
    const StrainRedoCheck bound{edges.edges, edges.rest, edges.count, s.strainRedo * s.strainTarget,
                                choice.strainMost, s.strainStretchOnly};
    check = [this, p, c, bound] { checkStrainRedo(device_, p, c.vertexSlot, bound, clock_.data()); };
  }
  substepCloth(device_, p, cloth, colliders, colliderCount, s.collisionRadiusScale, s.gravity,
               SubstepTime{clock_.data(), s.dt, s.substeps}, known, s.iterations,
               s.chebyshev,
               {substepStart_.data(), substepVelocity_.data(), velocityFix_.data(), contactStart_.data(),
                redo ? firstVelocity_.data() : nullptr},
               contacts, check, 0.5f * s.accelerationLimit * s.dt);
}

}  // namespace soak

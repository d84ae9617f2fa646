#pragma once
// The core's cloth.solve stage: the cloth's constraints, colliders and
// contacts for one step, in one or more sub-steps (ClothSolve.h), with
// the buffers it keeps between steps (the contact candidates, the
// sub-steps' scratch). Reads and writes the particles' x* through `p`.
#include <memory>

#include "Backend/Buffer.h"
#include "Backend/DownloadQueue.h"
#include "Cloth/AdaptiveSubsteps.h"
#include "Cloth/ClothContactLists.h"
#include "Cloth/ClothSystem.h"
#include "Physics/Collider.h"

namespace soak {

struct ClothStepSettings {
  float dt = 0.f;
  Vec3 gravity;
  int substeps = 1;          // Simulation.clothSubsteps (the fewest, with substepTravel)
  float substepTravel = 0.f; // Simulation.clothSubstepTravel: > 0, sub-steps from the speed (AdaptiveSubsteps.h)
  int maxSubsteps = 1;       // Simulation.clothMaxSubsteps
  float strainTarget = 0.f;  // Simulation.clothStrainTarget: > 0 (with substepTravel), sub-steps from the strain (AdaptiveSubsteps.h)
  int iterations = 1;        // Simulation.clothIterations: constraint rounds per (sub-)step
  float spectralRadius = 0;  // Simulation.clothSpectralRadius (chebyshev)
  int contactPasses = 2;     // particle contact passes per (sub-)step
  int crossingGuardRounds = 0;  // rounds of the crossing guard per (sub-)step (CrossingGuard.h)
  float collisionRadiusScale = 1.f;
  bool sizeLists = false;    // a step that sizes neighbour lists exactly (Simulation::sizeListsNow)
};

class ClothStep {
 public:
  explicit ClothStep(Device d);
  ~ClothStep();
  // With Simulation.clothSubstepTravel: queues the measurement of how far
  // the cloth travels this step (AdaptiveSubsteps.h) from the velocities
  // the predict stage left, for run() to read without waiting on the
  // stages in between. The predict stage calls it.
  // With Simulation.clothStrainTarget as well, the strain the step before
  // left (AdaptiveSubsteps.h), in the same copy.
  void measureTravel(ParticleView p, ClothSystem& cloth, float dt, float strainTarget);
  void run(ParticleView p, ClothSystem& cloth, const Collider* colliders, int colliderCount,
           const ClothStepSettings& s);
  // After a sub-stepped run: per slot, the velocity the last sub-step left
  // minus (x* - x) / dt, which finalize adds (ClothSolve.h); else null.
  const Vec3* velocityFix() const { return substepped_ ? velocityFix_.data() : nullptr; }
  // Sub-steps of the latest run(), and the dependent constraint phases of
  // all runs together (ClothSystem::constraintPhasesPerStep).
  int lastSubsteps() const { return lastSubsteps_; }
  // The sub-steps the strain asks for (AdaptiveSubsteps.h; 0 before the
  // first step): state a checkpoint keeps.
  StrainSubsteps strainSubsteps() const { return strainSubsteps_; }
  void setStrainSubsteps(StrainSubsteps s) { strainSubsteps_ = s; }
  long long phasesTaken() const { return phasesTaken_; }

 private:
  Device device_;
  Buffer<Float4> contactScratch_;  // the particle contact passes' second buffer of x*
  ClothContactLists contactLists_;
  Buffer<int> crossingFlag_;  // the crossing guard's flags (CrossingGuard.h), 0 between sub-steps
  Buffer<Float4> substepStart_;
  Buffer<Vec3> substepVelocity_, velocityFix_;
  // What measureTravel queued: the largest travel, and the strain counts
  // where it measured the strain.
  struct Measured {
    float travel = 0.f;
    bool strain = false;
    int above = 0, aboveQuarter = 0;
  };
  Measured takeMeasured(ParticleView p, ClothSystem& cloth, float dt, float strainTarget);
  Buffer<float> vertexTravel_;  // per vertex, AdaptiveSubsteps.h
  Buffer<float> maxTravel_;     // one float: the largest
  Buffer<int> strainFlags_, strainScan_, strainCounts_;  // measureClothStrain's
  bool strainQueued_ = false;
  StrainSubsteps strainSubsteps_;
  DownloadQueue travelDownload_;
  std::unique_ptr<DownloadQueue::Transfer> travelMeasured_;  // queued by measureTravel, read by run
  bool substepped_ = false;
  int lastSubsteps_ = 0;
  long long phasesTaken_ = 0;
};

}  // namespace soak

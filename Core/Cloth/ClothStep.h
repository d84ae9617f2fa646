#pragma once
// The core's cloth.solve stage: the cloth's constraints, colliders and
// contacts for one step, in one or more sub-steps (ClothSolve.h), with
// the buffers it keeps between steps (the contact candidates, the
// sub-steps' scratch). Reads and writes the particles' x* through `p`.
#include <memory>

#include "Backend/Buffer.h"
#include "Cloth/AdaptiveSubsteps.h"
#include "Cloth/StrainRedo.h"
#include "Cloth/SubstepClock.h"
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
  bool contactsBySpeed = false;  // Simulation.clothContactsBySpeed
  float accelerationLimit = 0.f;  // Simulation.clothAccelerationLimit (ClothSolve.h): 0, none
  int strainMaxSubsteps = 0; // Simulation.clothStrainMaxSubsteps: the strain's most; 0: kStrainSubstepsFactor x first
  int strainFirstSubsteps = 0;  // the strain rule's count before it has measured (0: substeps; ClothSolverDefaults.h)
  float strainTarget = 0.f;  // Simulation.clothStrainTarget: > 0 (with substepTravel), sub-steps from the strain (AdaptiveSubsteps.h)
  bool strainStretchOnly = false;  // Simulation.clothStrainStretchOnly
  float strainRedo = 0.f;    // Simulation.clothStrainRedo: > 0 (with strainTarget), the redo's bound over the target (StrainRedo.h)
  int iterations = 1;        // Simulation.clothIterations: constraint rounds per (sub-)step
  ChebyshevSchedule chebyshev;  // Simulation.clothSpectralRadius and clothChebyshevDelay
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
  // the predict stage left, on the device, for run() to choose the step's
  // sub-steps from. The predict stage calls it.
  // With Simulation.clothStrainTarget as well, the strain the step before
  // left (AdaptiveSubsteps.h); `fewest` is Simulation.clothSubsteps,
  // `stretchOnly` Simulation.clothStrainStretchOnly.
  void measureTravel(ParticleView p, ClothSystem& cloth, float dt, float strainTarget, int fewest, bool stretchOnly);
  // Chooses the step's sub-steps on the device (SubstepClock.h) and runs
  // them. The host reads the count only where it may be 1 (sub-steps from
  // the speed with Simulation.clothSubsteps 1: one sub-step is the paper's
  // single pass) or where the sub-steps cannot stay on the device (the
  // CPU; a GPU step run stage by stage).
  void run(ParticleView p, ClothSystem& cloth, const Collider* colliders, int colliderCount,
           const ClothStepSettings& s);
  // After a sub-stepped run: per slot, the velocity the last sub-step left
  // minus (x* - x) / dt, which finalize adds (ClothSolve.h); else null.
  const Vec3* velocityFix() const { return substepped_ ? velocityFix_.data() : nullptr; }
  // Sub-steps of the latest run() (0 before the first), and the dependent
  // constraint phases of all runs together
  // (ClothSystem::constraintPhasesPerStep). Each reads the clock: a host
  // wait on the GPU.
  int lastSubsteps() const { return readClock().substeps; }
  // Of those, the sub-steps that ran the contact passes (SubstepTime::contactsIn;
  // chooseClothSubsteps keeps it within [1, substeps]).
  int lastContactSubsteps() const { return readClock().contactSubsteps; }
  long long phasesTaken() const { return readClock().taken * phasesPerSubstep_; }
  // The latest run's sub-step count in device memory, for a copy that does
  // not wait (FrameCopy.h).
  const int* substepCount() const { return &clock_.data()->substeps; }
  // The sub-steps the strain asks for (AdaptiveSubsteps.h; 0 before the
  // first step): state a checkpoint keeps.
  StrainSubsteps strainSubsteps() const { return readClock().strain; }
  void setStrainSubsteps(StrainSubsteps s);

 private:
  SubstepClock readClock() const;
  Device device_;
  Buffer<Float4> contactScratch_;  // the particle contact passes' second buffer of x*
  ClothContactLists contactLists_;
  Buffer<int> crossingFlag_;  // the crossing guard's flags (CrossingGuard.h), 0 between sub-steps
  Buffer<Float4> substepStart_, contactStart_;
  Buffer<Vec3> substepVelocity_, velocityFix_, firstVelocity_;
  Buffer<SubstepClock> clock_;  // one
  Buffer<float> vertexTravel_;  // per vertex, AdaptiveSubsteps.h
  Buffer<float> maxTravel_;     // one float: the largest
  Buffer<int> strainFlags_, strainScan_, strainCounts_;  // measureClothStrain's
  bool travelQueued_ = false, strainQueued_ = false;  // what measureTravel queued this step
  bool substepped_ = false;
  long long phasesPerSubstep_ = 0;
};

}  // namespace soak

#pragma once
#include <optional>
#include <string>

#include "Base/Vec3.h"
#include "Fluid/WaterSettings.h"
#include "Output/CatalystSettings.h"
#include "Output/OutputSettings.h"

namespace soak {

// What one run may take (Doc/reliability.md, "Resource limits"): values in
// range whose product is absurd (a time step of 1e-30 s, a support radius
// of 10 m around particles 2 cm apart) are refused before anything runs,
// with a message naming the limit. Raised with <Simulation> attributes.
struct ResourceLimits {
  // Most particles a run may hold, counting every particle its nozzles
  // would emit up to the run's end as if none drained away. 0: as many as
  // the device's memory holds at Simulation::kEstimatedBytesPerParticle.
  long long maxParticles = 0;
  // Most time steps between two output frames.
  long long maxStepsPerFrame = 100000;
  // Most particles one neighbour-grid cell (edge: the largest support
  // radius) may hold at rest spacing: water (h / r0)^3, a cloth sheet
  // (h / edge)^2. A neighbour query visits 27 cells.
  long long maxCellParticles = 4096;
};

// Global settings from <Simulation>. Defaults are the paper's Table 1.
struct SimulationSettings {
  double timeStep = 0.015;     // s (kernels take it as float)
  double duration = 4.0;       // s of simulated time
  double frameRate = 30.0;     // output frames per simulated second
  Vec3 gravity{0.f, -9.81f, 0.f};
  float maxSpeed = 50.f;       // m/s; a faster particle is an instability
  // The cloth solver's counts; 0 (travel < 0): the solver's own, which
  // Simulation::initialize puts in their place (ClothSolverDefaults.h).
  int clothIterations = 0;     // n_s of the cloth constraints (Eq. 5), per cloth sub-step
  int clothSubsteps = 0;       // cloth sub-steps per step (Doc/model.md, "Cloth sub-steps"); the fewest with clothSubstepTravel
  float clothSubstepTravel = -1.f;  // > 0: sub-steps from the cloth's speed (Cloth/AdaptiveSubsteps.h)
  int clothMaxSubsteps = 32;   // the most sub-steps clothSubstepTravel may ask for
  bool clothContactsBySpeed = true;  // contact passes in as many sub-steps as the travel asks for (AdaptiveSubsteps.h)
  float clothAccelerationLimit = -1.f;  // m/s^2: a sub-stepped cloth vertex leaves a step at most A dt / 2 faster than its mean (Cloth/ClothSolve.h); 0: no limit; < 0: the solver's own
  int clothStrainMaxSubsteps = 0;  // the most sub-steps the strain asks for; 0: kStrainSubstepsFactor x the first
  // Not a parameter: the strain rule's first count where the solver chose
  // the sub-steps (ClothSolverDefaults.h); 0: clothSubsteps.
  int clothStrainFirstSubsteps = 0;
  bool clothStrainStretchOnly = false;  // the strain rule counts stretch alone, not compression (AdaptiveSubsteps.h)
  float clothStrainTarget = -1.f;  // > 0, with clothSubstepTravel: sub-steps from the strain left (Cloth/AdaptiveSubsteps.h); < 0: the solver's own
  float clothStrainRedo = 1.5f;  // > 0, with the strain rule: a step past this times the target is redone (Cloth/StrainRedo.h)
  float clothSpectralRadius = 0.95f;  // rho of the chebyshev cloth solve (Cloth/ClothJacobi.h)
  int clothChebyshevDelay = 2;        // plain Jacobi iterations before its Chebyshev weights (ChebyshevSchedule)
  int couplingPasses = 2;      // passes of the water-triangle constraint per step (n_s of Eq. 5 for it)
  int contactPasses = 2;       // passes of cloth contact (self and cloth-cloth) per step
  int crossingGuardRounds = 0; // rounds of the cloth crossing guard per sub-step (Cloth/CrossingGuard.h)
  bool cudaGraph = true;       // GPU: each step's work replayed as CUDA graphs (Doc/design.md, "Step graphs")
  Vec3 domainMin{-1e3f, -1e3f, -1e3f};  // water leaving this box is drained
  Vec3 domainMax{1e3f, 1e3f, 1e3f};
  std::optional<WaterSurfaceSettings> surface;  // a water surface mesh per frame where set (<WaterSurface>)
  ResourceLimits limits;
  OutputSettings output;        // <Output>
  CatalystSettings catalyst;    // <Catalyst>, and `soak run --catalyst/--live` added to it
  std::string where;            // <Simulation>'s file:line (empty when the scene has none)
};

}  // namespace soak

#pragma once
#include <memory>
#include <string>
#include <vector>

#include "Backend/Buffer.h"
#include "Backend/DownloadQueue.h"
#include "Checkpoint/CheckpointState.h"
#include "Cloth/ClothSystem.h"
#include "Cloth/VertexFields.h"
#include "Fluid/FluidSolver.h"
#include "Neighbours/NeighbourGrid.h"
#include "Output/FrameSource.h"
#include "Particles/ParticleState.h"
#include "Physics/Collider.h"
#include "Pipeline/Pipeline.h"
#include "Registry/Module.h"
#include "Simulation/Settings.h"
#include "Simulation/ClothSolverDefaults.h"
#include "Simulation/Stages/CoreStages.h"

namespace soak {

class StateWriter;
class StateReader;

// Where a module comes from: its element's file:line, and whether a plugin
// declares that element.
struct ModuleOrigin {
  std::string where;
  bool plugin = false;
};

// Everything one run holds: settings, particles, the neighbour grid,
// colliders, the modules made from the scene, and the step pipeline.
class Simulation final : public CheckpointState, public FrameSource {
 public:
  explicit Simulation(Device device);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  Device device() const { return device_; }

  // Takes ownership of the modules made from the scene, in scene order.
  void addModule(std::unique_ptr<Module> module, ModuleOrigin origin = {});
  // configure (every module), setup (the core's elements, then the
  // plugins': a plugin's element may stand anywhere in the scene and still
  // find the cloth and water the core's elements make), then the pipeline:
  // core stages, then each module's, placed once their anchors are in
  // (Pipeline::collectFor). Checkpoints and stats keep scene order.
  void initialize();
  // One time step.
  void step(bool profile = false);

  // Counts stay on the device: a step waits for the device (hostWaits())
  // only on maintenance steps, those whose index is a multiple of
  // maintenanceInterval (the first step among them, and a step after a
  // checkpoint is loaded is no different from the uninterrupted run's). There the drain stage compacts,
  // the fluid's neighbour lists are sized exactly, and modules read their
  // device counters back (Module::beforeStep sees maintenanceStep()).
  int maintenanceInterval = 16;
  bool maintenanceStep() const;
  // Whether neighbour lists (the fluid's, the wet cloth's) are sized this
  // step: on maintenance steps, and on the CPU in every step, where waiting
  // for the device costs nothing, so no particle goes without a list. Tests
  // turn sizeListsEveryStepOnCpu off to see on the CPU what the GPU does.
  bool sizeListsEveryStepOnCpu = true;
  bool sizeListsNow() const { return maintenanceStep() || (device_ == Device::Cpu && sizeListsEveryStepOnCpu); }
  // Drops the removed slots (drained mass into drainedWaterMass, in the
  // particles' order otherwise): the drain stage does it on maintenance steps.
  void compact();

  // The stats.csv row of the current state (FrameCopy.h's frameStats, from
  // a copy the host waits for).
  StatsRow collectStats();
  // The modules made from the scene, in scene order.
  const std::vector<std::unique_ptr<Module>>& modules() const { return modules_; }

  // Checkpoints: step counter, water budget, particles and every module's
  // state. loadState expects a simulation built from the same scene
  // (initialize() done) and refuses one that does not match.
  void saveState(StateWriter& out) const override;
  void loadState(StateReader& in) override;

  SimulationSettings settings;
  // Cloth models the scene's <Cloth> elements ask for, noted while the
  // settings are read (ClothSolverDefaults.h).
  ClothModelsUsed clothModelsUsed;
  WaterSettings water;
  ParticleState particles;
  NeighbourGrid grid;
  std::vector<Collider> colliders;  // host copy; uploaded when changed
  std::vector<std::string> colliderNames;  // parallel to colliders ("" if unnamed)
  ClothSystem cloth;
  FluidSolver fluid;
  Pipeline pipeline;
  // Sink boxes (min, max): water inside is removed and counted as drained.
  std::vector<std::pair<Vec3, Vec3>> sinks;
  // Per-cloth-vertex fields shared by name (Cloth/VertexFields.h): the
  // coupling stage reads field::kCouplingStiffness, WetCloth writes it.
  VertexFields vertexFields;

  // Check for an instability after every stage (slow; names the stage).
  // Throws InstabilityError.
  bool checkStages = false;

  long long stepIndex() const { return stepIndex_; }
  double time() const { return time_; }
  // Cloth sub-steps of the latest step, and dependent cloth constraint phases
  // of all steps of this object (Simulation.clothSubstepTravel makes both
  // vary; Cloth/AdaptiveSubsteps.h). Each reads the count from the device:
  // a host wait on the GPU.
  int lastClothSubsteps() const { return stages_.cloth.lastSubsteps(); }
  int lastClothContactSubsteps() const { return stages_.cloth.lastContactSubsteps(); }
  // The latest step's cloth sub-steps in device memory (FrameCopy.h).
  const int* clothSubstepCount() const { return stages_.cloth.substepCount(); }
  long long clothPhasesTaken() const { return stages_.cloth.phasesTaken(); }
  // Largest support radius of any particle (cell size of the grid). Modules
  // that add particles with a larger radius must raise it.
  float maxSupportRadius() const { return maxSupportRadius_; }
  void raiseSupportRadius(float r) {
    if (r > maxSupportRadius_) maxSupportRadius_ = r;
  }
  // Refuses (InputError at `where`) to add `added` particles when the run
  // would hold more than particleBudget(). `added` is a double so that no
  // count can overflow on its way here.
  void checkParticleBudget(double added, const std::string& what, const std::string& where) const;
  // Simulation.maxParticles, or as many as the memory the run may take on
  // its device (deviceMemoryBudget: the process's limits on the CPU, the
  // free memory on the GPU) holds at about kEstimatedBytesPerParticle each (Doc/performance.md measures
  // 316-913), at most kMaxParticles.
  double particleBudget() const;
  // Refuses a run to `endTime` whose emitters (Module::plannedParticles)
  // would take it past particleBudget(), before anything is written.
  void checkPlannedParticles(double endTime) const;
  // Refuses a grid cell that would hold more than
  // settings.limits.maxCellParticles at rest spacing (ResourceLimits).
  void checkCellOccupancy() const;
  // Most pairs neighbour lists keyed by `keys` particles can need: the
  // candidates of 27 cells at maxCellParticles each, with a factor 16 for
  // water packed above its rest density and the lists' headroom. A
  // checkpoint's list sizing beyond it is refused (a forged size would
  // otherwise allocate at will).
  double maxListCapacity(int keys) const {
    return double(keys + 1) * 27.0 * 16.0 * double(settings.limits.maxCellParticles);
  }
  static constexpr long long kEstimatedBytesPerParticle = 512;
  static constexpr long long kMaxParticles = 200000000LL;

  // Marks the collider list changed so it is uploaded before the next step.
  void collidersChanged() { collidersDirty_ = true; }
  const Collider* deviceColliders() const { return colliderBuffer_.data(); }
  // What the fluid's passes read (valid from the neighbours stage on).
  FluidContext fluidContext() const;

  // FrameSource (Output/FrameWriter.h): Simulation/FrameCopy.h does the work.
  Device frameDevice() const override { return device_; }
  OutputLayout outputLayout() const override;
  FrameCopy startFrameCopy(DownloadQueue& queue) override;
  FrameData finishFrameCopy(FrameCopy&& copy, DownloadQueue& queue) const override;
  StatsRow frameStats(const FrameData& frame) const override;

  // Water mass removed by sinks or by leaving the domain (kg), as of the
  // last compaction; collectStats() adds the removed slots not yet compacted.
  double drainedWaterMass = 0.0;
  // Water mass added by emitters after the start (kg).
  double emittedWaterMass = 0.0;
  // Serial numbers for new water particles (the `id` array).
  int nextWaterId = 0;

 private:
  // Moved colliders to the device: by a kernel's parameters (no wait).
  void writeColliders();
  Device device_;
  CoreStageState stages_;  // the core stages' own buffers (Stages/CoreStages.h)
  Buffer<float> instabilityScratch_;
  Buffer<int> removeFlag_;  // compact()
  Buffer<float> removedMass_;
  std::vector<std::unique_ptr<Module>> modules_;
  std::vector<ModuleOrigin> origins_;  // by module
  std::unique_ptr<DownloadQueue> statsDownloads_;  // collectStats()
  Buffer<Collider> colliderBuffer_;
  bool collidersDirty_ = true;
  long long stepIndex_ = 0;
  double time_ = 0.0;
  float maxSupportRadius_ = 0.f;
};

}  // namespace soak

#pragma once
#include <string>
#include <utility>
#include <vector>

#include "Backend/DownloadQueue.h"
#include "Output/FrameData.h"

namespace soak {

class Simulation;
class Pipeline;
class StateWriter;
class StateReader;

// One row of stats.csv, filled column by column (order is kept).
class StatsRow {
 public:
  void add(const std::string& column, double value) { values_.emplace_back(column, value); }
  const std::vector<std::pair<std::string, double>>& values() const { return values_; }
  double get(const std::string& column) const;

 private:
  std::vector<std::pair<std::string, double>> values_;
};

// Particles an emitter would add by a time (Simulation::checkPlannedParticles).
struct PlannedParticles {
  double count = 0.0;
  std::string what, where;  // e.g. "<Nozzle>", its file:line
};

// What a scene element becomes. A module may change settings, create
// particles and meshes, add stages to the step, and add stats columns.
// Every hook is optional.
class Module {
 public:
  virtual ~Module() = default;
  // First pass over all modules, in scene order: settings only.
  virtual void configure(Simulation&) {}
  // Second pass: create particles, cloth, colliders.
  virtual void setup(Simulation&) {}
  // Third pass: add stages relative to the named anchors of the step.
  virtual void addStages(Pipeline&, Simulation&) {}
  // Stats columns of an output frame. Runs on a frame writer thread while
  // the simulation steps on, so it reads only `frame` (the frame's host
  // copies; frame.modules[its index] holds what statsSources named) and
  // what setup fixed, never the simulation's live state.
  virtual void addStats(const FrameData& /*frame*/, const FrameData::ModuleCopies& /*own*/, StatsRow&) const {}
  // Device memory the stats read besides the particle arrays and channels
  // (counters, say), copied with every frame. Called on the stepping thread.
  virtual std::vector<DownloadQueue::Part> statsSources(Simulation&) { return {}; }
  // Called before every step (host side, e.g. to move a scripted collider).
  virtual void beforeStep(Simulation&) {}
  // Emitters: how many particles they would add from now to `endTime` (s),
  // so that a run that would outgrow its budget is refused before it starts.
  virtual PlannedParticles plannedParticles(const Simulation&, double /*endTime*/) const { return {}; }
  // Checkpoints (soak run --checkpoint-every, --resume): state that changes
  // during the run and lives outside the particle arrays and their channels
  // (counters, particles queued for the next step). Read back in the order
  // written; a module that keeps no such state writes nothing.
  virtual void saveState(StateWriter&) const {}
  virtual void loadState(StateReader&) {}
};

}  // namespace soak

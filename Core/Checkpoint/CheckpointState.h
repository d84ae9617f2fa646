#pragma once
// What a checkpoint saves and restores besides the output writer's state:
// the simulation implements it (Simulation::saveState / loadState), so
// checkpoint files need nothing else of it.
namespace soak {

class StateWriter;
class StateReader;

class CheckpointState {
 public:
  virtual void saveState(StateWriter& out) const = 0;
  // Expects the state of a run built from the same scene; refuses any other
  // with InputError.
  virtual void loadState(StateReader& in) = 0;

 protected:
  ~CheckpointState() = default;
};

}  // namespace soak

// Simulation's part of a checkpoint (Checkpoint/Checkpoint.h writes the file).
#include <typeinfo>

#include "Checkpoint/StateStream.h"
#include "Neighbours/PairListsState.h"
#include "Simulation/Simulation.h"

namespace soak {

void Simulation::saveState(StateWriter& out) const {
  out.putString("simulation");
  out.put<std::int64_t>(stepIndex_);
  out.put<double>(drainedWaterMass);
  out.put<double>(emittedWaterMass);
  out.put<std::int32_t>(nextWaterId);
  out.put<std::int32_t>(cloth.vertexCount());
  particles.saveState(out);
  putListSizing(out, fluid.neighbourListSizing());
  out.put<std::int32_t>(static_cast<std::int32_t>(modules_.size()));
  for (const auto& m : modules_) {
    const Module& module = *m;
    out.putString(typeid(module).name());
    module.saveState(out);
  }
}

void Simulation::loadState(StateReader& in) {
  in.expect("simulation");
  const long long step = in.get<std::int64_t>();
  if (step < 0) in.fail("negative step index");
  const double drained = in.get<double>(), emitted = in.get<double>();
  const int nextId = in.get<std::int32_t>();
  const int clothVertices = in.get<std::int32_t>();
  if (clothVertices != cloth.vertexCount())
    in.fail("it was written for " + std::to_string(clothVertices) + " cloth vertices, the scene makes " +
            std::to_string(cloth.vertexCount()) + " (did a mesh change?)");
  particles.loadState(in);
  const FluidListSizing lists = getListSizing(in, "neighbour list");
  const int moduleCount = in.get<std::int32_t>();
  if (moduleCount != int(modules_.size()))
    in.fail("it was written for " + std::to_string(moduleCount) + " scene elements, the scene has " +
            std::to_string(modules_.size()));
  for (auto& m : modules_) {
    Module& module = *m;
    const std::string kind = in.getString();
    if (kind != typeid(module).name()) in.fail("scene element of kind '" + kind + "' where the scene has another");
    module.loadState(in);
  }
  stepIndex_ = step;
  time_ = double(stepIndex_) * settings.timeStep;
  drainedWaterMass = drained;
  emittedWaterMass = emitted;
  nextWaterId = nextId;
  fluid.setNeighbourListSizing(lists);
  cloth.updateSlots(particles.view());
  collidersDirty_ = true;
}

}  // namespace soak

#pragma once
// The core's stages, one file each in this folder, and their table
// (CoreStageTable.cpp: the step's order). A stage takes the simulation's
// named parts and hands explicit views of them to the code that does the
// work (Physics/, Fluid/, Cloth/, Coupling/); the buffers only a stage uses
// live in CoreStageState.
#include "Backend/Buffer.h"
#include "Cloth/ClothStep.h"

namespace soak {

class Pipeline;
class Simulation;

struct CoreStageState {
  explicit CoreStageState(Device d) : cloth(d), couplingMoved(d), sinkCorners(d) {}
  ClothStep cloth;            // cloth.solve (its contact lists and sub-step buffers); finalize reads its velocity fix
  Buffer<int> couplingMoved;  // coupling: which water its last pass moved
  Buffer<Vec3> sinkCorners;   // drain: (min, max) of each sink box
};

void runPredict(CoreStageState& state, Simulation& sim);     // Predict.cpp
void runDrain(CoreStageState& state, Simulation& sim);       // Drain.cpp
void runNeighbours(CoreStageState& state, Simulation& sim);  // Neighbours.cpp
void runFluidSolve(CoreStageState& state, Simulation& sim);  // FluidSolve.cpp
void runClothSolve(CoreStageState& state, Simulation& sim);  // ClothSolve.cpp
void runCollide(CoreStageState& state, Simulation& sim);     // Collide.cpp
void runCoupling(CoreStageState& state, Simulation& sim);    // Coupling.cpp
void runFinalize(CoreStageState& state, Simulation& sim);    // Finalize.cpp

// Appends the core's stages to `pipeline`, in the step's order; `state` must
// outlive it.
void addCoreStages(Pipeline& pipeline, CoreStageState& state);

}  // namespace soak

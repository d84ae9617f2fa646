// The step's core stages, in order (Algorithm 1 of the paper, with the
// cloth's own solve between the fluid's and the colliders).
#include "Pipeline/Pipeline.h"
#include "Pipeline/StageNames.h"
#include "Simulation/Stages/CoreStages.h"

namespace soak {

namespace {
struct CoreStageRow {
  const char* name;
  void (*run)(CoreStageState&, Simulation&);
};

const CoreStageRow kCoreStages[] = {
    {stage::kPredict, runPredict},
    // Before the grid is built, so that removing particles never leaves a stale grid.
    {stage::kDrain, runDrain},
    {stage::kNeighbours, runNeighbours},
    {stage::kFluidSolve, runFluidSolve},
    {stage::kClothSolve, runClothSolve},
    {stage::kCollide, runCollide},
    {stage::kCoupling, runCoupling},
    {stage::kFinalize, runFinalize},
};
}  // namespace

void addCoreStages(Pipeline& pipeline, CoreStageState& state) {
  for (const CoreStageRow& row : kCoreStages) {
    CoreStageState* s = &state;
    auto run = row.run;
    pipeline.append({row.name, [s, run](Simulation& sim) { run(*s, sim); }});
  }
}

}  // namespace soak

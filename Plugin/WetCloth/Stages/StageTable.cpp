// The wetting stages in the order of Algorithm 1: after the cloth solve the
// volumes and saturations (which the core's coupling stage reads as
// kappa_couple), then absorption, diffusion, emission, sticking, and
// drying (beyond the paper). A new stage: its file in Stages/, and a row.
#include "Pipeline/StageNames.h"
#include "Pipeline/StageTable.h"
#include "Stages/WetStages.h"
#include "WetState.h"

namespace soak::wet {

void runVolume(WetState&, Simulation&);   // Stages/Volume.cpp
void runAbsorb(WetState&, Simulation&);   // Stages/Absorb.cpp
void runDiffuse(WetState&, Simulation&);  // Stages/Diffuse.cpp
void runEmit(WetState&, Simulation&);     // Stages/Emit.cpp
void runStick(WetState&, Simulation&);    // Stages/Stick.cpp
void runDry(WetState&, Simulation&);      // Stages/Dry.cpp

namespace {
const StageRow<WetState> kWetStages[] = {
    {kVolumeStage, Place::Before, stage::kCoupling, runVolume},
    {kAbsorbStage, Place::After, stage::kCoupling, runAbsorb},
    {kDiffuseStage, Place::After, kAbsorbStage, runDiffuse},
    {kEmitStage, Place::After, kDiffuseStage, runEmit},
    {kStickStage, Place::After, kEmitStage, runStick},
    {kDryStage, Place::After, kStickStage, runDry, [](const WetState& s) { return s.drying.fluxIntoDryAir > 0.f; }},
};
}  // namespace

void addWetStages(Pipeline& pipeline, WetState& state) { addStageTable(pipeline, state, kWetStages); }

}  // namespace soak::wet

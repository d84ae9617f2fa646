// The wetting stages in the order of Algorithm 1: after the cloth solve the
// volumes and saturations (which the core's coupling stage reads as
// kappa_couple), then absorption, diffusion, emission, sticking, and
// drying (beyond the paper); sticking as a force after the core's
// finalize. A new stage: its file in Stages/, and a row.
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
    // Eq. 20 as a force acts on the velocities finalize has set; as a
    // correction, on the positions before it (WetParams.h, StickForm).
    {kStickStage, Place::After, kEmitStage, runStick,
     [](const WetState& s) { return s.w.stickForm == StickForm::Correction; }},
    {kStickStage, Place::After, stage::kFinalize, runStick,
     [](const WetState& s) { return s.w.stickForm == StickForm::Force; }},
    {kDryStage, Place::After, kStickStage, runDry, [](const WetState& s) { return s.drying.fluxIntoDryAir > 0.f; }},
};
}  // namespace

void addWetStages(Pipeline& pipeline, WetState& state) { addStageTable(pipeline, state, kWetStages); }

}  // namespace soak::wet

#pragma once
// The wetting stages of a step, one file each (Stages/<Stage>.cpp), and
// the table that places them (Stages/StageTable.cpp).
#include "Pipeline/Pipeline.h"

namespace soak::wet {

struct WetState;

// Stage names other plugins may anchor on.
inline constexpr const char* kVolumeStage = "wet.volume";
inline constexpr const char* kAbsorbStage = "wet.absorb";
inline constexpr const char* kDiffuseStage = "wet.diffuse";
inline constexpr const char* kEmitStage = "wet.emit";
inline constexpr const char* kStickStage = "wet.stick";
inline constexpr const char* kDryStage = "wet.dry";

// Inserts the stages the scene switches on (WetClothModule::addStages).
void addWetStages(Pipeline& pipeline, WetState& state);

}  // namespace soak::wet

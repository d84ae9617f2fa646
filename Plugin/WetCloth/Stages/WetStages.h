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

// Particle channels WetCloth adds (per slot; water's entries stay 0), which
// other plugins may read and write by name (ParticleState::findChannel):
// held water and buffered water (kg) of each cloth particle, its
// saturation S (Eq. 10) and volume V (m^3).
inline constexpr const char* kHeldWaterChannel = "held_water";
inline constexpr const char* kBufferChannel = "buffer";
inline constexpr const char* kSaturationChannel = "saturation";
inline constexpr const char* kVolumeChannel = "volume";

// Inserts the stages the scene switches on (WetClothModule::addStages).
void addWetStages(Pipeline& pipeline, WetState& state);

}  // namespace soak::wet

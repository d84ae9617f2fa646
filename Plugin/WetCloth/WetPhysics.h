#pragma once
// The wetting stages' physics (paper Section 4, Algorithm 1 lines 11-25) as
// plain functions over particle arrays: each runs on the CPU and on the GPU.
// Each is defined in its stage's file, Stages/<Stage>.cpp, and takes the
// scratch it needs by name.
#include "Cloth/ClothNeighbours.h"
#include "Cloth/ClothSystem.h"
#include "Cloth/ForEachClothParticle.h"
#include "Neighbours/GridView.h"
#include "Particles/ParticleState.h"
#include "WetParams.h"

namespace soak::wet {

// Where the wetting state lives. Per slot (particle channels, so they follow
// the grid's reordering): held water (kg) and buffered excess water (kg) of
// cloth particles, their saturation and volume; per cloth vertex:
// kappa_couple (Eq. 22, read by the core's coupling stage) and the dry
// particle mass.
struct WetArrays {
  float* held = nullptr;
  float* buffer = nullptr;
  float* saturation = nullptr;
  float* volume = nullptr;
  float* kappaCouple = nullptr;
  float* bendScale = nullptr;      // per vertex, the core's field::kBendStiffnessScale (null: not made)
  float* frictionScale = nullptr;  // per vertex, the core's field::kFrictionScale (null: not made)
  const float* dryMass = nullptr;
  ClothSlots cloth;  // the cloth particles' slots: the cloth-side passes walk these only
  GridView clothGrid;  // the grid over the cloth particles alone: queries for cloth neighbours use it
  // Cloth-cloth lists of this step (Cloth/ClothNeighbours.h): the passes from
  // the porosity update to sticking walk them instead of clothGrid.
  ClothNeighbourView clothNeighbours;
};

// The water particle the model was set up with (m0, h0) and gravity.
struct WaterReference {
  float mass = 0.0082f, supportRadius = 0.04f;
  Vec3 gravityDir{0.f, -1.f, 0.f};
  float gravity = 9.81f;
};

// wet.volume: V_i (Eq. 10's volume), water above S^EW moved from the fabric
// to the buffer (Section 4.4), S_i, kappa_couple per vertex (Eq. 22), the
// particle mass m_dry + held + buffer (wet weight), and where they are made,
// the bend stiffness and friction factors of wet cloth.
void updatePorosity(Device d, ParticleView p, WetArrays a, const WetParams& w);

// wet.absorb (Eq. 11): water particles give water to the cloth particles
// around them; partial absorption shrinks a particle's mass and radius,
// whole absorption sets its mass to 0 (the core drains it next step).
struct AbsorbScratch {  // per slot
  float* scale = nullptr;  // cloth: the share of its wish a cloth particle may take (room left)
  float* ratio = nullptr;  // water: the share of each cloth particle's ask it can give
  float* asked = nullptr;  // water: what the cloth around asks of it
};
void absorbWater(Device d, ParticleView p, GridView g, WetArrays a, const WetParams& w, WaterReference ref,
                 float dt, AbsorbScratch s);

// wet.diffuse (Eq. 12-17): the saturation constraint, conservative or
// literal, over diffusionSchedule(w, dt)'s passes.
struct DiffusionScratch {  // per slot
  float* alpha = nullptr;  // alpha_i of Eq. 16
  float* limit = nullptr;  // the share of its outflow a donor can give
  float* next = nullptr;   // held water after the pass
};
void diffuseWater(Device d, ParticleView p, WetArrays a, const WetParams& w, WaterReference ref, float dt,
                  DiffusionScratch s);

// The diffusion passes' last kernel: held water becomes `next` (the values a
// pass computed), and the saturation follows (Eq. 10).
void applyHeldWater(Device d, WetArrays a, const float* next, float c, const char* stage);

// wet.emit, first half (Eq. 18): where gravity overcomes the saturation
// difference above, bufferFlowRate x dt of a buffer (all of it in one of
// the paper's steps) moves to the cloth particles below. due[v] (per
// cloth item, ClothSlots order) becomes 1 where the buffer now holds at
// least m_threshold: a drip is due there (takeDripMass).
struct TransferScratch {  // per slot
  float* out = nullptr;   // buffer mass a donor gives this step
  float* norm = nullptr;  // sum of its receivers' weights
};
void transferBuffers(Device d, ParticleView p, WetArrays a, const WetParams& w, WaterReference ref,
                     float dt, int* due, TransferScratch s);

// Where a drip starts: its cloth particle's predicted position and velocity.
struct DripSource {
  Vec3 position;
  Vec3 velocity;
};

// The drips' bookkeeping, in device memory: the step never reads it back
// (the plugin does on maintenance steps and for stats).
struct DripCounters {
  int pending = 0;          // drips taken this step, made at the start of the next
  int largestStep = 0;      // most drips due in one step since the plugin last looked
  long long spawned = 0;    // drips taken since the start
  long long deferred = 0;   // drips due but left for a later step for want of room
};

// Drips are due where a cloth buffer holds at least m_threshold (`due`, per
// cloth item, as transferBuffers marked it). The first `room` of them in
// slot order take m_threshold from their buffer and leave their source in
// sources[0..pending); the others keep it and drip in a later step.
// `offsets` is scratch of as many ints as there are cloth particles.
// Nothing waits for the device.
void takeDripMass(Device d, ParticleView p, WetArrays a, const WetParams& w, int room, int* due, int* offsets,
                  DripSource* sources, DripCounters* counters);

// What a drip is, besides where it starts (Section 4.4): mass m_threshold,
// radius (m / m0)^(1/3) h0, `below` added to its source's position.
struct DripShape {
  Vec3 below;
  float mass = 0.f, radius = 0.f;
  int firstId = 0;
};
// Fills the `room` slots appended at `first` (ParticleState::appendSlots):
// the first counters->pending become the drips taken last step (serial
// numbers firstId + k), the rest removed slots; then nothing is pending.
void placeDrips(Device d, ParticleView p, int first, int room, const DripSource* sources, const DripShape& shape,
                DripCounters* counters);

// wet.emit, second half (Eq. 19): cloth attracts water particles lighter
// than m0 (drips and partly absorbed particles), as a position change
// dt^2 f / m.
void attractDrips(Device d, ParticleView p, GridView g, WetArrays a, const WetParams& w, WaterReference ref,
                  float dt);

// wet.stick (Eq. 20): touching cloth particles of different layers attract,
// most at S^T: dt^2 f / m, added to the positions (StickForm::Correction)
// or, over dt, to the velocities (StickForm::Force). `delta`: scratch per
// slot (the correction's).
void stickWetCloth(Device d, ParticleView p, ClothView c, WetArrays a, const WetParams& w, float dt, Vec3* delta);

}  // namespace soak::wet

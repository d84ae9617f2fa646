#pragma once
// The wetting stages (paper Section 4, Algorithm 1 lines 11-25) as plain
// functions over particle arrays: each runs on the CPU and on the GPU.
#include "Cloth/ClothSystem.h"
#include "Cloth/ForEachClothParticle.h"
#include "Neighbours/GridView.h"
#include "Particles/ParticleState.h"
#include "WetParams.h"

namespace soak::wet {

// Where the wetting state lives. Per slot (particle channels, so they follow
// the grid's reordering): held water (kg) and buffered excess water (kg) of
// cloth particles, their saturation and volume; per slot scratch; per cloth
// vertex: kappa_couple (Eq. 22, read by the core's coupling stage) and the
// dry particle mass.
struct WetArrays {
  float* held = nullptr;
  float* buffer = nullptr;
  float* saturation = nullptr;
  float* volume = nullptr;
  float* scratchA = nullptr;
  float* scratchB = nullptr;
  float* scratchC = nullptr;
  Vec3* delta = nullptr;
  float* kappaCouple = nullptr;
  const float* dryMass = nullptr;
  ClothSlots cloth;  // the cloth particles' slots: the cloth-side passes walk these only
  GridView clothGrid;  // the grid over the cloth particles alone: queries for cloth neighbours use it
};

// The water particle the model was set up with (m0, h0) and gravity.
struct WaterReference {
  float mass = 0.0082f, supportRadius = 0.04f;
  Vec3 gravityDir{0.f, -1.f, 0.f};
  float gravity = 9.81f;
};

// wet.volume: V_i (Eq. 10's volume), water above S^EW moved from the fabric
// to the buffer (Section 4.4), S_i, kappa_couple per vertex (Eq. 22), and the
// particle mass m_dry + held + buffer (wet weight).
void updatePorosity(Device d, ParticleView p, GridView g, WetArrays a, const WetParams& w);

// wet.absorb (Eq. 11): water particles give water to the cloth particles
// around them; partial absorption shrinks a particle's mass and radius,
// whole absorption sets its mass to 0 (the core drains it next step).
void absorbWater(Device d, ParticleView p, GridView g, WetArrays a, const WetParams& w, WaterReference ref);

// wet.diffuse (Eq. 12-17): the saturation constraint, conservative or literal.
void diffuseWater(Device d, ParticleView p, GridView g, WetArrays a, const WetParams& w, WaterReference ref);

// wet.emit, first half (Eq. 18): buffers move to the cloth particles below
// where gravity overcomes the saturation difference above.
void transferBuffers(Device d, ParticleView p, GridView g, WetArrays a, const WetParams& w, WaterReference ref);

// Takes m_threshold from every buffer that holds at least that much; `spawn`
// gets 1 where a drip is due (the caller creates the particles) and
// `offsets` its exclusive scan (the drip's index). Returns the number of
// drips.
int takeDripMass(Device d, ParticleView p, WetArrays a, const WetParams& w, int* spawn, int* offsets);

// Where a drip starts: its cloth particle's predicted position and velocity.
struct DripSource {
  Vec3 position;
  Vec3 velocity;
};
// Packs the sources of the drips flagged by takeDripMass, in slot order, so
// that only they cross to the host (not whole particle arrays).
void gatherDripSources(Device d, ParticleView p, const int* spawn, const int* offsets, DripSource* out);

// wet.emit, second half (Eq. 19): cloth attracts water particles lighter
// than m0 (drips and partly absorbed particles), as a position change
// dt^2 f / m.
void attractDrips(Device d, ParticleView p, GridView g, WetArrays a, const WetParams& w, WaterReference ref,
                  float dt);

// wet.stick (Eq. 20): touching cloth particles of different layers attract,
// most at S^T, as a position change dt^2 f / m.
void stickWetCloth(Device d, ParticleView p, GridView g, ClothView c, WetArrays a, const WetParams& w, float dt);

}  // namespace soak::wet

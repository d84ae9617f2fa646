#pragma once
// What the wetting stages share over a run: the parameters, the particle
// channels and per-vertex arrays they read and write, the cloth-cloth
// lists, the drips' bookkeeping, and scratch memory that each stage takes
// under its own names (absorbScratch(), ...). WetClothModule owns it and
// sets it up; the stages (Stages/) run on it.
#include <memory>

#include "Backend/Buffer.h"
#include "Cloth/ClothNeighbours.h"
#include "Drying.h"
#include "Stages/FickDiffusion.h"
#include "WetParams.h"
#include "WetPhysics.h"

namespace soak {
class Simulation;
}

namespace soak::wet {

struct WetState {
  WetParams w;
  DryingParams drying;
  WaterReference ref;
  bool initialised = false;  // w.initialSaturation given (at the first wet.volume)

  // Particle channels (indices) and per-vertex arrays.
  int held = -1, buffer = -1, saturation = -1, volume = -1;
  int evaporated = -1;    // water each particle gave to the air (drying on)
  Buffer<float> dryMass;  // per vertex
  Buffer<float> vertexArea;         // per vertex: rest area (drying on)
  float* kappa = nullptr;           // the core's field::kCouplingStiffness
  float* bendScale = nullptr;       // the core's field::kBendStiffnessScale (wetBendSoftening > 0)
  float* frictionScale = nullptr;   // the core's field::kFrictionScale (wetFriction > 0)
  std::unique_ptr<ClothNeighbours> clothNeighbours;  // built in wet.volume

  // Drips (Stages/Emit.cpp): taken in wet.emit, placed at the next step's start.
  static constexpr int kMinDripRoom = 8;
  Buffer<int> due, dripOffset;
  Buffer<DripSource> dripSources;
  Buffer<DripCounters> dripCounters;
  int dripRoom = kMinDripRoom;  // drips one step may take
  int dripRoomCap = kMinDripRoom;
  int takenRoom = 0;  // the room the last step took drips with: slots to append next step

  // Every buffer on `d`, sized for nothing yet.
  explicit WetState(Device d);
  // The arrays of this step (scratch sized for the particles).
  WetArrays arrays(Simulation& sim);
  // Each stage's scratch, under its names; the stages run one at a time and
  // share the memory.
  AbsorbScratch absorbScratch() { return {pool_[0].data(), pool_[1].data(), pool_[2].data()}; }
  DiffusionScratch diffusionScratch() { return {pool_[0].data(), pool_[1].data(), pool_[2].data()}; }
  FickScratch fickScratch() { return {pool_[0].data(), pool_[1].data(), pool_[2].data()}; }
  TransferScratch transferScratch() { return {pool_[0].data(), pool_[1].data()}; }
  Vec3* stickDelta() { return delta_.data(); }
  // Every cloth particle starts holding w.initialSaturation V / c of water.
  void setInitialSaturation(Simulation& sim);

 private:
  Buffer<float> pool_[3];
  Buffer<Vec3> delta_;
};

}  // namespace soak::wet

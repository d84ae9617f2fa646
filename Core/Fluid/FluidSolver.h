#pragma once
// Position Based Fluids (paper Eq. 6-7) with cloth particles as boundary
// particles (Akinci et al. 2012), written as mass-weighted PBD so that water
// particles of different masses and radii (partial absorption, drips) stay
// symmetric and momentum conserving. See Doc/model.md, "Water".
#include "Backend/Buffer.h"
#include "Cloth/ForEachClothParticle.h"
#include "Fluid/FluidNeighbours.h"
#include "Fluid/WallDensity.h"
#include "Neighbours/GridView.h"
#include "Particles/ParticleState.h"
#include "Physics/Collider.h"
#include "Fluid/WaterSettings.h"

namespace soak {

// What the fluid's passes read besides the particles: the step's grid
// (valid from the neighbours stage on), the water's settings, the time
// step, the colliders (device memory) and the cloth's friction field
// against them (per cloth vertex; null: 1).
struct FluidContext {
  GridView grid;
  WaterSettings water;
  float dt = 0.f;
  const Collider* colliders = nullptr;
  int colliderCount = 0;
  const float* clothFrictionScale = nullptr;
};

class FluidSolver {
 public:
  // The neighbour lists' sizing (FluidNeighbours.h), for checkpoints and tests.
  FluidListSizing neighbourListSizing() const { return neighbours_.sizing(); }
  void setNeighbourListSizing(const FluidListSizing& s) { neighbours_.setSizing(s); }
  // Particles of the last solve that had no list (a download; for tests).
  int particlesWithoutNeighbourList() const { return neighbours_.particlesWithoutList(); }
  explicit FluidSolver(Device device);
  // Rest-lattice constants (the relaxation's reference denominator).
  void configure(const WaterSettings& water);
  // Volume V_k = 1 / sum_l W_kl of every cloth particle over the particles
  // of its own cloth (Akinci; the paper's V_i of Eq. 10) and its boundary
  // mass psi_k = rho0 V_k. Valid after the neighbour stage of a step.
  void computeBoundaryVolumes(ParticleView p, GridView clothGrid, ClothSlots cloth);
  // The density constraint, `water.iterations` times; each iteration also
  // projects the colliders. With `sizeLists` (a maintenance step) the
  // neighbour lists' buffer is sized exactly (PairLists.h).
  void solve(ParticleState& particles, const FluidContext& f, bool sizeLists);
  // XSPH viscosity and vorticity confinement on the new velocities.
  void applyViscosity(ParticleView p, const FluidContext& f);
  // Relative compression max(0, rho/rho0 - 1) of water particles at the
  // current positions: mean and max (reductions: the host waits).
  void densityError(ParticleView p, const FluidContext& f, double& mean, float& max);
  // The same per slot (0 for other particles), in device scratch that stays
  // valid until the solver's next call; queued, nothing waits. Null without
  // particles.
  const float* compressionPerParticle(ParticleView p, const FluidContext& f);

  const float* boundaryVolume() const { return volume_.data(); }
  // Density of each slot from the last solver iteration (kg/m^3).
  std::vector<float> downloadDensity(int count) const;
  // The same in device memory: densitySlots() slots (at most the particle count).
  const float* density() const { return density_.data(); }
  std::size_t densitySlots() const { return density_.size(); }

 private:
  void resize(int n);
  Device device_;
  float restDenominator_ = 1.f;  // G0: sum_j |grad W|^2 over a full rest lattice
  WallDensityTable wall_;
  Buffer<float> lambda_, density_, volume_, scratch_;
  Buffer<Vec3> omega_;
  // Per slot: x* of the next iteration during solve() (its passes swap it
  // with the particles' x*), the new velocity (xyz) in applyViscosity().
  Buffer<Float4> spare_;
  Buffer<Float4> attributes_;  // per particle during solve(): h, m / m0, boundary psi, kind (FluidSolver.cpp)
  FluidNeighbours neighbours_;
};

}  // namespace soak

#pragma once
#include "Base/Vec3.h"

namespace soak {

// Global settings from <Simulation>. Defaults are the paper's Table 1.
struct SimulationSettings {
  double timeStep = 0.015;     // s (kernels take it as float)
  double duration = 4.0;       // s of simulated time
  double frameRate = 30.0;     // output frames per simulated second
  Vec3 gravity{0.f, -9.81f, 0.f};
  float maxSpeed = 50.f;       // m/s; a faster particle is an instability
  int clothIterations = 8;     // n_s of the cloth constraints (Eq. 5), per cloth sub-step
  int clothSubsteps = 1;       // cloth sub-steps per step (Doc/model.md, "Cloth sub-steps")
  float clothSpectralRadius = 0.6f;   // rho of the chebyshev cloth solve (Cloth/ClothJacobi.h)
  Vec3 domainMin{-1e3f, -1e3f, -1e3f};  // water leaving this box is drained
  Vec3 domainMax{1e3f, 1e3f, 1e3f};
  float surfaceCellSize = 0.f;  // m; > 0: write a water surface mesh per frame (<WaterSurface>)
  float surfaceIso = 0.5f;      // relative density of that surface
};

// Water particle defaults from <Water> (Table 1).
struct WaterSettings {
  float spacing = 0.02f;        // r0, m
  float supportRadius = 0.04f;  // h, m
  float restDensity = 1000.f;   // kg/m^3
  float particleMass = 0.0082f; // kg
  int iterations = 8;           // PBF solver iterations per step
  float relaxation = 0.2f;      // epsilon of lambda, relative to the rest-lattice denominator
  float artificialPressure = 0.001f;  // k of s_corr, in units of a full density error
  float artificialPressureRadius = 0.2f;  // delta q / h
  float viscosity = 0.01f;      // XSPH c
  float vorticity = 0.0f;       // vorticity confinement epsilon, m/s
  float neighbourSkin = 0.1f;   // fluid neighbour lists keep pairs within (1 + skin) h (FluidNeighbours.h)
};

}  // namespace soak

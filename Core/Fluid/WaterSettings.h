#pragma once
#include <string>

namespace soak {

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
  std::string where;            // <Water>'s file:line (empty when the scene has none)
};

}  // namespace soak

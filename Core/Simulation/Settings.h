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
};

// Water particle defaults from <Water> (Table 1).
struct WaterSettings {
  float spacing = 0.02f;        // r0, m
  float supportRadius = 0.04f;  // h, m
  float restDensity = 1000.f;   // kg/m^3
  float particleMass = 0.0082f; // kg
};

}  // namespace soak

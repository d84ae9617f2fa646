#pragma once
#include <cstring>
#include <vector>

#include "Base/Vec3.h"

namespace soak {

// One output frame on the host: the particle arrays in slot order and what
// its stats row reads. Frame writer threads build the frame's files and its
// stats.csv row from it while the simulation steps on (FrameCopy.h).
struct FrameData {
  long long step = 0;
  double time = 0.0;
  std::vector<Float4> position;
  std::vector<Vec3> velocity;
  std::vector<float> mass, radius;
  std::vector<int> phase, id;
  std::vector<float> density;      // from the last solver iteration (kg/m^3)
  std::vector<float> compression;  // max(0, rho/rho0 - 1) at the frame's positions; empty at step 0
  std::vector<std::vector<float>> channels;  // ParticleState's channels, by index
  // Water budget (Simulation::drainedWaterMass, emittedWaterMass).
  double drainedWaterMass = 0.0, emittedWaterMass = 0.0;
  int clothSubsteps = 0;  // cloth sub-steps of the step before the frame (0 before the first)

  // What one module asked to be copied with the frame
  // (Module::statsSources), in the order it asked.
  struct ModuleCopies {
    std::vector<std::vector<unsigned char>> parts;
    // Part k as one T (T trivially copyable, as the device held it).
    template <class T>
    T as(std::size_t k) const {
      T v{};
      if (k < parts.size() && parts[k].size() == sizeof(T)) std::memcpy(&v, parts[k].data(), sizeof(T));
      return v;
    }
  };
  std::vector<ModuleCopies> modules;  // by module, in scene order
};

}  // namespace soak

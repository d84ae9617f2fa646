#pragma once
// Instability detection: a particle whose position, predicted position or
// velocity is not finite, or that moves faster than Simulation.maxSpeed.
// The runner checks once per frame, before the frame is written, so every
// frame on disk is sound; `soak run --check-stages` checks after every stage
// to name the stage where it first appears.
#include <stdexcept>
#include <string>

#include "Backend/Buffer.h"
#include "Base/Vec3.h"

namespace soak {

class Simulation;

struct Instability {
  bool found = false;
  std::string stage;   // empty when checked between steps
  long long step = 0;  // steps done when found (the step that went wrong is step + 1 when `stage` is set)
  double time = 0.0;
  int id = -1;         // the particle's id (water serial number or cloth vertex)
  bool cloth = false;
  bool finite = true;
  Vec3 position, velocity;
  float speed = 0.f;
};

// One pass and one reduction on the device; downloads only when something is found.
Instability findInstability(Simulation& sim, Buffer<float>& scratch, const std::string& stage = {});

// "step 12 (t = 0.180 s), after stage fluid.solve: water particle 345 at
// (x, y, z) moves at 73.2 m/s, above Simulation.maxSpeed = 50 m/s".
std::string describeInstability(const Instability& s, float maxSpeed);

class InstabilityError : public std::runtime_error {
 public:
  explicit InstabilityError(const Instability& s, const std::string& message)
      : std::runtime_error(message), instability(s) {}
  Instability instability;
};

}  // namespace soak

#pragma once
// The simulation's own per-particle arrays as they lie in memory (CPU or
// GPU), for sharing without copies: pointers, shapes and strides, in slot
// order. No Python type here. They stay where they are until the next
// step: a step reorders the slots and may move the arrays.
#include <cstdint>
#include <string>
#include <vector>

#include "Simulation/Simulation.h"

namespace soak {

struct SharedArray {
  std::string name;
  void* data = nullptr;
  bool integer = false;         // int32, else float32
  std::int64_t rows = 0;
  std::int64_t columns = 0;     // 0: one value per particle, shape (rows,)
  std::int64_t rowStride = 1;   // elements (4 bytes each) from one row to the next
  bool writable = false;
};

// position (n, 3), velocity (n, 3), inverse_mass, mass, radius, phase, id,
// then the channels; position, velocity and the channels are writable, as
// for setField. position and inverse_mass are views of one float4 array.
std::vector<SharedArray> sharedArrays(Simulation& sim);

}  // namespace soak

#pragma once
// Per-particle arrays of a simulation as host copies, by name, and writes
// back: what the Python module's get/set, water() and cloth() serve. No
// Python type here, so that the module can call these without the GIL.
#include <string>
#include <vector>

#include "Simulation/Simulation.h"

namespace soak {

// One array: float or int values, `components` per row.
struct HostArray {
  std::string name;
  int components = 1;
  bool integer = false;
  std::vector<float> values;
  std::vector<int> ints;
  std::size_t rows() const { return (integer ? ints.size() : values.size()) / std::size_t(components); }
};

// position, velocity, inverse_mass, mass, radius, density, phase, id, then
// the channels. Of these, position, velocity and the channels are writable.
std::vector<std::string> arrayFieldNames(Simulation& sim);
// In slot order. std::invalid_argument for an unknown name (the list is in
// the message).
HostArray getField(Simulation& sim, const std::string& field);
// `rows` x `cols` floats in slot order; std::invalid_argument for a field
// that cannot be written or a shape that does not fit.
void setField(Simulation& sim, const std::string& field, const float* data, std::size_t rows, std::size_t cols);

// The water particles sorted by id: position, velocity, mass, radius,
// density, id.
std::vector<HostArray> waterArrays(Simulation& sim);
std::vector<std::string> clothNames(const Simulation& sim);
// One cloth in vertex order: position, velocity, each channel, triangles.
std::vector<HostArray> clothArrays(Simulation& sim, const std::string& name);
void setClothField(Simulation& sim, const std::string& name, const std::string& field, const float* data,
                   std::size_t rows, std::size_t cols);

}  // namespace soak

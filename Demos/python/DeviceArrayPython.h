#pragma once
// soak.DeviceArray: one of a simulation's own arrays (SharedArrays.h),
// shared without a copy through __cuda_array_interface__ (v3) and DLPack on
// the GPU, and through __array_interface__ and DLPack on the CPU. A handle
// is valid until the simulation's arrays may move (a step, a run, close):
// used after that it raises soak.StaleArrayError.
#include <pybind11/pybind11.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "SharedArrays.h"

namespace soak {

// Bumped, under the simulation's lock, before anything that may move its
// arrays; a handle remembers the value it was made at.
struct ArrayGeneration {
  std::atomic<std::uint64_t> value{0};
  void bump() { value.fetch_add(1); }
};

// Registers soak.DeviceArray and soak.StaleArrayError.
void addDeviceArrayClass(pybind11::module_& m);

// The dict sim.device_arrays() returns, name -> DeviceArray, in the order of
// `arrays`. Every handle keeps `owner` (the Python Simulation) alive.
pybind11::dict makeDeviceArrays(const std::vector<SharedArray>& arrays, Device device, long long stepIndex,
                                std::uint64_t generation, const std::shared_ptr<ArrayGeneration>& current,
                                const pybind11::object& owner);

}  // namespace soak

#pragma once
// forEach(device, n, f): calls f(i) for i in [0, n) on the chosen device.
//
// The same call site runs an OpenMP loop on the CPU and a kernel on the GPU,
// which is how physics is written once ("one source, two machines"). A file
// that calls forEach with Device::Cuda must be compiled by nvcc: list it with
// soak_physics_sources() in CMake. f must only write to index i (or to
// disjoint places) so that results do not depend on thread count or order.
#include <stdexcept>

#include "Backend/Device.h"
#include "Base/HostDevice.h"

namespace soak {

#if defined(__CUDACC__)
template <class F>
__global__ void soakForEachKernel(int n, F f) {
  int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < n) f(i);
}
#endif

constexpr int kForEachBlockSize = 256;

template <class F>
void forEach(Device device, int n, F f, const char* what = "forEach") {
  if (n <= 0) return;
  if (device == Device::Cuda) {
#if defined(__CUDACC__)
    int blocks = (n + kForEachBlockSize - 1) / kForEachBlockSize;
    soakForEachKernel<<<blocks, kForEachBlockSize>>>(n, f);
    checkLastLaunch(device, what);
#else
    (void)f;
    throw std::logic_error(std::string(what) +
                           ": this translation unit was not compiled for CUDA (use soak_physics_sources)");
#endif
  } else {
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; ++i) f(i);
  }
}

}  // namespace soak

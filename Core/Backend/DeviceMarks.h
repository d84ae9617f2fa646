#pragma once
// DeviceMarks: time device work without waiting after each piece of it.
// mark(k) puts mark k on the device's queue (on the GPU a CUDA event; on
// the CPU, whose work is done when its call returns, the host clock);
// elapsedMs(a, b) waits for mark b and gives the milliseconds between the
// two. Timing the pipeline's stages this way leaves the device's queue as
// full as in a plain step: a wait after each stage instead added its
// latency and an idle device to every stage (Doc/performance.md).
#include <chrono>
#include <vector>

#include "Backend/Device.h"

namespace soak {

class DeviceMarks {
 public:
  explicit DeviceMarks(Device d = Device::Cpu) : device_(d) {}
  ~DeviceMarks();
  DeviceMarks(const DeviceMarks&) = delete;
  DeviceMarks& operator=(const DeviceMarks&) = delete;

  Device device() const { return device_; }
  void mark(int k);
  double elapsedMs(int a, int b);

 private:
  Device device_;
  std::vector<void*> events_;  // GPU
  std::vector<std::chrono::steady_clock::time_point> times_;  // CPU
};

}  // namespace soak

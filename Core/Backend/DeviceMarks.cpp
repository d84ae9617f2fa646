#include "Backend/DeviceMarks.h"

#include "Backend/CudaBackend.h"

namespace soak {

DeviceMarks::~DeviceMarks() {
  for (void* e : events_) cuda::destroyMark(e);
}

void DeviceMarks::mark(int k) {
  const std::size_t need = std::size_t(k) + 1;
  if (device_ == Device::Cuda) {
    while (events_.size() < need) events_.push_back(cuda::createMark());
    cuda::recordMark(events_[std::size_t(k)]);
  } else {
    if (times_.size() < need) times_.resize(need);
    times_[std::size_t(k)] = std::chrono::steady_clock::now();
  }
}

double DeviceMarks::elapsedMs(int a, int b) {
  if (device_ == Device::Cuda) {
    countHostWait();
    return cuda::markElapsedMs(events_[std::size_t(a)], events_[std::size_t(b)]);
  }
  return std::chrono::duration<double, std::milli>(times_[std::size_t(b)] - times_[std::size_t(a)]).count();
}

}  // namespace soak

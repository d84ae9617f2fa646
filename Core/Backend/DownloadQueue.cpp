#include "Backend/DownloadQueue.h"

#include <cstring>

#include "Backend/CudaBackend.h"

namespace soak {

namespace {
constexpr std::size_t kAlign = 256;
std::size_t aligned(std::size_t n) { return (n + kAlign - 1) / kAlign * kAlign; }
}  // namespace

DownloadQueue::Transfer::Transfer(Device d) : device_(d) {
  if (device_ == Device::Cuda) done_ = cuda::createFence();
}

DownloadQueue::Transfer::~Transfer() {
  if (device_ == Device::Cuda) {
    // The copy may still be writing into host_. A failed wait means the
    // device has failed already, which the step reports; a destructor
    // cannot throw.
    try {
      if (!waited_) cuda::hostWaitForFence(done_);
    } catch (...) {
    }
    cuda::releasePinned(host_);
    cuda::destroyFence(done_);
  } else {
    delete[] host_;
  }
}

void DownloadQueue::Transfer::reserve(std::size_t bytes) {
  if (bytes <= capacity_) return;
  // Geometric growth: a run whose water grows (a nozzle) reallocates
  // page-locked memory, which makes the device wait, a few times only.
  const std::size_t grown = capacity_ + capacity_ / 2;
  const std::size_t n = bytes > grown ? bytes : grown;
  if (device_ == Device::Cuda) {
    cuda::releasePinned(host_);
    host_ = nullptr;
    capacity_ = 0;
    host_ = static_cast<unsigned char*>(cuda::allocatePinned(n));
  } else {
    delete[] host_;
    host_ = nullptr;
    capacity_ = 0;
    host_ = new unsigned char[n];
  }
  capacity_ = n;
}

void DownloadQueue::Transfer::wait() {
  if (waited_) return;
  countHostWait();
  cuda::hostWaitForFence(done_);
  waited_ = true;
}

DownloadQueue::DownloadQueue(Device d) : device_(d), staging_(d) {
  if (device_ == Device::Cuda) {
    staged_ = cuda::createFence();
    copiedOut_ = cuda::createFence();
    cuda::recordFence(copiedOut_, 1);
  }
}

DownloadQueue::~DownloadQueue() {
  free_.clear();
  if (device_ == Device::Cuda) {
    // The staging block is freed in stream order on the compute stream:
    // after its last copy out.
    cuda::streamWaitForFence(0, copiedOut_);
    cuda::destroyFence(staged_);
    cuda::destroyFence(copiedOut_);
  }
}

std::unique_ptr<DownloadQueue::Transfer> DownloadQueue::download(const std::vector<Part>& parts) {
  std::unique_ptr<Transfer> t;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!free_.empty()) {
      t = std::move(free_.back());
      free_.pop_back();
    }
  }
  if (!t) t.reset(new Transfer(device_));
  t->offsets_.clear();
  t->bytes_.clear();
  std::size_t total = 0;
  for (const Part& p : parts) {
    t->offsets_.push_back(total);
    t->bytes_.push_back(p.bytes);
    total += aligned(p.bytes);
  }
  t->reserve(total > 0 ? total : kAlign);

  if (device_ == Device::Cpu) {
    countHostWait();  // a copy the calling thread makes (as copyDeviceToHost)
    for (std::size_t k = 0; k < parts.size(); ++k)
      if (parts[k].bytes > 0) std::memcpy(t->host_ + t->offsets_[k], parts[k].device, parts[k].bytes);
    t->waited_ = true;
    return t;
  }
  // Two streams and fences: never captured into a step graph (the segment
  // before is launched, these are queued after it).
  cuda::graphHold(true);
  // The previous download's copy out of the staging block must be done
  // before the block is written, resized or freed.
  cuda::streamWaitForFence(0, copiedOut_);
  staging_.resize(total);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (parts[k].bytes == 0) continue;
    countLaunch();
    cuda::copyAsync(staging_.data() + t->offsets_[k], parts[k].device, parts[k].bytes, 2, 0);
  }
  cuda::recordFence(staged_, 0);
  cuda::streamWaitForFence(1, staged_);
  if (total > 0) cuda::copyAsync(t->host_, staging_.data(), total, 1, 1);
  cuda::recordFence(t->done_, 1);
  cuda::recordFence(copiedOut_, 1);
  cuda::graphHold(false);
  t->waited_ = false;
  return t;
}

void DownloadQueue::recycle(std::unique_ptr<Transfer> t) {
  if (!t) return;
  t->wait();
  std::lock_guard<std::mutex> lock(mutex_);
  free_.push_back(std::move(t));
}

}  // namespace soak

#pragma once
#include <cstddef>
#include <utility>
#include <vector>

#include "Backend/Device.h"

namespace soak {

// An owning array of trivially copyable T on one device. Size may grow up to
// capacity without reallocating; reserve() reallocates preserving contents.
template <class T>
class Buffer {
 public:
  Buffer() = default;
  explicit Buffer(Device d) : device_(d) {}
  Buffer(Device d, std::size_t n) : device_(d) { resize(n); }
  ~Buffer() { release(); }
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  Buffer(Buffer&& o) noexcept { swap(o); }
  Buffer& operator=(Buffer&& o) noexcept {
    if (this != &o) { release(); swap(o); }
    return *this;
  }

  void swap(Buffer& o) noexcept {
    std::swap(device_, o.device_);
    std::swap(data_, o.data_);
    std::swap(size_, o.size_);
    std::swap(capacity_, o.capacity_);
  }

  Device device() const { return device_; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  std::size_t size() const { return size_; }
  std::size_t capacity() const { return capacity_; }
  bool empty() const { return size_ == 0; }

  void reserve(std::size_t n) {
    if (n <= capacity_) return;
    T* fresh = static_cast<T*>(deviceAllocate(device_, n * sizeof(T)));
    if (size_ > 0) copyDeviceToDevice(device_, fresh, data_, size_ * sizeof(T));
    if (data_) deviceFree(device_, data_);
    data_ = fresh;
    capacity_ = n;
  }
  // Grows capacity geometrically (by a sixteenth) so repeated appends stay
  // cheap. Not by doubling, nor by a quarter: the per-slot buffers (some 40
  // arrays, about 250 bytes per slot) are sized for the scene's particles
  // and grow on the first drip room appended past them, which needs a few
  // slots per thousand; by a quarter they held 25 % of unused slots for the
  // rest of the run (a 1M scene about 50 bytes per particle). A sixteenth
  // costs one more copy of an array each time it grows by 6 %.
  void resize(std::size_t n) {
    const std::size_t grown = capacity_ + capacity_ / 16;
    if (n > capacity_) reserve(n > grown ? n : grown);
    size_ = n;
  }
  void clear() { size_ = 0; }

  void upload(const std::vector<T>& host) {
    resize(host.size());
    if (!host.empty()) copyHostToDevice(device_, data_, host.data(), host.size() * sizeof(T));
  }
  // Writes host values into [offset, offset + host.size()).
  void uploadAt(std::size_t offset, const std::vector<T>& host) {
    if (!host.empty()) copyHostToDevice(device_, data_ + offset, host.data(), host.size() * sizeof(T));
  }
  std::vector<T> download() const {
    std::vector<T> host(size_);
    if (size_ > 0) copyDeviceToHost(device_, host.data(), data_, size_ * sizeof(T));
    return host;
  }
  void fillZero() {
    if (size_ > 0) fillBytes(device_, data_, 0, size_ * sizeof(T));
  }
  void copyFrom(const Buffer& o) {
    resize(o.size_);
    if (size_ > 0) copyDeviceToDevice(device_, data_, o.data_, size_ * sizeof(T));
  }

 private:
  void release() noexcept {
    if (data_) deviceFree(device_, data_);
    data_ = nullptr;
    size_ = capacity_ = 0;
  }
  Device device_ = Device::Cpu;
  T* data_ = nullptr;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

}  // namespace soak

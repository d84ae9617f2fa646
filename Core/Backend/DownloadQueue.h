#pragma once
#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

#include "Backend/Buffer.h"
#include "Backend/Device.h"

namespace soak {

// Copies of device arrays to the host that the thread queueing them does not
// wait for, so a frame can be taken without stalling the step.
//
// On the GPU, download() queues on the compute stream one device-to-device
// copy of each part into a staging block: in order with the step's own work,
// so the copy sees the arrays as they are now and the next step may change
// them at once. The copy stream then moves the staging block to page-locked
// host memory while the compute stream goes on. The staging block is reused
// only once its last copy out is done (the compute stream waits for that,
// not the host). On the CPU download() copies at once.
//
// A Transfer is one download's host memory; wait() (any thread) returns when
// it is complete. Give it back with recycle() to reuse its host memory.
class DownloadQueue {
 public:
  struct Part {
    const void* device = nullptr;
    std::size_t bytes = 0;
  };
  class Transfer {
   public:
    ~Transfer();
    Transfer(const Transfer&) = delete;
    Transfer& operator=(const Transfer&) = delete;
    // Waits until the host copy is complete. On the GPU this is the thread's
    // wait for the device (hostWaits()); on the CPU the copy was made by
    // download(), which counted it.
    void wait();
    std::size_t partCount() const { return offsets_.size(); }
    const void* part(std::size_t k) const { return host_ + offsets_[k]; }
    std::size_t partBytes(std::size_t k) const { return bytes_[k]; }

   private:
    friend class DownloadQueue;
    explicit Transfer(Device d);
    void reserve(std::size_t bytes);
    Device device_;
    unsigned char* host_ = nullptr;  // pinned on the GPU
    std::size_t capacity_ = 0;
    std::vector<std::size_t> offsets_, bytes_;
    void* done_ = nullptr;  // fence on the copy stream
    bool waited_ = true;
  };

  explicit DownloadQueue(Device d);
  ~DownloadQueue();
  DownloadQueue(const DownloadQueue&) = delete;
  DownloadQueue& operator=(const DownloadQueue&) = delete;

  // Queues copies of the parts (called by the thread that queues device work).
  std::unique_ptr<Transfer> download(const std::vector<Part>& parts);
  // Returns a finished transfer's host memory for later downloads (any thread).
  void recycle(std::unique_ptr<Transfer> t);

 private:
  Device device_;
  Buffer<unsigned char> staging_;
  void* staged_ = nullptr;     // compute stream: staging block filled
  void* copiedOut_ = nullptr;  // copy stream: staging block read out
  std::mutex mutex_;
  std::vector<std::unique_ptr<Transfer>> free_;
};

}  // namespace soak

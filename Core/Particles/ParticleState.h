#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "Backend/Buffer.h"
#include "Base/Vec3.h"
#include "Particles/Phase.h"

namespace soak {

class StateWriter;
class StateReader;

// Raw pointers into the particle arrays, passed by value to solver functions
// and kernels. Index i is a slot; slots are reordered every step (cell sort).
struct ParticleView {
  Float4* position = nullptr;   // x (xyz) and inverse mass (w); w == 0: pinned or static
  Float4* predicted = nullptr;  // x* of the current step (w mirrors position.w)
  Vec3* velocity = nullptr;
  float* mass = nullptr;        // kg (kept even when pinned)
  float* radius = nullptr;      // support radius h, m
  int* phase = nullptr;         // kPhaseWater, cloth index + 1, or kPhaseStatic
  int* id = nullptr;            // cloth: global cloth vertex index; water: serial number
  int count = 0;
};

// One particle to add, on the host.
struct ParticleInit {
  Vec3 position;
  Vec3 velocity;
  float mass = 0.f;
  float radius = 0.f;
  int phase = kPhaseWater;
  int id = -1;
  bool pinned = false;
};

// Structure-of-arrays particle storage on one device, with a capacity.
// Modules can attach extra per-particle float channels (e.g. held water);
// every channel follows the particles through reordering and removal.
class ParticleState {
 public:
  explicit ParticleState(Device device = Device::Cpu);

  Device device() const { return device_; }
  int count() const { return count_; }
  int capacity() const { return static_cast<int>(position_.capacity()); }
  void reserve(int capacity);

  ParticleView view();

  // Appends particles at the end (slots count()..count()+k-1). Extra
  // channels of new particles are zero. Returns the first new slot.
  int append(const std::vector<ParticleInit>& particles);
  // Appends k slots whose arrays the caller fills on the device (nothing
  // crosses from the host; channels are zeroed). Returns the first new slot.
  int appendSlots(int k);
  // Removes every slot i with remove[i] != 0, keeping the order of the rest.
  // Returns how many were removed.
  int removeFlagged(const int* remove);
  // Reorders all arrays so that new slot i holds old slot order[i].
  void gather(const std::uint32_t* order);
  // Exchanges the storage of x* with `other` (at least count() long): for a
  // solver that writes the next x* beside the current one.
  void swapPredicted(Buffer<Float4>& other);

  // Extra float channel: created (zeroed) on first call, same index afterwards.
  int addChannel(const std::string& name);
  int findChannel(const std::string& name) const;  // -1 if absent
  float* channel(int index) { return channels_[index].data.data(); }
  const std::string& channelName(int index) const { return channels_[index].name; }
  int channelCount() const { return static_cast<int>(channels_.size()); }

  // Per-slot host copies, mostly for output and tests.
  std::vector<Float4> downloadPositions() const { return position_.download(); }
  std::vector<Float4> downloadPredicted() const { return predicted_.download(); }
  std::vector<Vec3> downloadVelocities() const { return velocity_.download(); }
  std::vector<float> downloadMasses() const { return mass_.download(); }
  std::vector<float> downloadRadii() const { return radius_.download(); }
  std::vector<int> downloadPhases() const { return phase_.download(); }
  std::vector<int> downloadIds() const { return id_.download(); }
  std::vector<float> downloadChannel(int index) const { return channels_[index].data.download(); }

  // Checkpoints: every array and channel of the live slots, in slot order.
  // loadState needs the same channels (by name, in order) as were saved.
  void saveState(StateWriter& out) const;
  void loadState(StateReader& in);

  // Bytes of device memory the particle arrays hold.
  std::size_t bytes() const;

 private:
  struct Channel {
    std::string name;
    Buffer<float> data;
  };
  template <class F>
  void forEachArray(F&& f);

  Device device_;
  int count_ = 0;
  Buffer<Float4> position_, predicted_;
  Buffer<Vec3> velocity_;
  Buffer<float> mass_, radius_;
  Buffer<int> phase_, id_;
  std::vector<Channel> channels_;
  // Scratch for gather/compaction.
  Buffer<std::uint32_t> order_;
  Buffer<int> keepScan_, keepOffset_;
  Buffer<char> scratch_;
};

}  // namespace soak

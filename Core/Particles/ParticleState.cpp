#include "Particles/ParticleState.h"

#include <cstring>
#include <stdexcept>

#include "Base/Unroll.h"
#include "Backend/ForEachPhased.h"
#include "Backend/Primitives.h"

namespace soak {

namespace {
// The GPU's gather moves every array through one scratch area, a batch of
// arrays at a time: at most this many bytes per slot, so that the scratch
// costs no more than the widest array (the particle arrays take 76 bytes
// per slot with the wetting's channels: 5 batches). 32 bytes (3 batches,
// four barriers fewer) measured within the noise of 16 on the H100 (fig7
// 1.254 vs 1.282 ms a step) and cost 16 bytes per slot more.
constexpr int kGatherBatchBytes = 16;
constexpr int kMaxGatherArrays = 24;

struct GatherArray {
  char* data;
  int bytes;   // per element: 4, 12 or 16
  int offset;  // bytes per slot before it in its batch's scratch
  int batch;
};
// Passed in the kernel's parameters; read with constant indices only (an
// unrolled loop), so that it stays there rather than in local memory.
struct GatherPlan {
  GatherArray arrays[kMaxGatherArrays];
  int count = 0;
  int batches = 0;
};

// new[i] = old[order[i]] through the scratch, one array (the CPU's gather:
// typed loops that the compiler vectorises; the GPU's batched launch below
// took the CPU's grid build at 100k particles from 11.9 to 21.0 ms).
template <class T>
void gatherArray(Buffer<T>& data, const std::uint32_t* order, int n, Buffer<char>& scratch) {
  scratch.resize(std::size_t(n) * sizeof(T));
  T* tmp = reinterpret_cast<T*>(scratch.data());
  const T* src = data.data();
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) tmp[i] = src[order[i]];
  std::memcpy(data.data(), tmp, std::size_t(n) * sizeof(T));
}

SOAK_INLINE void copyElement(char* dst, const char* src, int bytes) {
  if (bytes == 16) {
    *reinterpret_cast<Float4*>(dst) = *reinterpret_cast<const Float4*>(src);
  } else {
    for (int w = 0; w < bytes / 4; ++w) reinterpret_cast<float*>(dst)[w] = reinterpret_cast<const float*>(src)[w];
  }
}
}  // namespace

ParticleState::ParticleState(Device device)
    : device_(device),
      position_(device),
      predicted_(device),
      velocity_(device),
      mass_(device),
      radius_(device),
      phase_(device),
      id_(device),
      order_(device),
      keepScan_(device),
      keepOffset_(device),
      scratch_(device) {}

template <class F>
void ParticleState::forEachArray(F&& f) {
  f(position_);
  f(predicted_);
  f(velocity_);
  f(mass_);
  f(radius_);
  f(phase_);
  f(id_);
  for (Channel& c : channels_) f(c.data);
}

void ParticleState::reserve(int capacity) {
  forEachArray([&](auto& b) { b.reserve(static_cast<std::size_t>(capacity)); });
}

ParticleView ParticleState::view() {
  ParticleView v;
  v.position = position_.data();
  v.predicted = predicted_.data();
  v.velocity = velocity_.data();
  v.mass = mass_.data();
  v.radius = radius_.data();
  v.phase = phase_.data();
  v.id = id_.data();
  v.count = count_;
  return v;
}

int ParticleState::append(const std::vector<ParticleInit>& particles) {
  const int first = count_;
  const int k = static_cast<int>(particles.size());
  if (k == 0) return first;
  std::vector<Float4> pos(k);
  std::vector<Vec3> vel(k);
  std::vector<float> mass(k), radius(k);
  std::vector<int> phase(k), id(k);
  for (int i = 0; i < k; ++i) {
    const ParticleInit& p = particles[i];
    float w = (p.pinned || p.phase == kPhaseStatic || p.mass <= 0.f) ? 0.f : 1.f / p.mass;
    pos[i] = Float4(p.position, w);
    vel[i] = p.velocity;
    mass[i] = p.mass;
    radius[i] = p.radius;
    phase[i] = p.phase;
    id[i] = p.id;
  }
  appendSlots(k);
  position_.uploadAt(first, pos);
  predicted_.uploadAt(first, pos);
  velocity_.uploadAt(first, vel);
  mass_.uploadAt(first, mass);
  radius_.uploadAt(first, radius);
  phase_.uploadAt(first, phase);
  id_.uploadAt(first, id);
  return first;
}

int ParticleState::appendSlots(int k) {
  const int first = count_;
  if (k <= 0) return first;
  const int n = first + k;
  forEachArray([&](auto& b) { b.resize(static_cast<std::size_t>(n)); });
  for (Channel& c : channels_) fillBytes(device_, c.data.data() + first, 0, sizeof(float) * k);
  count_ = n;
  return first;
}

int ParticleState::removeFlagged(const int* remove) {
  const int n = count_;
  if (n == 0) return 0;
  keepScan_.resize(n + 1);
  order_.resize(n);
  int* keep = keepScan_.data();
  forEach(device_, n, SOAK_LAMBDA(int i) { keep[i] = remove[i] ? 0 : 1; }, "removeFlagged.keep");
  keepOffset_.resize(n);
  int* off = keepOffset_.data();
  const int kept = exclusiveScan(device_, keep, off, n);
  if (kept == n) return 0;
  std::uint32_t* order = order_.data();
  forEach(device_, n, SOAK_LAMBDA(int i) {
    if (keep[i]) order[off[i]] = static_cast<std::uint32_t>(i);
  }, "removeFlagged.order");
  // Only the first `kept` entries of order are defined: gather those.
  count_ = kept;
  gather(order);
  forEachArray([&](auto& b) { b.resize(static_cast<std::size_t>(kept)); });
  return n - kept;
}

// new[i] = old[order[i]] for every array, in one launch (forEachPhased):
// phase 2b gathers batch b into the scratch, phase 2b + 1 copies it back
// (so the arrays keep their storage, and pointers to them stay valid). One
// launch per array and one copy each had made the grid build 22 launches
// of a few microseconds each in the small scenes (Doc/performance.md).
void ParticleState::gather(const std::uint32_t* order) {
  const int n = count_;
  if (n == 0) return;
  if (device_ == Device::Cpu) {
    forEachArray([&](auto& b) { gatherArray(b, order, n, scratch_); });
    return;
  }
  GatherPlan plan;
  int batchBytes = 0;
  // 16-byte arrays come first (forEachArray's order), so they sit at
  // 16-byte aligned offsets of their batch.
  forEachArray([&](auto& b) {
    const int bytes = int(sizeof(*b.data()));
    if (plan.count == kMaxGatherArrays) throw std::logic_error("ParticleState::gather: too many channels");
    if (plan.count == 0 || batchBytes + bytes > kGatherBatchBytes) {
      ++plan.batches;
      batchBytes = 0;
    }
    plan.arrays[plan.count++] = {reinterpret_cast<char*>(b.data()), bytes, batchBytes, plan.batches - 1};
    batchBytes += bytes;
  });
  scratch_.resize(std::size_t(n) * kGatherBatchBytes);
  char* scratch = scratch_.data();
  const long long slots = n;
  // Phase 2b: batch b into the scratch; phase 2b + 1: back.
  auto move = SOAK_LAMBDA(int phase, int i) {
    const int b = phase / 2;
    const bool toScratch = phase % 2 == 0;
    SOAK_UNROLL
    for (int a = 0; a < kMaxGatherArrays; ++a) {
      if (a >= plan.count || plan.arrays[a].batch != b) continue;
      const GatherArray g = plan.arrays[a];
      char* area = scratch + slots * g.offset;
      if (toScratch) copyElement(area + std::size_t(i) * g.bytes, g.data + std::size_t(order[i]) * g.bytes, g.bytes);
      else copyElement(g.data + std::size_t(i) * g.bytes, area + std::size_t(i) * g.bytes, g.bytes);
    }
  };
  if (2LL * plan.batches * slots < (1LL << 30)) {
    PhaseList phases;
    for (int p = 0; p < 2 * plan.batches; ++p) phases.add(p * n, (p + 1) * n);
    forEachPhased(device_, phases, SOAK_LAMBDA(int k) {
      const int phase = int(k / slots);
      move(phase, int(k - phase * slots));
    }, "gather");
  } else {
    for (int p = 0; p < 2 * plan.batches; ++p) forEach(device_, n, SOAK_LAMBDA(int i) { move(p, i); }, "gather");
  }
}

void ParticleState::swapPredicted(Buffer<Float4>& other) {
  if (int(other.size()) < count_) throw std::logic_error("ParticleState::swapPredicted: buffer shorter than the particles");
  other.resize(std::size_t(count_));
  predicted_.swap(other);
}

int ParticleState::addChannel(const std::string& name) {
  int existing = findChannel(name);
  if (existing >= 0) return existing;
  Channel c{name, Buffer<float>(device_)};
  c.data.reserve(position_.capacity());
  c.data.resize(static_cast<std::size_t>(count_));
  c.data.fillZero();
  channels_.push_back(std::move(c));
  return static_cast<int>(channels_.size()) - 1;
}

int ParticleState::findChannel(const std::string& name) const {
  for (std::size_t i = 0; i < channels_.size(); ++i)
    if (channels_[i].name == name) return static_cast<int>(i);
  return -1;
}

std::size_t ParticleState::bytes() const {
  std::size_t per = 2 * sizeof(Float4) + sizeof(Vec3) + 2 * sizeof(float) + 2 * sizeof(int) +
                    channels_.size() * sizeof(float);
  return per * position_.capacity();
}

}  // namespace soak

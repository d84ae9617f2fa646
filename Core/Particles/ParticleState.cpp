#include "Particles/ParticleState.h"

#include "Backend/ForEach.h"
#include "Backend/Primitives.h"

namespace soak {

namespace {
// new[i] = old[order[i]] through a scratch buffer of the same bytes.
template <class T>
void gatherArray(Device d, Buffer<T>& data, const std::uint32_t* order, int n, Buffer<char>& scratch) {
  if (n == 0) return;
  scratch.resize(std::size_t(n) * sizeof(T));
  T* tmp = reinterpret_cast<T*>(scratch.data());
  const T* src = data.data();
  forEach(d, n, SOAK_LAMBDA(int i) { tmp[i] = src[order[i]]; }, "gather");
  copyDeviceToDevice(d, data.data(), tmp, std::size_t(n) * sizeof(T));
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

void ParticleState::gather(const std::uint32_t* order) {
  const int n = count_;
  forEachArray([&](auto& b) { gatherArray(device_, b, order, n, scratch_); });
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

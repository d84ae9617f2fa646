// ParticleState's part of a checkpoint: every array in slot order.
#include "Checkpoint/StateStream.h"
#include "Particles/ParticleState.h"

namespace soak {

namespace {
template <class T>
void restore(StateReader& in, Buffer<T>& buffer, int count, const char* name) {
  std::vector<T> values = in.getVector<T>();
  if (values.size() != std::size_t(count))
    in.fail(std::string("particle array '") + name + "' has " + std::to_string(values.size()) + " values for " +
            std::to_string(count) + " particles");
  buffer.upload(values);
}
}  // namespace

void ParticleState::saveState(StateWriter& out) const {
  out.putString("particles");
  out.put<std::int32_t>(count_);
  out.putVector(position_.download());
  out.putVector(predicted_.download());
  out.putVector(velocity_.download());
  out.putVector(mass_.download());
  out.putVector(radius_.download());
  out.putVector(phase_.download());
  out.putVector(id_.download());
  out.put<std::int32_t>(static_cast<std::int32_t>(channels_.size()));
  for (const Channel& c : channels_) {
    out.putString(c.name);
    out.putVector(c.data.download());
  }
}

void ParticleState::loadState(StateReader& in) {
  in.expect("particles");
  const int count = in.get<std::int32_t>();
  if (count < 0) in.fail("negative particle count");
  // Each particle's arrays take this many bytes of the file: a count the
  // bytes left cannot hold is refused before anything is allocated for it.
  const std::size_t bytesPerParticle = 2 * sizeof(Float4) + sizeof(Vec3) + 2 * sizeof(float) + 2 * sizeof(int) +
                                       channels_.size() * sizeof(float);
  if (std::size_t(count) > in.remaining() / bytesPerParticle)
    in.fail(std::to_string(count) + " particles announced, more than the data left can hold");
  reserve(count);
  restore(in, position_, count, "position");
  restore(in, predicted_, count, "predicted");
  restore(in, velocity_, count, "velocity");
  restore(in, mass_, count, "mass");
  restore(in, radius_, count, "radius");
  restore(in, phase_, count, "phase");
  restore(in, id_, count, "id");
  const int channels = in.get<std::int32_t>();
  if (channels != channelCount())
    in.fail("it holds " + std::to_string(channels) + " particle channels, the scene makes " +
            std::to_string(channelCount()));
  for (Channel& c : channels_) {
    const std::string name = in.getString();
    if (name != c.name) in.fail("particle channel '" + name + "' where the scene makes '" + c.name + "'");
    restore(in, c.data, count, c.name.c_str());
  }
  count_ = count;
}

}  // namespace soak

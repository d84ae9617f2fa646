#include "SharedArrays.h"

namespace soak {

static_assert(sizeof(Vec3) == 3 * sizeof(float), "velocity rows are three packed floats");
static_assert(sizeof(Float4) == 4 * sizeof(float), "position rows are four packed floats");

std::vector<SharedArray> sharedArrays(Simulation& sim) {
  ParticleState& ps = sim.particles;
  const ParticleView p = ps.view();
  const std::int64_t n = ps.count();
  auto floats = [&](const std::string& name, void* data, std::int64_t columns, std::int64_t rowStride, bool writable) {
    SharedArray a;
    a.name = name;
    a.data = data;
    a.rows = n;
    a.columns = columns;
    a.rowStride = rowStride;
    a.writable = writable;
    return a;
  };
  float* position = reinterpret_cast<float*>(p.position);
  std::vector<SharedArray> out{
      floats("position", position, 3, 4, true),
      floats("velocity", p.velocity, 3, 3, true),
      floats("inverse_mass", position ? position + 3 : nullptr, 0, 4, false),
      floats("mass", p.mass, 0, 1, false),
      floats("radius", p.radius, 0, 1, false),
  };
  for (const auto& [name, data] : {std::pair<const char*, int*>{"phase", p.phase}, {"id", p.id}}) {
    SharedArray a = floats(name, data, 0, 1, false);
    a.integer = true;
    out.push_back(a);
  }
  for (int k = 0; k < ps.channelCount(); ++k) out.push_back(floats(ps.channelName(k), ps.channel(k), 0, 1, true));
  return out;
}

}  // namespace soak

#include "WetState.h"

#include "Backend/Primitives.h"
#include "Simulation/Simulation.h"

namespace soak::wet {

WetState::WetState(Device d)
    : dryMass(d), vertexArea(d), due(d), dripOffset(d), dripSources(d), dripCounters(d), pool_{Buffer<float>(d), Buffer<float>(d), Buffer<float>(d)},
      delta_(d) {}

WetArrays WetState::arrays(Simulation& sim) {
  ParticleState& ps = sim.particles;
  const std::size_t n = std::size_t(ps.count());
  for (Buffer<float>& b : pool_) b.resize(n);
  delta_.resize(n);
  WetArrays a;
  a.held = ps.channel(held);
  a.buffer = ps.channel(buffer);
  a.saturation = ps.channel(saturation);
  a.volume = ps.channel(volume);
  a.kappaCouple = kappa;
  a.bendScale = bendScale;
  a.frictionScale = frictionScale;
  a.dryMass = dryMass.data();
  a.cloth = clothSlots(sim.cloth.view());
  a.clothGrid = sim.cloth.grid();
  a.clothNeighbours = clothNeighbours->view();
  return a;
}

void WetState::setInitialSaturation(Simulation& sim) {
  ParticleView p = sim.particles.view();
  WetArrays a = arrays(sim);
  updatePorosity(sim.device(), p, a, w);  // volumes
  std::vector<float> vol = sim.particles.downloadChannel(volume);
  const std::vector<int> phase = sim.particles.downloadPhases();
  std::vector<float> h(vol.size(), 0.f);
  for (std::size_t i = 0; i < h.size(); ++i)
    if (isCloth(phase[i])) h[i] = w.initialSaturation * vol[i] / w.c;
  Buffer<float> tmp(sim.device());
  tmp.upload(h);
  copyDeviceToDevice(sim.device(), a.held, tmp.data(), h.size() * sizeof(float));
}

}  // namespace soak::wet

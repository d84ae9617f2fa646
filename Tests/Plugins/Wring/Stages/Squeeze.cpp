// wring.squeeze, after wet.diffuse (WringPlugin.cpp's table).
#include "Backend/ForEach.h"
#include "Base/Error.h"
#include "Simulation/Simulation.h"
#include "Stages/WetStages.h"
#include "Wring.h"

namespace wring {

void squeeze(soak::Device d, soak::ParticleView p, float* held, float* buffer, float* saturation, float cap) {
  soak::forEach(d, p.count, SOAK_LAMBDA(int i) {
    const float S = saturation[i];
    if (!soak::isCloth(p.phase[i]) || !(S > cap)) return;
    const float out = held[i] * (1.f - cap / S);
    held[i] -= out;
    buffer[i] += out;
    saturation[i] = cap;
  }, "wring.squeeze");
}

void runSqueeze(WringState& state, soak::Simulation& sim) {
  soak::ParticleState& ps = sim.particles;
  if (state.held < 0) {
    state.held = ps.findChannel(soak::wet::kHeldWaterChannel);
    state.buffer = ps.findChannel(soak::wet::kBufferChannel);
    state.saturation = ps.findChannel(soak::wet::kSaturationChannel);
  }
  squeeze(sim.device(), ps.view(), ps.channel(state.held), ps.channel(state.buffer), ps.channel(state.saturation),
          state.cap);
}

}  // namespace wring

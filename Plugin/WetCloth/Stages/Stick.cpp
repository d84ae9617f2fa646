// wet.stick: Eq. 20, touching cloth particles of different layers attract,
// most at S^T; as a force on the velocities (after finalize) or as a
// correction of the positions (before it), WetParams.h's StickForm.
#include "Physics/Integrate.h"
#include <algorithm>
#include <cmath>

#include "Backend/ForEach.h"
#include "Simulation/Simulation.h"
#include "Stages/WetStages.h"
#include "WetKernels.h"
#include "WetState.h"

namespace soak::wet {

void stickWetCloth(Device d, ParticleView p, ClothView c, WetArrays a, const WetParams& w, float dt, Vec3* delta) {
  const float sT = w.sT, kAd = w.kappaAd, etaAd = w.etaAd >= 0.f ? w.etaAd : w.kappaAd * w.sT * w.sT;
  const float* S = a.saturation;
  // As a force the impulse f dt / m goes onto the velocity finalize set (the
  // next step's prediction carries it into the cloth solve), here: the pass
  // reads positions only. As a correction the displacement waits in `delta`
  // until every particle's pull is known, since the pass reads the positions
  // it would move.
  const bool asForce = w.stickForm == StickForm::Force;
  const float invDt = 1.f / dt;
  forEachClothItemLanes(d, a.cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
    const Float4 xi4 = p.predicted[i];
    if (xi4.w == 0.f) {
      if (lanes.leader() && !asForce) delta[i] = Vec3(0.f, 0.f, 0.f);
      return;
    }
    const int vi = p.id[i];
    const Vec3 xi = xi4.xyz(), resti = c.restPosition[vi];
    const float thi = c.thickness[vi];
    Vec3 f(0.f, 0.f, 0.f);
    forEachClothNeighbour(a.clothNeighbours, v, lanes, [&](int j) {
      if (j == i || !isCloth(p.phase[j])) return;
      const int vj = p.id[j];
      const float reach = thi + c.thickness[vj];  // touching: within two half-thicknesses each side
      const Vec3 xij = p.predicted[j].xyz() - xi;
      const float r2 = lengthSquared(xij);
      if (r2 >= reach * reach || r2 == 0.f) return;
      // Particles near each other in the rest shape are the same layer.
      if (p.phase[j] == p.phase[i] && lengthSquared(c.restPosition[vj] - resti) < 9.f * thi * thi) return;
      // Eq. 20, towards j, kernel relative to its peak.
      const float mag = stickingMagnitude(S[i], S[j], sT, kAd, etaAd) * poly6(r2, reach) / poly6(0.f, reach);
      f += xij * (mag / sqrtf(r2));
    });
    f = laneSum(lanes, f);
    if (!lanes.leader()) return;
    const Vec3 dx = f * (dt * dt * xi4.w);
    if (asForce) p.velocity[i] += dx * invDt;
    else delta[i] = dx;
  }, "wet.stick", kListLanes);
  if (!asForce) applyCorrectionsAt(d, p, a.cloth.slot, a.cloth.count, delta, "wet.stick.apply");
}

void runStick(WetState& st, Simulation& s) {
  if (!st.w.sticking) return;
  stickWetCloth(s.device(), s.particles.view(), s.cloth.view(), st.arrays(s), st.w, float(s.settings.timeStep),
                st.stickDelta());
}

}  // namespace soak::wet

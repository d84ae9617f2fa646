// wet.absorb (after the core's coupling): Eq. 11, water particles give
// water to the cloth particles around them.
#include <algorithm>
#include <cmath>

#include "Backend/ForEach.h"
#include "Simulation/Simulation.h"
#include "Stages/WetStages.h"
#include "WetKernels.h"
#include "WetState.h"

namespace soak::wet {

namespace {

// Eq. 11's per-pair factor 1 + eta^a cos(theta_ij), x_ij = x_cloth - x_water,
// or 0 when the pair is out of reach. Every pass that needs a pair's share
// calls this with the same arguments, so all passes see the same bits and
// the water a cloth particle gains is exactly what the water particle loses.
SOAK_INLINE float absorptionFactor(Vec3 xCloth, float hCloth, Vec3 xWater, float hWater, float etaA, Vec3 g) {
  const Vec3 xij = xCloth - xWater;
  const float r2 = lengthSquared(xij);
  const float h = pairSupport(hCloth, hWater);
  if (r2 >= h * h) return 0.f;
  return gravityTerm(etaA, cosToGravity(xij, sqrtf(r2), g));
}

}  // namespace

void absorbWater(Device d, ParticleView p, GridView g, WetArrays a, const WetParams& w, WaterReference ref,
                 float dt, AbsorbScratch s) {
  // kappa^a of this step: the rate per second times dt (Doc/model.md, "Rates per second").
  const float c = w.c, sMax = w.sMax, kA = stepFraction(w.kappaA, dt, w.rates), etaA = w.etaA;
  const float m0 = ref.mass, h0 = ref.supportRadius;
  // A buffer below kBufferFloor x m_threshold does not stop absorption
  // (Doc/model.md, "Rates per second").
  const float blocking = kBufferFloor * w.mThreshold;
  const Vec3 gd = ref.gravityDir;
  float* scale = s.scale;
  float* ratio = s.ratio;
  float* asked = s.asked;
  // Cloth: what each cloth particle may take from each water neighbour,
  // a_ij = kappa^a (1 + eta^a cos theta_ij) (S^MAX - S_i) V_i / c (Eq. 11, in
  // kg), scaled down if the sum over its neighbours would overfill it.
  forEachClothParticleLanes(d, a.cloth, SOAK_LAMBDA(int i, Lanes lanes) {
    if (lanes.leader()) scale[i] = 0.f;
    // A particle that already carries excess water (a buffer) takes no more:
    // otherwise the drips it sheds are absorbed again next step, and the
    // same water drips over and over (9,268 drips in 0.6 s from a sheet
    // holding excess for 1,400; their pushing tore the sheet). What the
    // per-second transfer leaves behind (a geometric tail) does not count.
    if (a.buffer[i] > blocking) return;
    const float cap = maxf(sMax - saturationOf(c, a.held[i], a.volume[i]), 0.f) * a.volume[i] / c;
    if (cap <= 0.f) return;
    const Vec3 xi = p.predicted[i].xyz();
    const float hi = p.radius[i];
    float factors = 0.f;
    forEachCandidate(g, g.slotKey[i], lanes, [&](int j) {
      if (!isWater(p.phase[j]) || p.mass[j] <= 0.f) return;
      factors += absorptionFactor(xi, hi, p.predicted[j].xyz(), p.radius[j], etaA, gd);
    });
    factors = laneSum(lanes, factors);
    if (!lanes.leader()) return;
    const float demand = kA * cap * factors;
    scale[i] = demand > cap ? cap / factors : kA * cap;
  }, "wet.absorb.demand");
  // Water: if the cloth around wants more than the particle has, every share
  // shrinks alike (ratio); what the cloth asks of the particle is kept.
  forEachLanes(d, p.count, SOAK_LAMBDA(int j, Lanes lanes) {
    if (!isWater(p.phase[j]) || p.mass[j] <= 0.f) {
      if (lanes.leader()) ratio[j] = 0.f;
      return;
    }
    const Vec3 xj = p.predicted[j].xyz();
    const float hj = p.radius[j];
    float sum = 0.f;
    forEachCandidate(a.clothGrid, g.slotKey[j], lanes, [&](int i) {
      if (!isCloth(p.phase[i]) || scale[i] <= 0.f) return;
      sum += scale[i] * absorptionFactor(p.predicted[i].xyz(), p.radius[i], xj, hj, etaA, gd);
    });
    sum = laneSum(lanes, sum);
    if (!lanes.leader()) return;
    asked[j] = sum;
    ratio[j] = sum > p.mass[j] ? p.mass[j] / sum : 1.f;
  }, "wet.absorb.ratio");
  forEachClothParticleLanes(d, a.cloth, SOAK_LAMBDA(int i, Lanes lanes) {
    if (scale[i] <= 0.f) return;
    const Vec3 xi = p.predicted[i].xyz();
    const float hi = p.radius[i];
    float gained = 0.f;
    forEachCandidate(g, g.slotKey[i], lanes, [&](int j) {
      if (!isWater(p.phase[j]) || p.mass[j] <= 0.f) return;
      gained += scale[i] * absorptionFactor(xi, hi, p.predicted[j].xyz(), p.radius[j], etaA, gd) * ratio[j];
    });
    gained = laneSum(lanes, gained);
    if (lanes.leader()) a.held[i] += gained;
  }, "wet.absorb.cloth");
  // Water gives ratio_j times what was asked of it: the sum over its cloth
  // neighbours of the shares the cloth took above (ratio_j is the same in
  // every term), without walking them again.
  forEach(d, p.count, SOAK_LAMBDA(int j) {
    if (!isWater(p.phase[j]) || p.mass[j] <= 0.f) return;
    const float given = asked[j] * ratio[j];
    if (given <= 0.f) return;
    const float m = ratio[j] < 1.f ? 0.f : maxf(p.mass[j] - given, 0.f);
    p.mass[j] = m;
    if (m > 0.f) {
      // Adaptive sampling (Section 4.2): h' = (m' / m0)^(1/3) h0.
      p.radius[j] = h0 * cbrtf(m / m0);
      p.position[j].w = 1.f / m;
      p.predicted[j].w = 1.f / m;
    }
  }, "wet.absorb.water");
}

void runAbsorb(WetState& st, Simulation& s) {
  absorbWater(s.device(), s.particles.view(), s.grid.view(), st.arrays(s), st.w, st.ref, float(s.settings.timeStep),
              st.absorbScratch());
}

}  // namespace soak::wet

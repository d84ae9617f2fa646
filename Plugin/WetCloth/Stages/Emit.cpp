// wet.emit: Eq. 18 moves buffered water down the cloth and makes drips
// where a buffer holds m_threshold; Eq. 19 lets cloth attract light water.
// The drips taken here join the water at the next step's start
// (placeDrips, from WetClothModule::beforeStep).
#include "Backend/Primitives.h"
#include "Physics/Integrate.h"
#include <algorithm>
#include <cmath>

#include "Backend/ForEach.h"
#include "Simulation/Simulation.h"
#include "Stages/WetStages.h"
#include "WetKernels.h"
#include "WetState.h"

namespace soak::wet {

namespace {

// Eq. 18's weight cos(theta_ki) W_ki of receiver k below donor i (0 unless k
// lies below i and within reach).
SOAK_INLINE float transferWeight(Vec3 xk, float hk, Vec3 xi, float hi, Vec3 g) {
  const Vec3 xki = xk - xi;
  const float r2 = lengthSquared(xki);
  const float h = pairSupport(hk, hi);
  if (r2 >= h * h || r2 == 0.f) return 0.f;
  const float cosT = cosToGravity(xki, sqrtf(r2), g);
  return cosT > 0.f ? cosT * poly6(r2, h) : 0.f;
}

}  // namespace

void transferBuffers(Device d, ParticleView p, WetArrays a, const WetParams& w, WaterReference ref,
                     float dt, int* due, TransferScratch s) {
  const Vec3 gd = ref.gravityDir;
  // The share of a buffer that moves this step: all of it in one of the
  // paper's steps (Doc/model.md, "Rates per second").
  const float share = minf(stepFraction(w.bufferShare, dt, w.rates), 1.f);
  const float mThr = w.mThreshold;
  const float threshold = w.beta * ref.gravity;
  float* out = s.out;
  float* norm = s.norm;
  const float* S = a.saturation;
  forEachClothItemLanes(d, a.cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
    if (lanes.leader()) {
      out[i] = 0.f;
      norm[i] = 0.f;
    }
    if (!(a.buffer[i] > 0.f)) return;
    const Vec3 xi = p.predicted[i].xyz();
    const float hi = p.radius[i];
    // Eq. 18, second condition: |sum_{j above i} V_j S_j cos(theta_ij) grad W_ij| < |beta g|.
    Vec3 pull(0.f, 0.f, 0.f);
    float below = 0.f;
    forEachClothNeighbour(a.clothNeighbours, v, lanes, [&](int j) {
      if (j == i || p.phase[j] != p.phase[i]) return;
      const Vec3 xj = p.predicted[j].xyz();
      const Vec3 xij = xi - xj;
      const float r2 = lengthSquared(xij);
      const float h = pairSupport(hi, p.radius[j]);
      if (r2 >= h * h || r2 == 0.f) return;
      const float r = sqrtf(r2);
      const float cosT = cosToGravity(xij, r, gd);
      if (cosT > 0.f) pull += spikyGradient(xij, r, h) * (a.volume[j] * S[j] * cosT);
      below += transferWeight(xj, p.radius[j], xi, hi, gd);
    });
    pull = laneSum(lanes, pull);
    below = laneSum(lanes, below);
    if (lanes.leader() && length(pull) < threshold && below > 0.f) {
      out[i] = share < 1.f ? share * a.buffer[i] : a.buffer[i];
      norm[i] = below;
    }
  }, "wet.emit.decide", kListLanes);
  // Receivers below take cos(theta_ki) W_ki of what the donor sends,
  // normalised so all of it arrives (the paper's weights do not sum to one).
  // A particle reads its neighbours' out and norm and only its own buffer,
  // so it writes its new buffer in place.
  forEachClothItemLanes(d, a.cloth, SOAK_LAMBDA(int k, int v, Lanes lanes) {
    const Vec3 xk = p.predicted[k].xyz();
    const float hk = p.radius[k];
    float gain = 0.f;
    forEachClothNeighbour(a.clothNeighbours, v, lanes, [&](int i) {
      if (i == k || p.phase[i] != p.phase[k] || !(out[i] > 0.f)) return;
      gain += out[i] * transferWeight(xk, hk, p.predicted[i].xyz(), p.radius[i], gd) / norm[i];
    });
    gain = laneSum(lanes, gain);
    if (!lanes.leader()) return;
    const float buffer = a.buffer[k] - out[k] + gain;
    a.buffer[k] = buffer;
    due[v] = buffer >= mThr ? 1 : 0;  // a drip is due (takeDripMass)
  }, "wet.emit.transfer", kListLanes);
}


void takeDripMass(Device d, ParticleView p, WetArrays a, const WetParams& w, int room, int* due, int* offsets,
                  DripSource* sources, DripCounters* counters) {
  const float mThr = w.mThreshold;
  // Over the cloth's slots, which are in increasing order: the first `room`
  // due in slot order take their drips.
  const int n = a.cloth.count;
  if (n == 0) return;
  const int* slot = a.cloth.slot;
  exclusiveScanAsync(d, due, offsets, n);
  forEach(d, n, SOAK_LAMBDA(int v) {
    if (v == 0) {  // the bookkeeping, once
      const int wanted = offsets[n - 1] + due[n - 1], taken = wanted < room ? wanted : room;
      counters->pending = taken;
      if (wanted > counters->largestStep) counters->largestStep = wanted;
      counters->spawned += taken;
      counters->deferred += wanted - taken;
    }
    if (!due[v] || offsets[v] >= room) return;
    const int i = slot[v];
    a.buffer[i] -= mThr;
    sources[offsets[v]] = {p.predicted[i].xyz(), p.velocity[i]};
  }, "wet.emit.take");
}


void placeDrips(Device d, ParticleView p, int first, int room, const DripSource* sources, const DripShape& shape,
                DripCounters* counters) {
  const DripShape s = shape;
  forEach(d, room, SOAK_LAMBDA(int k) {
    const int i = first + k;
    if (k < counters->pending) {
      const Float4 x(sources[k].position + s.below, 1.f / s.mass);
      p.position[i] = x;
      p.predicted[i] = x;
      p.velocity[i] = sources[k].velocity;
      p.mass[i] = s.mass;
      p.radius[i] = s.radius;
      p.phase[i] = kPhaseWater;
      p.id[i] = s.firstId + k;
    } else {
      p.position[i] = Float4(0.f, 0.f, 0.f, 0.f);
      p.predicted[i] = Float4(0.f, 0.f, 0.f, 0.f);
      p.velocity[i] = Vec3(0.f, 0.f, 0.f);
      p.mass[i] = 0.f;
      p.radius[i] = s.radius;
      p.phase[i] = kPhaseRemoved;
      p.id[i] = -1;
    }
  }, "wet.drips.place");
  forEach(d, 1, SOAK_LAMBDA(int) { counters->pending = 0; }, "wet.drips.placed");
}


void attractDrips(Device d, ParticleView p, GridView g, WetArrays a, const WetParams& w, WaterReference ref,
                  float dt) {
  const float kE = w.kappaE, etaE = w.etaE, rho0 = w.clothRestDensity, light = 0.999f * ref.mass;
  const float* S = a.saturation;
  forEachLanes(d, p.count, SOAK_LAMBDA(int j, Lanes lanes) {
    if (!isWater(p.phase[j]) || !(p.mass[j] > 0.f) || p.mass[j] >= light) return;
    const Vec3 xj = p.predicted[j].xyz();
    const float hj = p.radius[j];
    Vec3 f(0.f, 0.f, 0.f);
    forEachCandidate(a.clothGrid, g.slotKey[j], lanes, [&](int i) {
      if (!isCloth(p.phase[i])) return;
      const Vec3 xij = p.predicted[i].xyz() - xj;
      const float r2 = lengthSquared(xij);
      const float h = pairSupport(p.radius[i], hj);
      if (r2 >= h * h || r2 == 0.f) return;
      const float dry = a.dryMass[p.id[i]];
      const float psi = rho0 * a.volume[i] / dry;  // Akinci's Psi relative to the particle's own mass
      // Eq. 19, towards the cloth particle, kernel relative to its peak.
      f += xij * (kE * (dry + etaE * S[i]) * psi * poly6(r2, h) / poly6(0.f, h) / sqrtf(r2));
    });
    // As a position change dt^2 f / m, at most a quarter of the particle's
    // support per step: a light remnant of partial absorption would
    // otherwise be flung by a force meant for a drip.
    f = laneSum(lanes, f);
    if (!lanes.leader()) return;
    Vec3 dx = f * (dt * dt / p.mass[j]);
    const float most = 0.25f * hj, len = length(dx);
    if (len > most) dx = dx * (most / len);
    const Float4 x = p.predicted[j];
    p.predicted[j] = Float4(x.xyz() + dx, x.w);
  }, "wet.emit.attract");
}

void runEmit(WetState& st, Simulation& s) {
  if (!st.w.emission) return;
  WetArrays a = st.arrays(s);
  ParticleView p = s.particles.view();
  const float dt = float(s.settings.timeStep);
  st.due.resize(std::size_t(a.cloth.count));
  st.dripOffset.resize(std::size_t(a.cloth.count));
  transferBuffers(s.device(), p, a, st.w, st.ref, dt, st.due.data(), st.transferScratch());
  st.dripSources.resize(std::size_t(st.dripRoom));
  takeDripMass(s.device(), p, a, st.w, st.dripRoom, st.due.data(), st.dripOffset.data(), st.dripSources.data(),
               st.dripCounters.data());
  st.takenRoom = st.dripRoom;
  attractDrips(s.device(), p, s.grid.view(), a, st.w, st.ref, dt);
}

}  // namespace soak::wet

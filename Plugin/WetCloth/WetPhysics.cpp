#include "WetPhysics.h"

#include <cmath>

#include "Backend/ForEach.h"
#include "Backend/Primitives.h"
#include "Cloth/ClothVolume.h"
#include "Physics/Integrate.h"
#include "WetKernels.h"

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

// Eq. 12's a_ij = kappa^d (1 + eta^d cos theta_ij) lap W_ij / rho0 for
// receiver i and neighbour j (0 out of reach).
SOAK_INLINE float diffusionWeight(Vec3 xi, float hi, Vec3 xj, float hj, float kD, float etaD, float rho0, Vec3 g) {
  const Vec3 xij = xi - xj;
  const float r2 = lengthSquared(xij);
  const float h = pairSupport(hi, hj);
  if (r2 >= h * h || r2 == 0.f) return 0.f;
  const float r = sqrtf(r2);
  return kD * gravityTerm(etaD, cosToGravity(xij, r, g)) * laplacianWeight(r, h) / rho0;
}

// Water mass that flows into the drier receiver r from the wetter donor d in
// one iteration: the receiver's own term of Eq. 17, alpha_r a_rd (S_d - S_r),
// as mass. Both particles evaluate it with the same arguments.
SOAK_INLINE float diffusionFlux(Vec3 xr, float hr, float Sr, float alphaR, float Vr, Vec3 xd, float hd, float Sd,
                                float kD, float etaD, float rho0, Vec3 g, float c) {
  return alphaR * diffusionWeight(xr, hr, xd, hd, kD, etaD, rho0, g) * (Sd - Sr) * Vr / c;
}

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

void updatePorosity(Device d, ParticleView p, WetArrays a, const WetParams& w) {
  const float sEW = w.sEW, c = w.c, sT = w.sT, sMax = w.sMax;
  const bool wetWeight = w.wetWeight;
  const float bendSoftening = w.wetBendSoftening, wetFriction = w.wetFriction;
  const ClothListWalk lists{a.clothNeighbours};
  // One pass: the volume over the cloth's lists (which read positions, not
  // the masses and inverse masses this pass writes), then the rest.
  forEachClothItemLanes(d, a.cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
    const float V = clothVolumeOf(p, i, v, lanes, lists);
    if (!lanes.leader()) return;
    a.volume[i] = V;
    float held = a.held[i];
    // Water above S^EW is excess (Section 4.4): it leaves the fabric for the buffer.
    const float limit = sEW * V / c;
    if (held > limit) {
      const float excess = held - limit;
      a.buffer[i] += excess;
      held -= excess;
      a.held[i] = held;
    }
    const float S = saturationOf(c, held, V);  // Eq. 10
    a.saturation[i] = S;
    const int vertex = p.id[i];
    // Eq. 22 (per vertex), from all the water the particle carries, held and
    // buffered: cloth with excess water is the wettest (Doc/model.md).
    const float wetness = minf(saturationOf(c, held + a.buffer[i], V), sMax);
    a.kappaCouple[vertex] = couplingStiffnessOf(wetness, sT, sMax);
    // Wet cloth bends easier and grips colliders harder (Doc/model.md,
    // "Wet stiffness and friction"), in proportion to S / S^MAX.
    if (a.bendScale) a.bendScale[vertex] = 1.f - bendSoftening * wetness / sMax;
    if (a.frictionScale) a.frictionScale[vertex] = 1.f + wetFriction * wetness / sMax;
    if (wetWeight) {
      // Held and buffered water weigh on the cloth particle (the paper's rho0* = (m_i + m_j) / m_i).
      const float m = a.dryMass[vertex] + held + a.buffer[i];
      p.mass[i] = m;
      if (p.position[i].w > 0.f) {
        p.position[i].w = 1.f / m;
        p.predicted[i].w = 1.f / m;
      }
    }
  }, "wet.porosity", kListLanes);
}

void absorbWater(Device d, ParticleView p, GridView g, WetArrays a, const WetParams& w, WaterReference ref,
                 float dt) {
  // kappa^a of this step: the rate per second times dt (Doc/model.md, "Rates per second").
  const float c = w.c, sMax = w.sMax, kA = stepFraction(w.kappaA, dt, w.rates), etaA = w.etaA;
  const float m0 = ref.mass, h0 = ref.supportRadius;
  // A buffer below kBufferFloor x m_threshold does not stop absorption
  // (Doc/model.md, "Rates per second").
  const float blocking = kBufferFloor * w.mThreshold;
  const Vec3 gd = ref.gravityDir;
  float* scale = a.scratchA;
  float* ratio = a.scratchB;
  float* asked = a.scratchC;
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

void diffuseWater(Device d, ParticleView p, WetArrays a, const WetParams& w, WaterReference ref,
                  float dt) {
  const DiffusionSchedule schedule = diffusionSchedule(w, dt);
  const float c = w.c, sMax = w.sMax, kD = w.kappaD, etaD = w.etaD, kS = schedule.smoothing, eps = w.epsilon;
  const float rho0 = w.clothRestDensity;
  const bool literal = w.form == DiffusionForm::Literal;
  const Vec3 gd = ref.gravityDir;
  float* alpha = a.scratchA;
  float* limit = a.scratchB;
  float* next = a.scratchC;
  float* S = a.saturation;
  for (int it = 0; it < schedule.iterations; ++it) {
    // alpha_i = kappa^s sum_j a_ij / (sum_j a_ij^2 + (sum_j a_ij)^2 + eps), so
    // that Eq. 17 reads S_i* = S_i + alpha_i sum_j a_ij (S_j - S_i).
    forEachClothItemLanes(d, a.cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
      const Vec3 xi = p.predicted[i].xyz();
      const float hi = p.radius[i];
      float sum = 0.f, sum2 = 0.f;
      forEachClothNeighbour(a.clothNeighbours, v, lanes, [&](int j) {
        if (j == i || p.phase[j] != p.phase[i]) return;
        const float aij = diffusionWeight(xi, hi, p.predicted[j].xyz(), p.radius[j], kD, etaD, rho0, gd);
        sum += aij;
        sum2 += aij * aij;
      });
      sum = laneSum(lanes, sum);
      sum2 = laneSum(lanes, sum2);
      if (!lanes.leader()) return;
      S[i] = saturationOf(c, a.held[i], a.volume[i]);
      const float den = sum2 + sum * sum * (1.f + eps);
      alpha[i] = den > 0.f ? kS * sum / den : 0.f;
    }, "wet.diffuse.alpha", kListLanes);
    if (literal) {
      // Eq. 17 as written: each particle moves its own saturation (not conservative).
      forEachClothItemLanes(d, a.cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
        const Vec3 xi = p.predicted[i].xyz();
        const float hi = p.radius[i];
        float C = 0.f;
        forEachClothNeighbour(a.clothNeighbours, v, lanes, [&](int j) {
          if (j == i || p.phase[j] != p.phase[i]) return;
          C += diffusionWeight(xi, hi, p.predicted[j].xyz(), p.radius[j], kD, etaD, rho0, gd) * (S[j] - S[i]);
        });
        C = laneSum(lanes, C);
        if (!lanes.leader()) return;
        const float Snew = minf(maxf(S[i] + alpha[i] * C, 0.f), sMax);
        next[i] = Snew * a.volume[i] / c;
      }, "wet.diffuse.literal", kListLanes);
    } else {
      // Conservative form: the pair (receiver r, donor d) exchanges the mass
      // of the receiver's term of Eq. 17; the donor loses what the receiver
      // gains. A donor never gives more than it holds.
      forEachClothItemLanes(d, a.cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
        const Vec3 xi = p.predicted[i].xyz();
        const float hi = p.radius[i];
        float out = 0.f;
        forEachClothNeighbour(a.clothNeighbours, v, lanes, [&](int j) {
          if (j == i || p.phase[j] != p.phase[i] || !(S[j] < S[i])) return;
          out += diffusionFlux(p.predicted[j].xyz(), p.radius[j], S[j], alpha[j], a.volume[j], xi, hi, S[i], kD, etaD,
                               rho0, gd, c);
        });
        out = laneSum(lanes, out);
        if (lanes.leader()) limit[i] = out > a.held[i] ? a.held[i] / out : 1.f;
      }, "wet.diffuse.limit", kListLanes);
      forEachClothItemLanes(d, a.cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
        const Vec3 xi = p.predicted[i].xyz();
        const float hi = p.radius[i];
        float change = 0.f;
        forEachClothNeighbour(a.clothNeighbours, v, lanes, [&](int j) {
          if (j == i || p.phase[j] != p.phase[i]) return;
          const Vec3 xj = p.predicted[j].xyz();
          if (S[j] > S[i])
            change += diffusionFlux(xi, hi, S[i], alpha[i], a.volume[i], xj, p.radius[j], S[j], kD, etaD, rho0, gd, c) *
                      limit[j];
          else if (S[j] < S[i])
            change -= diffusionFlux(xj, p.radius[j], S[j], alpha[j], a.volume[j], xi, hi, S[i], kD, etaD, rho0, gd, c) *
                      limit[i];
        });
        change = laneSum(lanes, change);
        if (lanes.leader()) next[i] = maxf(a.held[i] + change, 0.f);
      }, "wet.diffuse.exchange", kListLanes);
    }
    applyHeldWater(d, a, c, "wet.diffuse.apply");
  }
}

void applyHeldWater(Device d, WetArrays a, float c, const char* stage) {
  const float* next = a.scratchC;
  forEachClothParticle(d, a.cloth, SOAK_LAMBDA(int i) {
    a.held[i] = next[i];
    a.saturation[i] = saturationOf(c, next[i], a.volume[i]);
  }, stage);
}

void transferBuffers(Device d, ParticleView p, WetArrays a, const WetParams& w, WaterReference ref,
                     float dt, int* due) {
  const Vec3 gd = ref.gravityDir;
  // The share of a buffer that moves this step: all of it in one of the
  // paper's steps (Doc/model.md, "Rates per second").
  const float share = minf(stepFraction(w.bufferShare, dt, w.rates), 1.f);
  const float mThr = w.mThreshold;
  const float threshold = w.beta * ref.gravity;
  float* out = a.scratchA;
  float* norm = a.scratchB;
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

void stickWetCloth(Device d, ParticleView p, ClothView c, WetArrays a, const WetParams& w, float dt) {
  const float sT = w.sT, kAd = w.kappaAd, etaAd = w.etaAd >= 0.f ? w.etaAd : w.kappaAd * w.sT * w.sT;
  const float* S = a.saturation;
  Vec3* delta = a.delta;
  forEachClothItemLanes(d, a.cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
    const Float4 xi4 = p.predicted[i];
    if (xi4.w == 0.f) {
      if (lanes.leader()) delta[i] = Vec3(0.f, 0.f, 0.f);
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
    if (lanes.leader()) delta[i] = f * (dt * dt * xi4.w);
  }, "wet.stick", kListLanes);
  applyCorrectionsAt(d, p, a.cloth.slot, a.cloth.count, delta, "wet.stick.apply");
}

}  // namespace soak::wet

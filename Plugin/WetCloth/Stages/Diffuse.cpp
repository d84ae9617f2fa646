// wet.diffuse: the saturation constraint of Eq. 12-17 (conservative or
// literal), or Fick's law (FickDiffusion.cpp, diffusionForm=fick).
#include "Stages/FickDiffusion.h"
#include <algorithm>
#include <cmath>

#include "Backend/ForEach.h"
#include "Simulation/Simulation.h"
#include "Stages/WetStages.h"
#include "WetKernels.h"
#include "WetState.h"

namespace soak::wet {

namespace {

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

}  // namespace

void diffuseWater(Device d, ParticleView p, WetArrays a, const WetParams& w, WaterReference ref,
                  float dt, DiffusionScratch s) {
  const DiffusionSchedule schedule = diffusionSchedule(w, dt);
  const float c = w.c, sMax = w.sMax, kD = w.kappaD, etaD = w.etaD, kS = schedule.smoothing, eps = w.epsilon;
  const float rho0 = w.clothRestDensity;
  const bool literal = w.form == DiffusionForm::Literal;
  const Vec3 gd = ref.gravityDir;
  float* alpha = s.alpha;
  float* limit = s.limit;
  float* next = s.next;
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
    applyHeldWater(d, a, next, c, "wet.diffuse.apply");
  }
}


void applyHeldWater(Device d, WetArrays a, const float* next, float c, const char* stage) {
  forEachClothParticle(d, a.cloth, SOAK_LAMBDA(int i) {
    a.held[i] = next[i];
    a.saturation[i] = saturationOf(c, next[i], a.volume[i]);
  }, stage);
}

void runDiffuse(WetState& st, Simulation& s) {
  const WetParams& w = st.w;
  const float dt = float(s.settings.timeStep);
  if (w.form != DiffusionForm::Fick) {
    diffuseWater(s.device(), s.particles.view(), st.arrays(s), w, st.ref, dt, st.diffusionScratch());
    return;
  }
  if (w.diffusionIterations == 0) return;
  // Neighbours closer than half the shortest rest edge: cloth squeezed to half.
  const int substeps = std::max(w.diffusionIterations, fickSubsteps(w, dt, 0.5f * s.cloth.minEdgeLength()));
  diffuseFick(s.device(), s.particles.view(), st.arrays(s), s.cloth.view().materialCoord, w, st.ref, dt,
              std::min(substeps, kMaxDiffusionPasses), st.fickScratch());
}

}  // namespace soak::wet

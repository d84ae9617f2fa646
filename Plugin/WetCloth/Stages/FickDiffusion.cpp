#include "Stages/FickDiffusion.h"

#include <algorithm>
#include <cmath>

#include "Backend/ForEach.h"
#include "WetKernels.h"

namespace soak::wet {

namespace {

// The pair weight w(r) = h - r: the shape of the viscosity kernel's
// Laplacian (Eq. 12's), positive on the whole support. Its scale cancels in
// the normalised Laplacian below.
SOAK_INLINE float pairWeight(float r2, float hi, float hj) {
  const float h = pairSupport(hi, hj);
  if (r2 >= h * h || r2 == 0.f) return 0.f;
  return h - sqrtf(r2);
}

// What a cloth particle's side of a pair needs.
struct FickPoint {
  Vec3 x, material;  // position; material coordinates (warp u, weft v)
  float h, S, V, norm;
};

// The diffusivity of a pair at angle phi to the warp, p cos^2 + q sin^2,
// chosen so that the sum over a neighbourhood gives div(D grad S) for
// D = diag(D_u, D_v): over the directions of a neighbourhood the means are
// <cos^4> = 3/8 and <cos^2 sin^2> = 1/8, so 3p + q = 4 D_u, p + 3q = 4 D_v.
// (Plain D_u cos^2 + D_v sin^2 gives 1.5 D_u + 0.5 D_v along the warp:
// a spot meant to spread 4:1 spreads 1.9:1.) q < 0 where D_u > 3 D_v would
// let water flow from drier to wetter across the weft, so it is clamped at
// zero: the ratio of the two diffusivities is exact between 1/3 and 3.
SOAK_INLINE float pairDiffusivity(const FickPoint& a, const FickPoint& b, float Du, float Dv) {
  if (Du == Dv) return Du;
  const Vec3 m = a.material - b.material;
  const float uu = m.x * m.x, vv = m.y * m.y;
  if (!(uu + vv > 0.f)) return 0.5f * (Du + Dv);
  const float p = maxf(0.5f * (3.f * Du - Dv), 0.f), q = maxf(0.5f * (3.f * Dv - Du), 0.f);
  return (p * uu + q * vv) / (uu + vv);
}

// Water (kg/s) flowing into a from b. The Laplacian is normalised per
// particle, L S_a = sum_b w~_ab (S_b - S_a) with w~_ab = 2 w_ab (1/N_a +
// 1/N_b) and N = sum w r^2, which is exact for a quadratic field on a
// surface (sum w~ r^2 = 4) and symmetric, so a pair's two sides see one
// flux. Drainage moves water from the particle above to the one below at
// u times their height difference along gravity (upwind).
SOAK_INLINE float fickFlux(const FickPoint& a, const FickPoint& b, float Du, float Dv, float u, float c, Vec3 g) {
  const Vec3 xab = a.x - b.x;
  const float w = pairWeight(lengthSquared(xab), a.h, b.h);
  if (w == 0.f || a.norm <= 0.f || b.norm <= 0.f) return 0.f;
  const float wt = 2.f * w * (1.f / a.norm + 1.f / b.norm);
  const float drop = dot(xab, g);  // > 0: a lies below b
  const float drain = drop > 0.f ? drop * b.S : drop * a.S;
  return 0.5f * (a.V + b.V) / c * wt * (pairDiffusivity(a, b, Du, Dv) * (b.S - a.S) + u * drain);
}

SOAK_INLINE FickPoint fickPoint(const ParticleView& p, const Vec3* material, const float* S, const float* V,
                                const float* norm, int k) {
  return FickPoint{p.predicted[k].xyz(), material[p.id[k]], p.radius[k], S[k], V[k], norm[k]};
}

// The flux into slot i from slot j, evaluated with the lower slot first so
// that both sides of the pair compute the same bits.
SOAK_INLINE float fluxInto(int i, const FickPoint& pi, int j, const FickPoint& pj, float Du, float Dv, float u, float c,
                           Vec3 g) {
  return i < j ? fickFlux(pi, pj, Du, Dv, u, c, g) : -fickFlux(pj, pi, Du, Dv, u, c, g);
}

}  // namespace

int fickSubsteps(const WetParams& w, float dt, float closest) {
  // Explicit diffusion stays monotone while dt sum_j w~_ij (D + u |d_ij|)
  // <= 1; with sum_j w~ r^2 = 4 and r >= closest that sum is at most
  // 4 D / closest^2 + 4 u / closest. Half of that bound, for margin.
  if (!(closest > 0.f)) return 1;
  const double D = std::max(w.diffusivity, weftDiffusivity(w));
  const double rate = 4.0 * D / (double(closest) * closest) + 4.0 * w.drainageSpeed / closest;
  const double n = std::ceil(double(dt) * rate / 0.5);
  return int(std::min(std::max(n, 1.0), double(kMaxDiffusionPasses)));
}

void diffuseFick(Device d, ParticleView p, WetArrays a, const Vec3* material, const WetParams& w, WaterReference ref,
                 float dt, int substeps, FickScratch s) {
  const float c = w.c, Du = w.diffusivity, Dv = weftDiffusivity(w), u = w.drainageSpeed, h = dt / float(substeps);
  const Vec3 g = ref.gravityDir;
  float* norm = s.norm;
  float* limit = s.limit;
  float* next = s.next;
  float* S = a.saturation;
  // N_i = sum_j w_ij r_ij^2 over the particle's own cloth; the cloth does
  // not move while the water spreads.
  forEachClothItemLanes(d, a.cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
    const Vec3 xi = p.predicted[i].xyz();
    const float hi = p.radius[i];
    float n = 0.f;
    forEachClothNeighbour(a.clothNeighbours, v, lanes, [&](int j) {
      if (j == i || p.phase[j] != p.phase[i]) return;
      const float r2 = lengthSquared(xi - p.predicted[j].xyz());
      n += pairWeight(r2, hi, p.radius[j]) * r2;
    });
    n = laneSum(lanes, n);
    if (!lanes.leader()) return;
    norm[i] = n;
    S[i] = saturationOf(c, a.held[i], a.volume[i]);
  }, "wet.fick.norm", kListLanes);
  const float* V = a.volume;
  for (int step = 0; step < substeps; ++step) {
    // What each particle would give this sub-step, scaled down where that
    // is more than it holds.
    forEachClothItemLanes(d, a.cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
      const FickPoint pi = fickPoint(p, material, S, V, norm, i);
      float out = 0.f;
      forEachClothNeighbour(a.clothNeighbours, v, lanes, [&](int j) {
        if (j == i || p.phase[j] != p.phase[i]) return;
        out += maxf(-fluxInto(i, pi, j, fickPoint(p, material, S, V, norm, j), Du, Dv, u, c, g), 0.f);
      });
      out = laneSum(lanes, out) * h;
      if (lanes.leader()) limit[i] = out > a.held[i] ? a.held[i] / out : 1.f;
    }, "wet.fick.limit", kListLanes);
    forEachClothItemLanes(d, a.cloth, SOAK_LAMBDA(int i, int v, Lanes lanes) {
      const FickPoint pi = fickPoint(p, material, S, V, norm, i);
      float change = 0.f;
      forEachClothNeighbour(a.clothNeighbours, v, lanes, [&](int j) {
        if (j == i || p.phase[j] != p.phase[i]) return;
        const float f = fluxInto(i, pi, j, fickPoint(p, material, S, V, norm, j), Du, Dv, u, c, g);
        change += f * (f > 0.f ? limit[j] : limit[i]);
      });
      change = laneSum(lanes, change) * h;
      if (lanes.leader()) next[i] = maxf(a.held[i] + change, 0.f);
    }, "wet.fick.exchange", kListLanes);
    applyHeldWater(d, a, next, c, "wet.fick.apply");
  }
}

}  // namespace soak::wet

#pragma once
// diffusionForm="fick": water spreads through the fabric by Fick's law with
// a diffusivity D (m^2/s) and drains along it under gravity at a speed u
// (m/s), in place of the paper's saturation constraint (Eq. 12-17):
//   dS/dt = div(D grad S) - div(u g_t S)
// with g_t gravity's direction along the cloth and D = diag(D_warp, D_weft)
// in the fabric's material coordinates (warp along u, weft along v). A wicking front then rises
// as h^2 = K t, K = 4 D erfc^-1(S_front / S_bath)^2 (a diffusion front from
// a wet edge), and levels off where drainage balances diffusion, at
// h = (D / u) ln(S_bath / S_front). Doc/model.md, "Fick diffusion".
#include "WetPhysics.h"

namespace soak::wet {

// Explicit sub-steps of the diffusion a step of dt needs to stay
// monotone: neighbours closer than `closest` are not expected.
int fickSubsteps(const WetParams& w, float dt, float closest);

// wet.diffuse, Fick form: `substeps` explicit sub-steps over the cloth's
// neighbour lists. Each pair exchanges one flux, so water is conserved to
// round-off; a donor never gives more than it holds.
// `material`: the cloth's material coordinates per vertex (ClothView), for
// the warp and weft diffusivities.
struct FickScratch {  // per slot
  float* norm = nullptr;   // N_i = sum_j w_ij r_ij^2
  float* limit = nullptr;  // the share of its outflow a donor can give
  float* next = nullptr;   // held water after the sub-step
};
void diffuseFick(Device d, ParticleView p, WetArrays a, const Vec3* material, const WetParams& w, WaterReference ref,
                 float dt, int substeps, FickScratch s);

}  // namespace soak::wet

#include "Fluid/FluidSolver.h"

#include <cmath>

#include "Backend/ForEach.h"
#include "Backend/Primitives.h"
#include "Cloth/ClothVolume.h"
#include "Fluid/SphKernels.h"
#include "Physics/Integrate.h"

namespace soak {

// Units used below (Doc/model.md, "Water"): masses are relative to the water
// particle mass m0 (mu_i = m_i / m0, psi_k = rho0 V_k / m0 for a cloth
// boundary particle) and Lambda_i = m0 * lambda_i, so that
//   Lambda_i = -C_i rho0^2 / (G_i + eps G0),
//   G_i = sum_j mu_j |g_ij|^2 + sum_k psi_k^2 / mu_k |g_ik|^2 + |sum_j mu_j g_ij + sum_k psi_k g_ik|^2 / mu_i,
//   dx_i = 1 / (rho0 m0) [ sum_j (Lambda_i mu_j / mu_i + Lambda_j + s_ij mu_j) g_ij + sum_k Lambda_i psi_k / mu_i g_ik ],
//   dx_k = 1 / (rho0 m0) psi_k / mu_k sum_j Lambda_j g_kj          (cloth reaction),
// with g_ij the Spiky gradient of W(x_i - x_j, h_ij) with respect to x_i.
// With equal masses and no cloth this is exactly PBF's
// dx_i = 1/rho0 sum_j (lambda_i + lambda_j + s_corr) grad W_ij.

FluidSolver::FluidSolver(Device device)
    : device_(device), lambda_(device), density_(device), volume_(device), scratch_(device), spare_(device),
      omega_(device), attributes_(device), neighbours_(device) {}

void FluidSolver::configure(const WaterSettings& water) {
  const float h = water.supportRadius, s = water.spacing;
  const int reach = int(std::ceil(h / s)) + 1;
  double g2 = 0.0;
  for (int k = -reach; k <= reach; ++k)
    for (int j = -reach; j <= reach; ++j)
      for (int i = -reach; i <= reach; ++i) {
        Vec3 x(float(i) * s, float(j) * s, float(k) * s);
        float r = length(x);
        g2 += lengthSquared(spikyGradient(x, r, h));
      }
  restDenominator_ = float(g2);
  wall_ = makeWallDensityTable(s, h, water.particleMass);
}

std::vector<float> FluidSolver::downloadDensity(int count) const {
  std::vector<float> out = density_.download();
  out.resize(std::size_t(count), 0.f);
  return out;
}

void FluidSolver::resize(int n) {
  lambda_.resize(n);
  density_.resize(n);
  volume_.resize(n);
  scratch_.resize(n);
  spare_.resize(n);
  omega_.resize(n);
  attributes_.resize(n);
}

void FluidSolver::computeBoundaryVolumes(ParticleView p, GridView clothGrid, ClothSlots cloth) {
  resize(p.count);
  computeClothVolumes(device_, p, clothGrid, cloth, volume_.data());
}

namespace {

// FluidAttributes: per particle, Float4(h, mu = m / m0, psi (cloth: rho0 V /
// m0, else 0), kind), kind one of:
constexpr float kFluidOther = 0.f, kFluidWater = 1.f, kFluidCloth = 2.f;

// Blocks of 256 threads the two list passes keep resident per SM: 5 caps
// them at 48 registers (40 warps). The grid walk for particles without a
// list (FluidNeighbours.h) had raised them from 46-47 to 54, which fits only
// 4 blocks (32 warps).
constexpr int kFluidPassBlocks = 5;

// Lane groups of the two list passes: as wide as it takes to put about 400k
// threads in flight, not a million as for the other passes (their loops are
// short: about 45 entries a particle); 8 lanes for fig5b's 60k particles and
// fig9b's 99k, 4 for the 100k scale scene's. H100, fluid.solve ms at
// 4 / 8 / 16 lanes: fig9b (99k particles) 1.20 / 1.17 / 1.39, the 100k
// scale scene 0.905 / 0.96 / 1.16, fig5b (60k) 0.615 / 0.61 / 0.73, fig1
// (16.5k) 0.38 / 0.275 / 0.235 (Doc/performance.md).
constexpr int kFluidPassThreads = 400000;

struct CorrectionConstants {
  float rho0, m0, corrK, corrQ, moveScale, dt;
  const Collider* colliders;
  int colliderCount;
  const WallDensityTable* wall;
  const float* clothFrictionScale;  // per cloth vertex (field::kFrictionScale); null: 1
};

// dx of every water particle and of the cloth particles it touches, from the
// multipliers `lam` (see the units comment above); then, for every slot,
// next = x* + dx projected out of the colliders (x* as it is when it does
// not move). Written to `next`, not to x*, which the pass's neighbours
// still read: the two buffers swap roles each iteration. This is the old
// three launches (corrections, x* += dx, colliders) in one, same bits.
void applyDensityCorrections(Device d, ParticleView p, FluidNeighbourView g, const float* lam, const Float4* attr,
                             Float4* next, CorrectionConstants k) {
  const float corrK = k.corrK, corrQ = k.corrQ, moveScale = k.moveScale, m0 = k.m0, dt = k.dt;
  const Collider* colliders = k.colliders;
  const int colliderCount = k.colliderCount;
  const WallDensityTable wall = *k.wall;
  const float* clothFriction = k.clothFrictionScale;
    // Position corrections of water particles and of the cloth they touch.
  forEachLanes<kFluidPassBlocks>(d, p.count, SOAK_LAMBDA(int i, Lanes lanes) {
    const int phi = p.phase[i];
    const Float4 xi4 = p.predicted[i];
    Vec3 dx(0.f, 0.f, 0.f);
    if (isWater(phi)) {
      const Vec3 xi = xi4.xyz();
      const Float4 ai = attr[i];
      const float hi = ai.x, mui = ai.y, li = lam[i];
      const float liOverMui = li / mui;
      SphPairFactors kernel;
      forEachListedNeighbour(g, i, lanes, [&](int j) {
        if (j == i) return;
        const Float4 aj = attr[j];
        const Vec3 xij = xi - p.predicted[j].xyz();
        const float r2 = lengthSquared(xij);
        const float h = pairSupport(hi, aj.x);
        if (h != kernel.h) kernel.setFor(h, corrQ);
        if (r2 >= kernel.h2) return;
        const Vec3 gr = kernel.spikyGradientAt(xij, r2);
        const float muj = aj.y;
        if (aj.w == kFluidWater) {
          // Artificial pressure s_corr = -k (W(r) / W(dq))^4 against clumping.
          const float ratio = kernel.poly6RatioAt(r2);
          const float scorr = -corrK * ratio * ratio * ratio * ratio;
          dx += gr * (liOverMui * muj + lam[j] + scorr * muj);
        } else {
          dx += gr * (liOverMui * aj.z);
        }
      });
      dx = laneSum(lanes, dx);
      if (colliderCount > 0) {
        // The wall's share of grad_i C_i (its density gradient), as for cloth boundary particles.
        Vec3 wallGradient;
        collidersDensity(wall, colliders, colliderCount, xi, wallGradient);
        dx += wallGradient * (li / (m0 * mui));
      }
      dx = dx * moveScale;
    } else if (isCloth(phi) && xi4.w > 0.f) {
      const Vec3 xi = xi4.xyz();
      const Float4 ai = attr[i];
      const float hi = ai.x, psi = ai.z, mui = ai.y;
      SphPairFactors kernel;
      forEachListedNeighbour(g, i, lanes, [&](int j) {
        const Vec3 xij = xi - p.predicted[j].xyz();
        const float r2 = lengthSquared(xij);
        const float h = pairSupport(hi, attr[j].x);
        if (h != kernel.h) kernel.setFor(h, corrQ);
        if (r2 >= kernel.h2) return;
        dx += kernel.spikyGradientAt(xij, r2) * lam[j];
      });
      dx = laneSum(lanes, dx) * (moveScale * psi / mui);
    }
    if (!lanes.leader()) return;
    Float4 x = xi4;
    if (x.w > 0.f) {
      if (dx.x != 0.f || dx.y != 0.f || dx.z != 0.f) x = Float4(x.xyz() + dx, x.w);
      if (colliderCount > 0)
        x = Float4(projectOutOfColliders(colliders, colliderCount, p.position[i].xyz(), x.xyz(),
                                         kCollisionRadiusScale * p.radius[i], dt,
                                         clothFriction && isCloth(phi) ? clothFriction[p.id[i]] : 1.f),
                   x.w);
    }
    next[i] = x;
  }, "fluid.delta", kListLanes, kFluidPassThreads);
}

}  // namespace

void FluidSolver::solve(ParticleState& particles, const FluidContext& f, bool sizeLists) {
  ParticleView p = particles.view();
  if (p.count == 0) return;
  resize(p.count);
  // Pairs within (1 + skin) h, once per step (FluidNeighbours.h).
  neighbours_.build(p, f.grid, f.water.neighbourSkin, sizeLists);
  FluidNeighbourView g = neighbours_.view();
  const WaterSettings ws = f.water;
  const float rho0 = ws.restDensity, m0 = ws.particleMass;
  const float eps = ws.relaxation * restDenominator_;
  // A lattice sparser than h has no neighbours and a zero denominator: then
  // there is no artificial pressure (and no relaxation to scale).
  const float corrK = restDenominator_ > 0.f ? ws.artificialPressure * rho0 * rho0 / restDenominator_ : 0.f;
  const float corrQ = ws.artificialPressureRadius;
  const Collider* colliders = f.colliders;
  const int colliderCount = f.colliderCount;
  const WallDensityTable wall = wall_;
  const CorrectionConstants k{rho0, m0, corrK, corrQ, 1.f / (rho0 * m0), f.dt,
                              colliders, colliderCount, &wall_, f.clothFrictionScale};
  float* lam = lambda_.data();
  float* rho = density_.data();
  const float* volume = volume_.data();
  // x* of this iteration (read) and of the next (written); swapped after
  // each iteration (applyDensityCorrections).
  Float4* const own = p.predicted;
  Float4* spare = spare_.data();
  // What the passes read of a neighbour besides its position, in one load
  // (FluidAttributes): fixed for the whole solve.
  Float4* attr = attributes_.data();
  forEach(device_, p.count, SOAK_LAMBDA(int i) {
    const int ph = p.phase[i];
    const float kind = isWater(ph) ? kFluidWater : isCloth(ph) ? kFluidCloth : kFluidOther;
    attr[i] = Float4(p.radius[i], p.mass[i] / m0, isCloth(ph) ? rho0 * volume[i] / m0 : 0.f, kind);
  }, "fluid.attributes");
  for (int it = 0; it < ws.iterations; ++it) {
    // Lambda of every water particle (Eq. 6-7 and the mass-weighted PBD step).
    forEachLanes<kFluidPassBlocks>(device_, p.count, SOAK_LAMBDA(int i, Lanes lanes) {
      if (!isWater(p.phase[i])) {
        if (lanes.leader()) lam[i] = 0.f;
        return;
      }
      const Vec3 xi = p.predicted[i].xyz();
      const Float4 ai = attr[i];
      const float hi = ai.x, mui = ai.y;
      float dens = 0.f, sumG2 = 0.f;
      Vec3 gradSelf(0.f, 0.f, 0.f);
      SphPairFactors kernel;
      forEachListedNeighbour(g, i, lanes, [&](int j) {
        const Float4 aj = attr[j];
        const Float4 xj = p.predicted[j];
        const Vec3 xij = xi - xj.xyz();
        const float r2 = lengthSquared(xij);
        const float h = pairSupport(hi, aj.x);
        if (h != kernel.h) kernel.setFor(h, corrQ);
        if (r2 >= kernel.h2) return;
        const float muj = aj.y;
        if (aj.w == kFluidWater) {
          dens += muj * kernel.poly6At(r2);
          if (j == i) return;
          Vec3 gr = kernel.spikyGradientAt(xij, r2);
          gradSelf += gr * muj;
          sumG2 += muj * lengthSquared(gr);
        } else {
          const float psi = aj.z;
          dens += psi * kernel.poly6At(r2);
          Vec3 gr = kernel.spikyGradientAt(xij, r2);
          gradSelf += gr * psi;
          if (xj.w > 0.f) sumG2 += psi * psi / muj * lengthSquared(gr);
        }
      });
      dens = laneSum(lanes, dens);
      sumG2 = laneSum(lanes, sumG2);
      gradSelf = laneSum(lanes, gradSelf);
      if (!lanes.leader()) return;
      if (colliderCount > 0) {
        Vec3 wallGradient;
        dens += collidersDensity(wall, colliders, colliderCount, xi, wallGradient) / m0;
        gradSelf += wallGradient * (1.f / m0);
      }
      rho[i] = dens * m0;
      const float C = maxf(rho[i] / rho0 - 1.f, 0.f);  // unilateral: compression only
      const float G = sumG2 + lengthSquared(gradSelf) / mui;
      lam[i] = G + eps > 0.f ? -C * rho0 * rho0 / (G + eps) : 0.f;  // a lone particle: nothing to solve
    }, "fluid.lambda", kListLanes, kFluidPassThreads);
    applyDensityCorrections(device_, p, g, lam, attr, spare, k);
    std::swap(p.predicted, spare);
    g.predicted = p.predicted;
  }
  // After an odd number of iterations x* lies in the spare buffer.
  if (p.predicted != own) particles.swapPredicted(spare_);
}

namespace {

// Lane groups of XSPH's and vorticity's walks of the 27 cells: about a
// quarter of a million threads, and at least 2 lanes. H100, `finalize` ms
// with groups aimed at 1M / 500k / 250k threads: fig9b 0.28 / 0.214 /
// 0.187, fig5b 0.164 / 0.164 / 0.120, the 100k scale scene 0.245 / 0.206 /
// 0.20; at 1M particles with 1 / 2 / 4 lanes 2.47 / 2.28 / 2.30, at 4M
// 10.35 / 10.04 / 10.54 (Doc/performance.md).
constexpr int kGridWalkThreads = 250000;
constexpr int kGridWalkMinLanes = 2;
// Blocks of 256 threads XSPH's walk keeps resident per SM (registers capped
// from 62 to 40 to fit): H100 `finalize` 1M 2.26 -> 2.02 ms, 2.10 at 5
// blocks; fig9b unchanged (0.183-0.186 ms) (Doc/performance.md).
constexpr int kXsphBlocks = 6;

// Calls f(j, x_ij, r^2, h_ij) for every other water particle j within h_ij of
// water particle i, at the positions after the step's velocity update.
template <class F>
SOAK_INLINE void forEachWaterNeighbour(const GridView& g, const ParticleView& p, int i, const Lanes& lanes, F&& f) {
  const Vec3 xi = p.position[i].xyz();
  const float hi = p.radius[i];
  forEachCandidate(g, g.slotKey[i], lanes, [&](int j) {
    if (j == i || !isWater(p.phase[j])) return;
    const Vec3 xij = xi - p.position[j].xyz();
    const float r2 = lengthSquared(xij);
    const float h = pairSupport(hi, p.radius[j]);
    if (r2 < h * h) f(j, xij, r2, h);
  });
}

}  // namespace

void FluidSolver::applyViscosity(ParticleView p, const FluidContext& f) {
  const WaterSettings ws = f.water;
  if (ws.viscosity <= 0.f && ws.vorticity <= 0.f) return;
  if (p.count == 0) return;
  resize(p.count);
  GridView g = f.grid;
  const float rho0 = ws.restDensity, c = ws.viscosity, vort = ws.vorticity;
  const float dt = f.dt;
  const float* rho = density_.data();
  Float4* vnew = spare_.data();  // the new velocity (xyz)
  Vec3* omega = omega_.data();
  float* omegaNorm = scratch_.data();
  forEachLanes<kXsphBlocks>(device_, p.count, SOAK_LAMBDA(int i, Lanes lanes) {
    const Vec3 vi = p.velocity[i];
    if (!isWater(p.phase[i])) {
      if (lanes.leader()) {
        vnew[i] = Float4(vi, 0.f);
        omega[i] = Vec3(0.f, 0.f, 0.f);
        omegaNorm[i] = 0.f;
      }
      return;
    }
    Vec3 visc(0.f, 0.f, 0.f), w(0.f, 0.f, 0.f);
    SphPairFactors kernel;
    forEachWaterNeighbour(g, p, i, lanes, [&](int j, Vec3 xij, float r2, float h) {
      if (h != kernel.h) kernel.setFor(h, 0.f);
      const float vol = p.mass[j] / maxf(rho[j], 0.5f * rho0);
      const Vec3 vij = p.velocity[j] - vi;
      visc += vij * (vol * kernel.poly6At(r2));
      w += cross(vij, kernel.spikyGradientAt(xij, r2)) * (-vol);  // curl v (Macklin & Mueller, Eq. 15)
    });
    visc = laneSum(lanes, visc);
    w = laneSum(lanes, w);
    if (!lanes.leader()) return;
    vnew[i] = Float4(vi + visc * c, 0.f);  // XSPH
    omega[i] = w;
    omegaNorm[i] = length(w);
  }, "fluid.xsph", kGridWalkMinLanes, kGridWalkThreads);
  if (vort > 0.f) {
    forEachLanes(device_, p.count, SOAK_LAMBDA(int i, Lanes lanes) {
      if (!isWater(p.phase[i])) return;
      Vec3 eta(0.f, 0.f, 0.f);
      SphPairFactors kernel;
      forEachWaterNeighbour(g, p, i, lanes, [&](int j, Vec3 xij, float r2, float h) {
        if (h != kernel.h) kernel.setFor(h, 0.f);
        const float vol = p.mass[j] / maxf(rho[j], 0.5f * rho0);
        eta += kernel.spikyGradientAt(xij, r2) * (vol * omegaNorm[j]);
      });
      eta = laneSum(lanes, eta);
      if (!lanes.leader()) return;
      const Vec3 N = normalizedOrZero(eta);
      // Vorticity confinement force, as acceleration. This pass reads no
      // velocity, so it writes the new one in place (other slots keep theirs).
      p.velocity[i] = vnew[i].xyz() + cross(N, omega[i]) * (vort * dt);
    }, "fluid.vorticity", kGridWalkMinLanes, kGridWalkThreads);
    return;
  }
  forEach(device_, p.count, SOAK_LAMBDA(int i) { p.velocity[i] = vnew[i].xyz(); }, "fluid.velocity");
}

const float* FluidSolver::compressionPerParticle(ParticleView p, const FluidContext& f) {
  if (p.count == 0) return nullptr;
  resize(p.count);
  GridView g = f.grid;
  const float rho0 = f.water.restDensity;
  const Collider* colliders = f.colliders;
  const int colliderCount = f.colliderCount;
  const WallDensityTable wall = wall_;
  float* err = scratch_.data();
  float* isWaterFlag = lambda_.data();  // scratch here: the solver recomputes lambda every iteration
  const float* volume = volume_.data();
  forEach(device_, p.count, SOAK_LAMBDA(int i) {
    err[i] = 0.f;
    isWaterFlag[i] = isWater(p.phase[i]) ? 1.f : 0.f;
    if (!isWater(p.phase[i])) return;
    const Vec3 xi = p.position[i].xyz();
    const float hi = p.radius[i];
    float dens = 0.f;
    forEachCandidate(g, g.slotKey[i], [&](int j) {
      const int phj = p.phase[j];
      const float h = pairSupport(hi, p.radius[j]);
      const float r2 = lengthSquared(xi - p.position[j].xyz());
      if (isWater(phj)) dens += p.mass[j] * poly6(r2, h);
      else if (isCloth(phj)) dens += rho0 * volume[j] * poly6(r2, h);
    });
    if (colliderCount > 0) {
      Vec3 wallGradient;
      dens += collidersDensity(wall, colliders, colliderCount, xi, wallGradient);
    }
    err[i] = maxf(dens / rho0 - 1.f, 0.f);
  }, "fluid.error");
  return err;
}

void FluidSolver::densityError(ParticleView p, const FluidContext& f, double& mean, float& max) {
  mean = 0.0;
  max = 0.f;
  const int n = p.count;
  const float* err = compressionPerParticle(p, f);
  if (!err) return;
  max = maxf(reduceMax(device_, err, n), 0.f);
  const double sum = reduceSum(device_, err, n);
  const double water = reduceSum(device_, lambda_.data(), n);
  mean = water > 0.0 ? sum / water : 0.0;
}

}  // namespace soak

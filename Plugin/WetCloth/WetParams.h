#pragma once
// Parameters of the wetting model (paper Section 4, Table 1). The defaults
// here are the scene's defaults: WetClothPlugin.cpp binds each member to its
// scene attribute (Registry/ParamBinding.h), with units, ranges and
// descriptions.
#include <algorithm>
#include <cmath>

namespace soak::wet {

enum class DiffusionForm { Conservative = 0, Literal = 1, Fick = 2 };

// The paper's rates (Table 1) are fractions per step of its time step,
// 0.015 s. PerSecond reads them as rates per second (rate x dt per step), so
// results converge as dt -> 0; PerStep is the paper's form (rate x 0.015 s
// per step whatever the time step). Doc/model.md, "Rates per second".
enum class RateForm { PerSecond = 0, PerStep = 1 };

// How Eq. 20's attraction acts. Force: as the force it is, an impulse
// f dt / m on the velocity at the end of the step, so that the next step's
// prediction carries it into the cloth solve, which weighs it against the
// cloth's stretch (Algorithm 1 line 2 with the forces of its last line).
// Correction: a displacement dt^2 f / m of the positions the cloth solve
// left, which no constraint sees before the frame. Doc/model.md, "Wet
// sticking as a force".
enum class StickForm { Force = 0, Correction = 1 };
constexpr double kPaperTimeStep = 0.015;  // s

struct WetParams {
  float sMax = 0.4f;           // S^MAX (Eq. 10)
  float sEW = 0.35f;           // S^EW: emission threshold (Section 4.4)
  float sT = 0.12f;            // S^T = 0.3 S^MAX (Section 4.5)
  float c = 0.001f;            // Eq. 10: S = c m_water / V (m^3/kg; 1/rho_water makes S a volume fraction)
  // Rates are kept as what they do in one of the paper's steps (0.015 s):
  // the value at dt = 0.015 is then Table 1's to the bit.
  float kappaA = 0.1f;         // absorption (Eq. 11), per 0.015 s
  float etaA = 0.4f;           // gravity influence on absorption (Eq. 11)
  float kappaD = 0.5f;         // diffusion rate (Eq. 12)
  float etaD = 0.6f;           // gravity influence on diffusion (Eq. 12)
  float kappaS = 0.8f;         // saturation smoothing (Eq. 17), per 0.015 s
  float epsilon = 0.1f;        // Eq. 15 relaxation, relative to (sum_j a_ij)^2
  int diffusionIterations = 1;
  DiffusionForm form = DiffusionForm::Conservative;
  // DiffusionForm::Fick (FickDiffusion.h): Fick's law with a diffusivity
  // and a gravity drainage speed, in place of Eq. 12-17.
  float diffusivity = 1e-4f;   // m^2/s, along the warp (material u)
  float diffusivityWeft = -1.f;  // m^2/s, along the weft (material v); < 0: the warp's
  float drainageSpeed = 0.f;   // m/s
  float beta = 10.f;           // Eq. 18; see Doc/model.md
  float bufferShare = 1.f;     // share of a buffer Eq. 18 moves down, per 0.015 s
  RateForm rates = RateForm::PerSecond;
  float mThreshold = 0.002f;   // drip mass (kg)
  float kappaE = 10.f;         // Eq. 19 attraction (m/s^2)
  float etaE = 0.02f;          // Eq. 19 saturation weight (kg)
  float kappaAd = 0.3f;        // Eq. 20 (N)
  float etaAd = -1.f;          // Eq. 20 (N); < 0: kappaAd * S^T^2 (no pull between dry particles)
  float clothRestDensity = 800.f;  // Table 1, for Psi of Eq. 19
  float initialSaturation = 0.f;  // every cloth particle starts holding S V / c (Figure 6's scenes)
  bool emission = true, sticking = true, wetWeight = true;
  StickForm stickForm = StickForm::Force;
  // Beyond the paper (Doc/model.md, "Wet stiffness and friction"): at
  // saturation S the bends are 1 - wetBendSoftening S / S^MAX as stiff and
  // colliders grip 1 + wetFriction S / S^MAX times as hard.
  float wetBendSoftening = 0.f;
  float wetFriction = 0.f;
};

// A cloth particle whose buffer is below kBufferFloor x m_threshold counts
// as carrying none when it absorbs: the per-second transfer of Eq. 18 moves
// a share of a buffer each step and leaves a tail that shrinks
// geometrically (Doc/model.md, "Rates per second").
constexpr float kBufferFloor = 1e-3f;

inline float weftDiffusivity(const WetParams& w) { return w.diffusivityWeft >= 0.f ? w.diffusivityWeft : w.diffusivity; }

// What a process that does `perPaperStep` in 0.015 s does in one step of dt.
inline float stepFraction(float perPaperStep, float dt, RateForm form) {
  return form == RateForm::PerStep ? perPaperStep : perPaperStep * (dt / float(kPaperTimeStep));
}
// A rate per second as what it does in 0.015 s.
inline float perPaperStep(double ratePerSecond) { return float(ratePerSecond * kPaperTimeStep); }

// How the saturation constraint (Eq. 13-17) runs in one step: `iterations`
// passes, each moving kappa^s = `smoothing` of the way. Per step (the
// paper): diffusionIterations passes of kappa^s each. Per second: the
// step's smoothing (smoothingRate x dt) is split over diffusionIterations passes, or
// more where one pass would move more than kMaxSmoothing (Eq. 17 asks
// kappa^s < 1), up to kMaxDiffusionPasses.
constexpr float kMaxSmoothing = 0.8f;
constexpr int kMaxDiffusionPasses = 256;
struct DiffusionSchedule {
  int iterations = 0;
  float smoothing = 0.f;
};
inline DiffusionSchedule diffusionSchedule(const WetParams& w, float dt) {
  if (w.diffusionIterations <= 0) return {};
  if (w.rates == RateForm::PerStep) return {w.diffusionIterations, w.kappaS};
  const float total = stepFraction(w.kappaS, dt, w.rates);
  const int needed = int(std::ceil(total / kMaxSmoothing));
  const int n = std::min(std::max(w.diffusionIterations, needed), kMaxDiffusionPasses);
  return {n, std::min(total / float(n), kMaxSmoothing)};
}

}  // namespace soak::wet

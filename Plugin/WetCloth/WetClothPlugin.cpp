// The WetCloth plugin: <WetCloth .../> switches the paper's wetting model
// (Section 4) on for every cloth in the scene. Here its parameters are
// declared (Table 1 defaults); WetClothModule.cpp sets the model up and
// Stages/ holds its stages.
#include <algorithm>
#include <cmath>
#include <memory>

#include "Base/Error.h"
#include "Plugins/PluginApi.h"
#include "WetClothModule.h"

namespace soak::wet {
namespace {

WetParams paramsFrom(const ElementParams& e) {
  WetParams w;
  w.sMax = e.realf("sMax");
  w.sEW = e.realf("sEW");
  w.sT = e.given("sT") ? e.realf("sT") : 0.3f * w.sMax;
  w.c = e.realf("c");
  w.kappaA = perPaperStep(e.real("absorptionRate"));
  w.etaA = e.realf("absorptionGravity");
  w.kappaD = e.realf("diffusionRate");
  w.etaD = e.realf("diffusionGravity");
  w.kappaS = perPaperStep(e.real("smoothingRate"));
  w.epsilon = e.realf("diffusionRelaxation");
  w.diffusionIterations = int(e.integer("diffusionIterations"));
  const std::string form = e.text("diffusionForm");
  w.form = form == "literal" ? DiffusionForm::Literal : form == "fick" ? DiffusionForm::Fick : DiffusionForm::Conservative;
  w.diffusivity = e.realf("diffusivity");
  w.drainageSpeed = e.realf("drainageSpeed");
  w.diffusivityWeft = e.realf("diffusivityWeft");
  w.beta = e.realf("emissionBeta");
  w.bufferShare = perPaperStep(e.real("bufferFlowRate"));
  w.rates = e.text("wettingRates") == "perStep" ? RateForm::PerStep : RateForm::PerSecond;
  w.mThreshold = e.realf("dripMass");
  w.kappaE = e.realf("dripAttraction");
  w.etaE = e.realf("dripSaturationWeight");
  w.kappaAd = e.realf("stickiness");
  w.etaAd = e.realf("stickinessOffset");
  w.clothRestDensity = e.realf("clothRestDensity");
  w.emission = e.boolean("emission");
  w.sticking = e.boolean("sticking");
  w.wetWeight = e.boolean("wetWeight");
  w.wetBendSoftening = e.realf("wetBendSoftening");
  w.wetFriction = e.realf("wetFriction");
  return w;
}

DryingParams dryingFrom(const ElementParams& e) {
  DryingParams d;
  d.fluxIntoDryAir = e.realf("dryingRate");
  d.ambientHumidity = e.realf("ambientHumidity");
  d.criticalSaturation = e.realf("dryingCriticalSaturation");
  return d;
}

}  // namespace
}  // namespace soak::wet

SOAK_PLUGIN(WetCloth) {
  using soak::ElementDecl;
  registry.add(
      ElementDecl("WetCloth",
                  "The paper's wetting model (Section 4) for every cloth in the scene: absorption (Eq. 11), "
                  "diffusion (Eq. 12-17), emission and drips (Eq. 18-19), wet sticking (Eq. 20) and coupling "
                  "stiffness that falls with saturation (Eq. 22). Defaults are Table 1's.",
                  "Plugins")
          .real("sMax", "", "0.4", "S^MAX, the most water a cloth particle holds (Eq. 10).", 0.0, 1.0, true)
          .real("sEW", "", "0.35", "S^EW: above it water goes to the emission buffer (Section 4.4).", 0.0, 1.0, true)
          .real("sT", "", "0.12", "S^T (default 0.3 sMax): wet sticking peaks here, coupling softens above it.", 0.0,
                1.0, true)
          .real("c", "m^3/kg", "0.001",
                "Eq. 10's c in S = c m_water / V (the paper gives no value; 1/rho_water makes S the volume "
                "fraction of water).",
                0.0, 1.0, true)
          .choice("wettingRates", {"perSecond", "perStep"}, "perSecond",
                  "perSecond: absorptionRate, smoothingRate and bufferFlowRate are rates per second, applied as "
                  "rate x timeStep each step, so the wetting converges as the time step falls; perStep: the "
                  "paper's form, rate x 0.015 s each step whatever timeStep is (Doc/model.md, 'Rates per second').")
          .real("absorptionRate", "1/s", "6.6666667",
                "kappa^a of Eq. 11 per second (Table 1: 0.1 per step of 0.015 s).", 0.0, 1e4)
          .real("absorptionGravity", "", "0.4",
                "eta^a of Eq. 11 (Table 1 prints eta^d twice; we read 0.4 as eta^a).", 0.0, 1.0)
          .real("diffusionRate", "", "0.5", "kappa^d of Eq. 12.", 0.0, 1e3)
          .real("diffusionGravity", "", "0.6", "eta^d of Eq. 12.", 0.0, 1.0)
          .real("smoothingRate", "1/s", "53.333333",
                "kappa^s of Eq. 17 per second (Table 1: 0.8 per step of 0.015 s). A step runs "
                "diffusionIterations passes, more where one would move more than kappa^s = 0.8 (at most 256).",
                0.0, 1e4)
          .real("diffusionRelaxation", "", "0.1", "epsilon of Eq. 15, relative to (sum_j a_ij)^2.", 0.0, 1e6)
          .integer("diffusionIterations", "1",
                   "Saturation-constraint passes per step (0: no diffusion). Per second they share the step's "
                   "smoothing; per step each moves kappa^s.",
                   0, 1000)
          .choice("diffusionForm", {"conservative", "literal", "fick"}, "conservative",
                  "conservative: pairwise exchange that conserves water and reduces to Eq. 17 per receiver; "
                  "literal: Eq. 17 as printed (does not conserve water); fick: Fick's law with diffusivity and "
                  "drainageSpeed, set from a fabric's measured wicking (Doc/model.md, 'Fick diffusion').")
          .real("diffusivity", "m^2/s", "1e-4",
                "diffusionForm=fick: D of dS/dt = div(D grad S); a wicking front rises as h^2 = K t with "
                "K = 4 D erfc^-1(S_front / S_bath)^2.",
                0.0, 10.0)
          .real("diffusivityWeft", "m^2/s", "-1",
                "diffusionForm=fick: D along the weft (the cloth's v axis, or the mesh's vt v); diffusivity is "
                "then the warp's (u). Negative: the same as diffusivity. A wet spot spreads into an ellipse with "
                "axes in the ratio sqrt(diffusivity / diffusivityWeft).",
                -1.0, 10.0)
          .real("drainageSpeed", "m/s", "0",
                "diffusionForm=fick: speed at which gravity drains water down the fabric; a wicking front levels "
                "off at (diffusivity / drainageSpeed) ln(S_bath / S_front).",
                0.0, 100.0)
          .real("emissionBeta", "1/s^2", "10", "beta of Eq. 18 (no value in the paper; Doc/model.md says why 10).", 0.0, 1e6)
          .real("bufferFlowRate", "1/s", "66.666667",
                "Share of a buffer Eq. 18 moves to the cloth below, per second (the paper moves all of it each "
                "0.015 s step).",
                0.0, 1e6)
          .real("dripMass", "kg", "0.002", "m^threshold: buffer mass that becomes a drip (Table 1).", 0.0, 1.0, true)
          .real("dripAttraction", "m/s^2", "10", "kappa^e of Eq. 19 (Table 1).", 0.0, 1e6)
          .real("dripSaturationWeight", "kg", "0.02", "eta^e of Eq. 19 (no value in the paper).", 0.0, 1e3)
          .real("stickiness", "N", "0.3", "kappa^ad of Eq. 20 (Table 1).", 0.0, 1e6)
          .real("stickinessOffset", "N", "-1",
                "eta^ad of Eq. 20 (no value in the paper); negative: stickiness x sT^2, so dry cloth does not "
                "stick.",
                -1.0, 1e6)
          .real("clothRestDensity", "kg/m^3", "800", "Cloth rest density (Table 1), for Psi of Eq. 19.", 0.0, 1e5,
                true)
          .real("initialSaturation", "", "0", "Saturation every cloth particle starts with.", 0.0, 1.0)
          .boolean("emission", "true", "Buffers, drips and drip attraction (Section 4.4).")
          .boolean("sticking", "true", "Wet cloth sticking (Eq. 20).")
          .boolean("wetWeight", "true", "Held and buffered water add to the cloth particle's mass.")
          .real("wetBendSoftening", "", "0",
                "Beyond the paper: saturated cloth (S = sMax) bends with 1 - wetBendSoftening of its dry bend "
                "stiffness, in proportion to S / sMax between (0: the paper's, wet cloth as stiff as dry; "
                "Doc/model.md, 'Wet stiffness and friction').",
                0.0, 1.0)
          .real("wetFriction", "", "0",
                "Beyond the paper: colliders grip saturated cloth with 1 + wetFriction times their friction, in "
                "proportion to S / sMax between (at most 1 in all; 0: the paper's).",
                0.0, 100.0)
          .real("dryingRate", "kg/(m^2 s)", "0",
                "Beyond the paper: evaporation per area of cloth into dry air while the fabric is wetter than "
                "dryingCriticalSaturation (0: no drying). Held water leaves at dryingRate x (1 - ambientHumidity) "
                "per area, falling in proportion to S below the critical saturation; stats.csv counts it in "
                "evaporated_water_mass (Doc/model.md, 'Drying').",
                0.0, 1e3)
          .real("ambientHumidity", "", "0.5", "Relative humidity of the air the cloth dries into, 0 to 1.", 0.0, 1.0)
          .real("dryingCriticalSaturation", "", "0.1",
                "Saturation below which drying slows in proportion to the water left (the falling-rate period).",
                0.0, 1.0)
          .makeUnique()
          .create([](const soak::ElementParams& e) {
            if (e.realf("initialSaturation") > e.realf("sMax"))
              throw soak::InputError("<WetCloth>: initialSaturation must not exceed sMax", e.where());
            return soak::wet::makeWetClothModule(soak::wet::paramsFrom(e), soak::wet::dryingFrom(e),
                                                 e.realf("initialSaturation"), e.where());
          }));
}

// The WetCloth plugin: <WetCloth .../> switches the paper's wetting model
// (Section 4) on for every cloth in the scene. Here its parameters are
// declared (Table 1 defaults); WetClothModule.cpp sets the model up and
// Stages/ holds its stages.
#include <algorithm>
#include <cmath>
#include <memory>

#include "Base/Error.h"
#include "Plugins/PluginApi.h"
#include "Registry/ParamBinding.h"
#include "WetClothModule.h"

SOAK_PLUGIN(WetCloth) {
  using namespace soak::wet;
  soak::ElementDecl decl("WetCloth",
                         "The paper's wetting model (Section 4) for every cloth in the scene: absorption (Eq. 11), "
                         "diffusion (Eq. 12-17), emission and drips (Eq. 18-19), wet sticking (Eq. 20) and coupling "
                         "stiffness that falls with saturation (Eq. 22). Defaults are Table 1's.",
                         "Plugins");
  // Each parameter once, bound to its member: defaults are WetParams{}'s
  // and DryingParams{}'s (Registry/ParamBinding.h). The rates per second are
  // kept as what they do in one of the paper's steps (scale 0.015 s).
  soak::ParamBinding<WetParams> wet(decl);
  wet.real("sMax", &WetParams::sMax, "", "S^MAX, the most water a cloth particle holds (Eq. 10).", 0.0, 1.0, true)
          .real("sEW", &WetParams::sEW, "", "S^EW: above it water goes to the emission buffer (Section 4.4).", 0.0, 1.0, true)
          .real("sT", &WetParams::sT, "", "S^T (default 0.3 sMax): wet sticking peaks here, coupling softens above it.", 0.0,
                1.0, true)
          .real("c", &WetParams::c, "m^3/kg",
                "Eq. 10's c in S = c m_water / V (the paper gives no value; 1/rho_water makes S the volume "
                "fraction of water).",
                0.0, 1.0, true)
          .choice<RateForm>("wettingRates", &WetParams::rates, {{"perSecond", RateForm::PerSecond}, {"perStep", RateForm::PerStep}},
                  "perSecond: absorptionRate, smoothingRate and bufferFlowRate are rates per second, applied as "
                  "rate x timeStep each step, so the wetting converges as the time step falls; perStep: the "
                  "paper's form, rate x 0.015 s each step whatever timeStep is (Doc/model.md, 'Rates per second').")
          .real("absorptionRate", &WetParams::kappaA, "1/s",
                "kappa^a of Eq. 11 per second (Table 1: 0.1 per step of 0.015 s).", 0.0, 1e4, false, kPaperTimeStep)
          .real("absorptionGravity", &WetParams::etaA, "",
                "eta^a of Eq. 11 (Table 1 prints eta^d twice; we read 0.4 as eta^a).", 0.0, 1.0)
          .real("diffusionRate", &WetParams::kappaD, "", "kappa^d of Eq. 12.", 0.0, 1e3)
          .real("diffusionGravity", &WetParams::etaD, "", "eta^d of Eq. 12.", 0.0, 1.0)
          .real("smoothingRate", &WetParams::kappaS, "1/s",
                "kappa^s of Eq. 17 per second (Table 1: 0.8 per step of 0.015 s). A step runs "
                "diffusionIterations passes, more where one would move more than kappa^s = 0.8 (at most 256).",
                0.0, 1e4, false, kPaperTimeStep)
          .real("diffusionRelaxation", &WetParams::epsilon, "", "epsilon of Eq. 15, relative to (sum_j a_ij)^2.", 0.0, 1e6)
          .integer("diffusionIterations", &WetParams::diffusionIterations,
                   "Saturation-constraint passes per step (0: no diffusion). Per second they share the step's "
                   "smoothing; per step each moves kappa^s.",
                   0, 1000)
          .choice<DiffusionForm>("diffusionForm", &WetParams::form, {{"conservative", DiffusionForm::Conservative}, {"literal", DiffusionForm::Literal}, {"fick", DiffusionForm::Fick}},
                  "conservative: pairwise exchange that conserves water and reduces to Eq. 17 per receiver; "
                  "literal: Eq. 17 as printed (does not conserve water); fick: Fick's law with diffusivity and "
                  "drainageSpeed, set from a fabric's measured wicking (Doc/model.md, 'Fick diffusion').")
          .real("diffusivity", &WetParams::diffusivity, "m^2/s",
                "diffusionForm=fick: D of dS/dt = div(D grad S); a wicking front rises as h^2 = K t with "
                "K = 4 D erfc^-1(S_front / S_bath)^2.",
                0.0, 10.0)
          .real("diffusivityWeft", &WetParams::diffusivityWeft, "m^2/s",
                "diffusionForm=fick: D along the weft (the cloth's v axis, or the mesh's vt v); diffusivity is "
                "then the warp's (u). Negative: the same as diffusivity. A wet spot spreads into an ellipse with "
                "axes in the ratio sqrt(diffusivity / diffusivityWeft).",
                -1.0, 10.0)
          .real("drainageSpeed", &WetParams::drainageSpeed, "m/s",
                "diffusionForm=fick: speed at which gravity drains water down the fabric; a wicking front levels "
                "off at (diffusivity / drainageSpeed) ln(S_bath / S_front).",
                0.0, 100.0)
          .real("emissionBeta", &WetParams::beta, "1/s^2", "beta of Eq. 18 (no value in the paper; Doc/model.md says why 10).", 0.0, 1e6)
          .real("bufferFlowRate", &WetParams::bufferShare, "1/s",
                "Share of a buffer Eq. 18 moves to the cloth below, per second (the paper moves all of it each "
                "0.015 s step).",
                0.0, 1e6, false, kPaperTimeStep)
          .real("dripMass", &WetParams::mThreshold, "kg", "m^threshold: buffer mass that becomes a drip (Table 1).", 0.0, 1.0, true)
          .real("dripAttraction", &WetParams::kappaE, "m/s^2", "kappa^e of Eq. 19 (Table 1).", 0.0, 1e6)
          .real("dripSaturationWeight", &WetParams::etaE, "kg", "eta^e of Eq. 19 (no value in the paper).", 0.0, 1e3)
          .real("stickiness", &WetParams::kappaAd, "N", "kappa^ad of Eq. 20 (Table 1).", 0.0, 1e6)
          .real("stickinessOffset", &WetParams::etaAd, "N",
                "eta^ad of Eq. 20 (no value in the paper); negative: stickiness x sT^2, so dry cloth does not "
                "stick.",
                -1.0, 1e6)
          .real("clothRestDensity", &WetParams::clothRestDensity, "kg/m^3", "Cloth rest density (Table 1), for Psi of Eq. 19.", 0.0, 1e5,
                true)
          .real("initialSaturation", &WetParams::initialSaturation, "", "Saturation every cloth particle starts with.", 0.0, 1.0)
          .boolean("emission", &WetParams::emission, "Buffers, drips and drip attraction (Section 4.4).")
          .boolean("sticking", &WetParams::sticking, "Wet cloth sticking (Eq. 20).")
          .choice<StickForm>("stickingForm", &WetParams::stickForm, {{"force", StickForm::Force}, {"correction", StickForm::Correction}},
                  "force: Eq. 20's attraction changes the cloth's velocity at the end of the step and the next "
                  "step's cloth solve carries it out against the cloth's stretch; correction: it moves the "
                  "positions the cloth solve left, unseen by any constraint before the frame (Doc/model.md, "
                  "'Wet sticking as a force').")
          .boolean("wetWeight", &WetParams::wetWeight, "Held and buffered water add to the cloth particle's mass.")
          .real("wetBendSoftening", &WetParams::wetBendSoftening, "",
                "Beyond the paper: saturated cloth (S = sMax) bends with 1 - wetBendSoftening of its dry bend "
                "stiffness, in proportion to S / sMax between (0: the paper's, wet cloth as stiff as dry; "
                "Doc/model.md, 'Wet stiffness and friction').",
                0.0, 1.0)
          .real("wetFriction", &WetParams::wetFriction, "",
                "Beyond the paper: colliders grip saturated cloth with 1 + wetFriction times their friction, in "
                "proportion to S / sMax between (at most 1 in all; 0: the paper's).",
                0.0, 100.0);
  soak::ParamBinding<DryingParams> drying(decl);
  drying.real("dryingRate", &DryingParams::fluxIntoDryAir, "kg/(m^2 s)",
                "Beyond the paper: evaporation per area of cloth into dry air while the fabric is wetter than "
                "dryingCriticalSaturation (0: no drying). Held water leaves at dryingRate x (1 - ambientHumidity) "
                "per area, falling in proportion to S below the critical saturation; stats.csv counts it in "
                "evaporated_water_mass (Doc/model.md, 'Drying').",
                0.0, 1e3)
          .real("ambientHumidity", &DryingParams::ambientHumidity, "", "Relative humidity of the air the cloth dries into, 0 to 1.", 0.0, 1.0)
          .real("dryingCriticalSaturation", &DryingParams::criticalSaturation, "",
                "Saturation below which drying slows in proportion to the water left (the falling-rate period).",
                0.0, 1.0);
  registry.add(decl.makeUnique().create([wet, drying](const soak::ElementParams& e) {
    WetParams w = wet.read(e);
    if (!e.given("sT")) w.sT = 0.3f * w.sMax;  // S^T = 0.3 S^MAX (Section 4.5)
    if (w.initialSaturation > w.sMax)
      throw soak::InputError("<WetCloth>: initialSaturation must not exceed sMax", e.where());
    return makeWetClothModule(w, drying.read(e), e.where());
  }));
}

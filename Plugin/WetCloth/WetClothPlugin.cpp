// The WetCloth plugin: <WetCloth .../> switches the paper's wetting model
// (Section 4) on for every cloth in the scene. It declares its parameters
// (Table 1 defaults), inserts its stages at the places of Algorithm 1 and
// adds its columns to stats.csv.
#include <algorithm>
#include <cmath>
#include <memory>

#include "Backend/Primitives.h"
#include "Base/Error.h"
#include "Checkpoint/StateStream.h"
#include "Neighbours/PairListsState.h"
#include "Pipeline/Pipeline.h"
#include "Pipeline/StageNames.h"
#include "Plugins/PluginApi.h"
#include "Simulation/Simulation.h"
#include "Drying.h"
#include "FickDiffusion.h"
#include "WetPhysics.h"

namespace soak::wet {
namespace {

class WetClothModule : public Module {
 public:
  WetClothModule(const WetParams& params, const DryingParams& drying, std::string where)
      : w_(params), drying_(drying), where_(std::move(where)) {}

  void setup(Simulation& sim) override {
    if (sim.cloth.empty()) throw InputError("<WetCloth>: the scene has no <Cloth> to wet", where_);
    if (!(w_.sEW < w_.sMax)) throw InputError("<WetCloth>: sEW must be below sMax", where_);
    if (!(w_.sT < w_.sMax)) throw InputError("<WetCloth>: sT must be below sMax", where_);
    if (weftDiffusivity(w_) != w_.diffusivity)
      for (const ClothObject& o : sim.cloth.objects())
        if (!o.hasMaterialCoordinates)
          throw InputError("<WetCloth>: diffusivityWeft needs the warp and weft of every cloth, and cloth '" + o.name +
                               "' is a mesh without texture coordinates (vt) for every vertex",
                           where_);
    ParticleState& ps = sim.particles;
    held_ = ps.addChannel("held_water");
    buffer_ = ps.addChannel("buffer");
    saturation_ = ps.addChannel("saturation");
    volume_ = ps.addChannel("volume");
    // Dry mass and kappa_couple per cloth vertex (the id of a cloth particle is its vertex).
    const int vertices = sim.cloth.vertexCount();
    std::vector<float> dry(std::size_t(vertices), 0.f);
    const std::vector<float> mass = ps.downloadMasses();
    const std::vector<int> phase = ps.downloadPhases(), id = ps.downloadIds();
    for (std::size_t i = 0; i < mass.size(); ++i)
      if (isCloth(phase[i])) dry[std::size_t(id[i])] = mass[i];
    // Every array on the simulation's device (the Buffer members start on the CPU).
    for (Buffer<float>* b : {&dryMass_, &scratchA_, &scratchB_, &scratchC_}) *b = Buffer<float>(sim.device());
    delta_ = Buffer<Vec3>(sim.device());
    due_ = Buffer<int>(sim.device());
    dripOffset_ = Buffer<int>(sim.device());
    dripSources_ = Buffer<DripSource>(sim.device());
    dripCounters_ = Buffer<DripCounters>(sim.device());
    dripCounters_.upload({DripCounters{}});
    clothNeighbours_ = std::make_unique<ClothNeighbours>(sim.device());
    dripRoomCap_ = std::max(kMinDripRoom, sim.cloth.vertexCount() / 32);
    maxListCapacity_ = sim.maxListCapacity(sim.cloth.vertexCount());
    dryMass_.upload(dry);
    if (drying_.fluxIntoDryAir > 0.f) {
      evaporated_ = ps.addChannel("evaporated_water");
      vertexArea_ = Buffer<float>(sim.device());
      vertexArea_.upload(sim.cloth.vertexRestAreas());
    }
    // kappa_couple (Eq. 22), the core's field that its coupling stage reads.
    kappa_ = sim.vertexFields.get(field::kCouplingStiffness, vertices, 1.f);
    if (w_.wetBendSoftening > 0.f) bendScale_ = sim.vertexFields.get(field::kBendStiffnessScale, vertices, 1.f);
    if (w_.wetFriction > 0.f) frictionScale_ = sim.vertexFields.get(field::kFrictionScale, vertices, 1.f);
    ref_.mass = sim.water.particleMass;
    ref_.supportRadius = sim.water.supportRadius;
    ref_.gravity = length(sim.settings.gravity);
    ref_.gravityDir = ref_.gravity > 0.f ? sim.settings.gravity / ref_.gravity : Vec3(0.f, -1.f, 0.f);
    // Held water given in the scene (<WetCloth initialSaturation=...>): set
    // once the volumes are known, at the first porosity update.
  }

  void addStages(Pipeline& pipeline, Simulation&) override {
    // Algorithm 1: after the cloth solve, volume and saturation; the core's
    // coupling stage then reads kappa_couple; then absorb, diffuse, emit, stick.
    pipeline.insertBefore(stage::kCoupling, {"wet.volume", [this](Simulation& s) { porosity(s); }});
    pipeline.insertAfter(stage::kCoupling, {"wet.absorb", [this](Simulation& s) { absorb(s); }});
    pipeline.insertAfter("wet.absorb", {"wet.diffuse", [this](Simulation& s) { diffuse(s); }});
    pipeline.insertAfter("wet.diffuse", {"wet.emit", [this](Simulation& s) { emit(s); }});
    pipeline.insertAfter("wet.emit", {"wet.stick", [this](Simulation& s) { stick(s); }});
    if (drying_.fluxIntoDryAir > 0.f)
      pipeline.insertAfter("wet.stick", {"wet.dry", [this](Simulation& s) { dryOut(s); }});
  }

  void beforeStep(Simulation& sim) override {
    // Drips taken in the last step's wet.emit join the water here, before
    // the grid is built (as the nozzle's particles do): `takenRoom_` slots,
    // of which the device knows how many are drips; the rest stay removed
    // until the next compaction.
    if (takenRoom_ > 0) {
      const int first = sim.particles.appendSlots(takenRoom_);
      DripShape shape = dripShape(sim);
      shape.firstId = sim.nextWaterId;
      sim.nextWaterId += takenRoom_;
      placeDrips(sim.device(), sim.particles.view(), first, takenRoom_, dripSources_.data(), shape,
                 dripCounters_.data());
      takenRoom_ = 0;
    }
    if (w_.emission && sim.maintenanceStep()) resizeDripRoom();
  }

  // Drips taken but not yet placed, the room they were taken with and the
  // counters, and whether the initial saturation was already given (the
  // held water is a particle channel).
  void saveState(StateWriter& out) const override {
    const DripCounters c = counters();
    std::vector<DripSource> pending = dripSources_.download();
    pending.resize(std::size_t(c.pending));
    out.putVector(pending);
    out.put<std::int32_t>(takenRoom_);
    out.put<std::int32_t>(dripRoom_);
    out.put<std::int32_t>(c.largestStep);
    out.put<std::int64_t>(c.spawned);
    out.put<std::int64_t>(c.deferred);
    out.put<std::int32_t>(initialised_ ? 1 : 0);
    putListSizing(out, clothNeighbours_->sizing());
  }
  void loadState(StateReader& in) override {
    const std::vector<DripSource> pending = in.getVector<DripSource>();
    takenRoom_ = in.get<std::int32_t>();
    dripRoom_ = in.get<std::int32_t>();
    DripCounters c;
    c.pending = int(pending.size());
    c.largestStep = in.get<std::int32_t>();
    c.spawned = in.get<std::int64_t>();
    c.deferred = in.get<std::int64_t>();
    initialised_ = in.get<std::int32_t>() != 0;
    if (c.pending > takenRoom_ || takenRoom_ > dripRoomCap_ || dripRoom_ < 1 || dripRoom_ > dripRoomCap_)
      in.fail("drip bookkeeping out of range");
    clothNeighbours_->setSizing(getListSizing(in, "cloth neighbour list", maxListCapacity_));
    dripSources_.upload(pending);
    dripCounters_.upload({c});
  }

  std::vector<DownloadQueue::Part> statsSources(Simulation&) override {
    return {{dripCounters_.data(), sizeof(DripCounters)}};
  }

  // From the frame's copies (a writer thread): the channel indices and
  // m_threshold are fixed at setup.
  void addStats(const FrameData& frame, const FrameData::ModuleCopies& own, StatsRow& row) const override {
    const std::vector<float>& held = frame.channels.at(std::size_t(held_));
    const std::vector<float>& buffer = frame.channels.at(std::size_t(buffer_));
    const std::vector<float>& saturation = frame.channels.at(std::size_t(saturation_));
    const DripCounters drips = own.as<DripCounters>(0);
    double heldSum = 0.0, bufferSum = 0.0;
    for (float v : held) heldSum += v;
    for (float v : buffer) bufferSum += v;
    float maxSaturation = 0.f;
    for (float v : saturation) maxSaturation = std::max(maxSaturation, v);
    const double buffered = bufferSum + double(drips.pending) * double(w_.mThreshold);
    row.add("held_water_mass", heldSum);
    row.add("buffered_water_mass", buffered);
    double evaporated = 0.0;
    if (evaporated_ >= 0)
      for (float v : frame.channels.at(std::size_t(evaporated_))) evaporated += v;
    row.add("evaporated_water_mass", evaporated);
    row.add("total_water_mass",
            row.get("free_water_mass") + heldSum + buffered + row.get("drained_water_mass") + evaporated);
    row.add("max_saturation", maxSaturation);
    row.add("drips_spawned", double(drips.spawned));
    row.add("drips_deferred", double(drips.deferred));
  }

 private:
  WetArrays arrays(Simulation& sim) {
    ParticleState& ps = sim.particles;
    const std::size_t n = std::size_t(ps.count());
    for (Buffer<float>* b : {&scratchA_, &scratchB_, &scratchC_}) b->resize(n);
    delta_.resize(n);
    WetArrays a;
    a.held = ps.channel(held_);
    a.buffer = ps.channel(buffer_);
    a.saturation = ps.channel(saturation_);
    a.volume = ps.channel(volume_);
    a.scratchA = scratchA_.data();
    a.scratchB = scratchB_.data();
    a.scratchC = scratchC_.data();
    a.delta = delta_.data();
    a.kappaCouple = kappa_;
    a.bendScale = bendScale_;
    a.frictionScale = frictionScale_;
    a.dryMass = dryMass_.data();
    a.cloth = clothSlots(sim.cloth.view());
    a.clothGrid = sim.cloth.grid();
    a.clothNeighbours = clothNeighbours_->view();
    return a;
  }

  void porosity(Simulation& s) {
    // The cloth stays where its solve left it until wet.stick: the
    // cloth-cloth lists of every wetting pass, built once here.
    const ClothView c = s.cloth.view();
    clothNeighbours_->build(s.particles.view(), s.cloth.grid(), clothSlots(c), c.thickness, s.sizeListsNow());
    if (!initialised_) {
      initialised_ = true;
      if (initialSaturation_ > 0.f) setInitialSaturation(s);
    }
    updatePorosity(s.device(), s.particles.view(), arrays(s), w_);
  }
  void absorb(Simulation& s) {
    absorbWater(s.device(), s.particles.view(), s.grid.view(), arrays(s), w_, ref_, float(s.settings.timeStep));
  }
  void diffuse(Simulation& s) {
    const float dt = float(s.settings.timeStep);
    if (w_.form != DiffusionForm::Fick) {
      diffuseWater(s.device(), s.particles.view(), arrays(s), w_, ref_, dt);
      return;
    }
    if (w_.diffusionIterations == 0) return;
    // Neighbours closer than half the shortest rest edge: cloth squeezed to half.
    const int substeps = std::max(w_.diffusionIterations, fickSubsteps(w_, dt, 0.5f * s.cloth.minEdgeLength()));
    diffuseFick(s.device(), s.particles.view(), arrays(s), s.cloth.view().materialCoord, w_, ref_, dt,
                std::min(substeps, kMaxDiffusionPasses));
  }
  void emit(Simulation& s) {
    if (!w_.emission) return;
    WetArrays a = arrays(s);
    ParticleView p = s.particles.view();
    due_.resize(std::size_t(a.cloth.count));
    dripOffset_.resize(std::size_t(a.cloth.count));
    transferBuffers(s.device(), p, a, w_, ref_, float(s.settings.timeStep), due_.data());
    dripSources_.resize(std::size_t(dripRoom_));
    takeDripMass(s.device(), p, a, w_, dripRoom_, due_.data(), dripOffset_.data(), dripSources_.data(),
                 dripCounters_.data());
    takenRoom_ = dripRoom_;
    attractDrips(s.device(), p, s.grid.view(), a, w_, ref_, float(s.settings.timeStep));
  }
  void dryOut(Simulation& s) {
    evaporateWater(s.device(), s.particles.view(), arrays(s), vertexArea_.data(), s.particles.channel(evaporated_),
                   drying_, w_.c, float(s.settings.timeStep));
  }
  void stick(Simulation& s) {
    if (!w_.sticking) return;
    stickWetCloth(s.device(), s.particles.view(), s.cloth.view(), arrays(s), w_,
                  float(s.settings.timeStep));
  }

  // A drip of mass m_threshold and radius (m_p / m0)^(1/3) h0 (Section 4.4)
  // starts below its cloth particle, a drip spacing plus half the cloth
  // thickness away, so that it does not overlap the water already there
  // (the role of Lin's placement in the paper), with the particle's velocity.
  DripShape dripShape(const Simulation& s) const {
    const float scale = std::cbrt(w_.mThreshold / ref_.mass);
    const float offset = 0.5f * s.cloth.maxThickness() + 0.5f * s.water.spacing * scale;
    DripShape shape;
    shape.below = ref_.gravityDir * offset;
    shape.mass = w_.mThreshold;
    shape.radius = ref_.supportRadius * scale;
    return shape;
  }

  DripCounters counters() const { return dripCounters_.download().at(0); }

  // On a maintenance step: room for twice the most drips one step has
  // wanted since the last, a power of two from kMinDripRoom up to one per 32
  // cloth vertices. Drips past the room wait a step or more (counted in
  // drips_deferred; Doc/design.md).
  void resizeDripRoom() {
    DripCounters c = counters();
    int room = kMinDripRoom;
    while (room < 2 * c.largestStep && room < dripRoomCap_) room *= 2;
    dripRoom_ = std::min(room, dripRoomCap_);
    c.largestStep = 0;
    dripCounters_.upload({c});
  }

  // Every cloth particle starts holding S V / c of water (for scenes that
  // begin wet, such as Figure 6).
  void setInitialSaturation(Simulation& s) {
    ParticleView p = s.particles.view();
    WetArrays a = arrays(s);
    updatePorosity(s.device(), p, a, w_);  // volumes
    std::vector<float> volume = s.particles.downloadChannel(volume_);
    const std::vector<int> phase = s.particles.downloadPhases();
    std::vector<float> held(volume.size(), 0.f);
    for (std::size_t i = 0; i < held.size(); ++i)
      if (isCloth(phase[i])) held[i] = initialSaturation_ * volume[i] / w_.c;
    Buffer<float> tmp(s.device());
    tmp.upload(held);
    copyDeviceToDevice(s.device(), a.held, tmp.data(), held.size() * sizeof(float));
  }

 public:
  float initialSaturation_ = 0.f;

 private:
  WetParams w_;
  DryingParams drying_;
  std::string where_;
  WaterReference ref_;
  int held_ = -1, buffer_ = -1, saturation_ = -1, volume_ = -1;
  int evaporated_ = -1;       // channel of the water each particle gave to the air (drying on)
  Buffer<float> vertexArea_;  // per vertex: rest area (drying on)
  Buffer<float> dryMass_, scratchA_, scratchB_, scratchC_;
  float* kappa_ = nullptr;  // the core's field::kCouplingStiffness
  float* bendScale_ = nullptr;      // the core's field::kBendStiffnessScale (wetBendSoftening > 0)
  float* frictionScale_ = nullptr;  // the core's field::kFrictionScale (wetFriction > 0)
  Buffer<Vec3> delta_;
  static constexpr int kMinDripRoom = 8;
  Buffer<int> due_, dripOffset_;
  Buffer<DripSource> dripSources_;
  Buffer<DripCounters> dripCounters_;
  int dripRoom_ = kMinDripRoom;  // drips one step may take
  int dripRoomCap_ = kMinDripRoom;
  double maxListCapacity_ = 0.0;  // a checkpoint's cloth list sizing beyond it is refused
  int takenRoom_ = 0;  // the room the last step took drips with: slots to append next step
  std::unique_ptr<ClothNeighbours> clothNeighbours_;  // on the simulation's device (setup)
  bool initialised_ = false;
};

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
            auto m = std::make_unique<soak::wet::WetClothModule>(soak::wet::paramsFrom(e), soak::wet::dryingFrom(e),
                                                                 e.where());
            m->initialSaturation_ = e.realf("initialSaturation");
            if (m->initialSaturation_ > e.realf("sMax"))
              throw soak::InputError("<WetCloth>: initialSaturation must not exceed sMax", e.where());
            return m;
          }));
}

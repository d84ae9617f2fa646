#include "WetClothModule.h"

#include <algorithm>
#include <cmath>

#include "Base/Error.h"
#include "Checkpoint/StateStream.h"
#include "Neighbours/PairListsState.h"
#include "Simulation/Simulation.h"
#include "Stages/WetStages.h"
#include "WetState.h"

namespace soak::wet {
namespace {

class WetClothModule : public Module {
 public:
  WetClothModule(const WetParams& params, const DryingParams& drying, std::string where)
      : w_(params), drying_(drying), where_(std::move(where)) {}

  void setup(Simulation& sim) override {
    const WetParams& w = w_;
    const std::string& where = where_;
    if (sim.cloth.empty()) throw InputError("<WetCloth>: the scene has no <Cloth> to wet", where);
    if (!(w.sEW < w.sMax)) throw InputError("<WetCloth>: sEW must be below sMax", where);
    if (!(w.sT < w.sMax)) throw InputError("<WetCloth>: sT must be below sMax", where);
    if (weftDiffusivity(w) != w.diffusivity)
      for (const ClothObject& o : sim.cloth.objects())
        if (!o.hasMaterialCoordinates)
          throw InputError("<WetCloth>: diffusivityWeft needs the warp and weft of every cloth, and cloth '" + o.name +
                               "' is a mesh without texture coordinates (vt) for every vertex",
                           where);
    // Every array on the simulation's device.
    st_ = std::make_unique<WetState>(sim.device());
    st_->w = w_;
    st_->drying = drying_;
    ParticleState& ps = sim.particles;
    st_->held = ps.addChannel(kHeldWaterChannel);
    st_->buffer = ps.addChannel(kBufferChannel);
    st_->saturation = ps.addChannel(kSaturationChannel);
    st_->volume = ps.addChannel(kVolumeChannel);
    // Dry mass per cloth vertex (the id of a cloth particle is its vertex).
    const int vertices = sim.cloth.vertexCount();
    std::vector<float> dry(std::size_t(vertices), 0.f);
    const std::vector<float> mass = ps.downloadMasses();
    const std::vector<int> phase = ps.downloadPhases(), id = ps.downloadIds();
    for (std::size_t i = 0; i < mass.size(); ++i)
      if (isCloth(phase[i])) dry[std::size_t(id[i])] = mass[i];
    st_->dryMass.upload(dry);
    st_->dripCounters.upload({DripCounters{}});
    st_->clothNeighbours = std::make_unique<ClothNeighbours>(sim.device());
    st_->dripRoomCap = std::max(WetState::kMinDripRoom, vertices / 32);
    maxListCapacity_ = sim.maxListCapacity(vertices);
    if (st_->drying.fluxIntoDryAir > 0.f) {
      st_->evaporated = ps.addChannel("evaporated_water");
      st_->vertexArea.upload(sim.cloth.vertexRestAreas());
    }
    // kappa_couple (Eq. 22), the core's field that its coupling stage reads.
    st_->kappa = sim.vertexFields.get(field::kCouplingStiffness, vertices, 1.f);
    if (w.wetBendSoftening > 0.f) st_->bendScale = sim.vertexFields.get(field::kBendStiffnessScale, vertices, 1.f);
    if (w.wetFriction > 0.f) st_->frictionScale = sim.vertexFields.get(field::kFrictionScale, vertices, 1.f);
    WaterReference& ref = st_->ref;
    ref.mass = sim.water.particleMass;
    ref.supportRadius = sim.water.supportRadius;
    ref.gravity = length(sim.settings.gravity);
    ref.gravityDir = ref.gravity > 0.f ? sim.settings.gravity / ref.gravity : Vec3(0.f, -1.f, 0.f);
    // Held water given in the scene (<WetCloth initialSaturation=...>): set
    // once the volumes are known, at the first porosity update.
  }

  void addStages(Pipeline& pipeline, Simulation&) override { addWetStages(pipeline, *st_); }

  void beforeStep(Simulation& sim) override {
    // Drips taken in the last step's wet.emit join the water here, before
    // the grid is built (as the nozzle's particles do): `takenRoom` slots,
    // of which the device knows how many are drips; the rest stay removed
    // until the next compaction.
    if (st_->takenRoom > 0) {
      const int first = sim.particles.appendSlots(st_->takenRoom);
      DripShape shape = dripShape(sim);
      shape.firstId = sim.nextWaterId;
      sim.nextWaterId += st_->takenRoom;
      placeDrips(sim.device(), sim.particles.view(), first, st_->takenRoom, st_->dripSources.data(), shape,
                 st_->dripCounters.data());
      st_->takenRoom = 0;
    }
    if (st_->w.emission && sim.maintenanceStep()) resizeDripRoom();
  }

  // Drips taken but not yet placed, the room they were taken with and the
  // counters, and whether the initial saturation was already given (the
  // held water is a particle channel).
  void saveState(StateWriter& out) const override {
    const DripCounters c = counters();
    std::vector<DripSource> pending = st_->dripSources.download();
    pending.resize(std::size_t(c.pending));
    out.putVector(pending);
    out.put<std::int32_t>(st_->takenRoom);
    out.put<std::int32_t>(st_->dripRoom);
    out.put<std::int32_t>(c.largestStep);
    out.put<std::int64_t>(c.spawned);
    out.put<std::int64_t>(c.deferred);
    out.put<std::int32_t>(st_->initialised ? 1 : 0);
    putListSizing(out, st_->clothNeighbours->sizing());
  }
  void loadState(StateReader& in) override {
    const std::vector<DripSource> pending = in.getVector<DripSource>();
    st_->takenRoom = in.get<std::int32_t>();
    st_->dripRoom = in.get<std::int32_t>();
    DripCounters c;
    c.pending = int(pending.size());
    c.largestStep = in.get<std::int32_t>();
    c.spawned = in.get<std::int64_t>();
    c.deferred = in.get<std::int64_t>();
    st_->initialised = in.get<std::int32_t>() != 0;
    if (c.pending > st_->takenRoom || st_->takenRoom > st_->dripRoomCap || st_->dripRoom < 1 ||
        st_->dripRoom > st_->dripRoomCap)
      in.fail("drip bookkeeping out of range");
    st_->clothNeighbours->setSizing(getListSizing(in, "cloth neighbour list", maxListCapacity_));
    st_->dripSources.upload(pending);
    st_->dripCounters.upload({c});
  }

  std::vector<DownloadQueue::Part> statsSources(Simulation&) override {
    return {{st_->dripCounters.data(), sizeof(DripCounters)}};
  }

  // From the frame's copies (a writer thread): the channel indices and
  // m_threshold are fixed at setup.
  void addStats(const FrameData& frame, const FrameData::ModuleCopies& own, StatsRow& row) const override {
    const std::vector<float>& held = frame.channels.at(std::size_t(st_->held));
    const std::vector<float>& buffer = frame.channels.at(std::size_t(st_->buffer));
    const std::vector<float>& saturation = frame.channels.at(std::size_t(st_->saturation));
    const DripCounters drips = own.as<DripCounters>(0);
    double heldSum = 0.0, bufferSum = 0.0;
    for (float v : held) heldSum += v;
    for (float v : buffer) bufferSum += v;
    float maxSaturation = 0.f;
    for (float v : saturation) maxSaturation = std::max(maxSaturation, v);
    const double buffered = bufferSum + double(drips.pending) * double(st_->w.mThreshold);
    row.add("held_water_mass", heldSum);
    row.add("buffered_water_mass", buffered);
    double evaporated = 0.0;
    if (st_->evaporated >= 0)
      for (float v : frame.channels.at(std::size_t(st_->evaporated))) evaporated += v;
    row.add("evaporated_water_mass", evaporated);
    row.add("total_water_mass",
            row.get("free_water_mass") + heldSum + buffered + row.get("drained_water_mass") + evaporated);
    row.add("max_saturation", maxSaturation);
    row.add("drips_spawned", double(drips.spawned));
    row.add("drips_deferred", double(drips.deferred));
  }

 private:
  // A drip of mass m_threshold and radius (m_p / m0)^(1/3) h0 (Section 4.4)
  // starts below its cloth particle, a drip spacing plus half the cloth
  // thickness away, so that it does not overlap the water already there
  // (the role of Lin's placement in the paper), with the particle's velocity.
  DripShape dripShape(const Simulation& s) const {
    const float scale = std::cbrt(st_->w.mThreshold / st_->ref.mass);
    const float offset = 0.5f * s.cloth.maxThickness() + 0.5f * s.water.spacing * scale;
    DripShape shape;
    shape.below = st_->ref.gravityDir * offset;
    shape.mass = st_->w.mThreshold;
    shape.radius = st_->ref.supportRadius * scale;
    return shape;
  }

  DripCounters counters() const { return st_->dripCounters.download().at(0); }

  // On a maintenance step: room for twice the most drips one step has
  // wanted since the last, a power of two from kMinDripRoom up to one per 32
  // cloth vertices. Drips past the room wait a step or more (counted in
  // drips_deferred; Doc/design.md).
  void resizeDripRoom() {
    DripCounters c = counters();
    int room = WetState::kMinDripRoom;
    while (room < 2 * c.largestStep && room < st_->dripRoomCap) room *= 2;
    st_->dripRoom = std::min(room, st_->dripRoomCap);
    c.largestStep = 0;
    st_->dripCounters.upload({c});
  }

  WetParams w_;
  DryingParams drying_;
  std::string where_;
  std::unique_ptr<WetState> st_;  // on the simulation's device, from setup
  double maxListCapacity_ = 0.0;  // a checkpoint's cloth list sizing beyond it is refused
};

}  // namespace

std::unique_ptr<Module> makeWetClothModule(const WetParams& params, const DryingParams& drying,
                                           const std::string& where) {
  return std::make_unique<WetClothModule>(params, drying, where);
}

}  // namespace soak::wet

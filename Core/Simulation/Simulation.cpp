#include "Simulation/Simulation.h"
#include "Simulation/FrameCopy.h"

#include <algorithm>

#include "Backend/Primitives.h"
#include "Backend/ForEach.h"
#include "Coupling/TriangleCoupling.h"
#include "Physics/Integrate.h"
#include "Pipeline/StageNames.h"
#include "Simulation/Instability.h"

namespace soak {

Simulation::Simulation(Device device)
    : particles(device), grid(device), cloth(device), fluid(device), vertexFields(device), device_(device),
      clothStep_(device), instabilityScratch_(device), removeFlag_(device), couplingMoved_(device), removedMass_(device), sinkBuffer_(device), colliderBuffer_(device) {}

Simulation::~Simulation() = default;

void Simulation::addModule(std::unique_ptr<Module> module, ModuleOrigin origin) {
  modules_.push_back(std::move(module));
  origins_.push_back(std::move(origin));
}

void Simulation::initialize() {
  for (auto& m : modules_) m->configure(*this);
  maxSupportRadius_ = std::max(maxSupportRadius_, water.supportRadius);
  checkCellOccupancy();  // before the wall-density table, whose cost grows as (h / r0)^3
  fluid.configure(water);
  for (const bool plugins : {false, true})
    for (std::size_t i = 0; i < modules_.size(); ++i)
      if (origins_[i].plugin == plugins) modules_[i]->setup(*this);
  checkCellOccupancy();
  cloth.upload();
  // The fields the modules' setup made (their arrays stay put from here on).
  cloth.setFieldViews(vertexFields.find(field::kBendStiffnessScale), vertexFields.find(field::kFrictionScale));
  cloth.updateSlots(particles.view());
  std::vector<Vec3> sinkCorners;
  for (const auto& box : sinks) sinkCorners.insert(sinkCorners.end(), {box.first, box.second});
  sinkBuffer_.upload(sinkCorners);
  addCoreStages();
  for (std::size_t i = 0; i < modules_.size(); ++i) {
    pipeline.collectFor(origins_[i].where);
    modules_[i]->addStages(pipeline, *this);
  }
  pipeline.placeWaiting();
}

FluidContext Simulation::fluidContext() const {
  return {grid.view(), water, float(settings.timeStep), deviceColliders(), int(colliders.size()),
          vertexFields.find(field::kFrictionScale)};
}

void Simulation::addCoreStages() {
  pipeline.append({stage::kPredict, [](Simulation& s) {
                     predictPositions(s.device(), s.particles.view(), s.settings.gravity, s.settings.timeStep);
                   }});
  // Before the grid is built, so that removing particles never leaves a stale grid.
  pipeline.append({stage::kDrain, [](Simulation& s) { s.drainWater(); }});
  pipeline.append({stage::kNeighbours, [](Simulation& s) {
                     s.grid.build(s.particles, s.maxSupportRadius());
                     if (!s.cloth.empty()) {
                       s.cloth.updateSlots(s.particles.view());
                       s.cloth.buildGrid(s.grid.view());
                       s.fluid.computeBoundaryVolumes(s.particles.view(), s.cloth.grid(),
                                                      clothSlots(s.cloth.view()));
                     }
                   }});
  pipeline.append({stage::kFluidSolve, [](Simulation& s) {
                     s.fluid.solve(s.particles, s.fluidContext(), s.sizeListsNow());
                   }});
  pipeline.append({stage::kClothSolve, [](Simulation& s) {
                     if (s.cloth.empty()) return;
                     const SimulationSettings& set = s.settings;
                     s.clothStep_.run(s.particles.view(), s.cloth, s.deviceColliders(), int(s.colliders.size()),
                                      {float(set.timeStep), set.gravity, set.clothSubsteps, set.clothIterations,
                                       set.clothSpectralRadius, set.contactPasses, kCollisionRadiusScale,
                                       s.sizeListsNow()});
                   }});
  pipeline.append({stage::kCollide, [](Simulation& s) {
                     projectColliders(s.device(), s.particles.view(), s.deviceColliders(),
                                      static_cast<int>(s.colliders.size()), kCollisionRadiusScale,
                                      s.settings.timeStep, s.vertexFields.find(field::kFrictionScale));
                   }});
  pipeline.append({stage::kCoupling, [](Simulation& s) {
                     if (s.cloth.empty()) return;
                     s.couplingMoved_.resize(std::size_t(s.particles.count()));
                     projectWaterOutOfCloth(s.device(), s.particles.view(), s.cloth.grid(), s.cloth.view(),
                                            s.vertexFields.find(field::kCouplingStiffness), s.settings.couplingPasses, s.couplingMoved_.data(),
                                            s.couplingMinLanes);
                   }});
  pipeline.append({stage::kFinalize, [](Simulation& s) {
                     updateVelocities(s.device(), s.particles.view(), s.settings.timeStep,
                                      s.cloth.empty() ? nullptr : s.clothStep_.velocityFix());
                     s.fluid.applyViscosity(s.particles.view(), s.fluidContext());
                   }});
}

void Simulation::drainWater() {
  ParticleView p = particles.view();
  const Vec3 lo = settings.domainMin, hi = settings.domainMax;
  const Vec3* sinkBox = sinkBuffer_.data();
  const int sinkCount = int(sinks.size());
  // Marks the slots, nothing more: the host learns of them at the next
  // compaction (no reduction here, so that the step never waits).
  if (p.count > 0) forEach(device_, p.count, SOAK_LAMBDA(int i) {
    if (!isWater(p.phase[i])) return;
    bool out = !(p.mass[i] > 0.f);  // wholly absorbed by cloth (its mass is held there now)
    const Vec3 x = p.position[i].xyz();
    // A non-finite position is an instability, not water that left the
    // domain: keep it for the check (Instability.h) to report.
    if (!out && !isFinite(x)) return;
    if (!out) out = !(x.x >= lo.x && x.y >= lo.y && x.z >= lo.z && x.x <= hi.x && x.y <= hi.y && x.z <= hi.z);
    for (int k = 0; k < sinkCount && !out; ++k) {
      const Vec3 a = sinkBox[2 * k], b = sinkBox[2 * k + 1];
      out = x.x >= a.x && x.y >= a.y && x.z >= a.z && x.x <= b.x && x.y <= b.y && x.z <= b.z;
    }
    if (!out) return;
    // Inert from here on; a drained slot keeps its mass (counted at compaction).
    p.phase[i] = kPhaseRemoved;
    if (!(p.mass[i] > 0.f)) p.mass[i] = 0.f;
    p.position[i] = Float4(x, 0.f);
    p.predicted[i] = Float4(x, 0.f);
    p.velocity[i] = Vec3(0.f, 0.f, 0.f);
  }, "drain.mark");
  if (maintenanceStep()) compact();
}

void Simulation::compact() {
  ParticleView p = particles.view();
  if (p.count == 0) return;
  removeFlag_.resize(p.count);
  removedMass_.resize(p.count);
  int* flag = removeFlag_.data();
  float* removed = removedMass_.data();
  forEach(device_, p.count, SOAK_LAMBDA(int i) {
    const bool gone = isRemoved(p.phase[i]);
    flag[i] = gone ? 1 : 0;
    removed[i] = gone ? p.mass[i] : 0.f;
  }, "compact.flag");
  drainedWaterMass += reduceSum(device_, removed, p.count);
  if (particles.removeFlagged(flag) > 0 && !cloth.empty()) cloth.updateSlots(particles.view());
}

namespace {
// Up to this many colliders travel to the device inside a kernel's
// parameters (4 KiB at most), not by a copy that waits.
constexpr int kCollidersByParameter = 16;
struct ColliderParameters {
  Collider c[kCollidersByParameter];
};
void writeByParameters(Device d, const std::vector<Collider>& colliders, Collider* out) {
  const int n = int(colliders.size());
  ColliderParameters set;
  for (int k = 0; k < n; ++k) set.c[k] = colliders[std::size_t(k)];
  forEach(d, n, SOAK_LAMBDA(int k) { out[k] = set.c[k]; }, "colliders.write");
}
}  // namespace

void Simulation::writeColliders() {
  if (colliders.size() > std::size_t(kCollidersByParameter) || colliderBuffer_.size() != colliders.size())
    colliderBuffer_.upload(colliders);  // the first time, or too many: a copy
  else
    writeByParameters(device_, colliders, colliderBuffer_.data());
}

void Simulation::step(bool profile) {
  for (auto& m : modules_) m->beforeStep(*this);
  if (collidersDirty_) {
    writeColliders();
    collidersDirty_ = false;
  }
  if (checkStages) {
    pipeline.run(*this, device_, profile, [this](const std::string& stage) {
      const Instability s = findInstability(*this, instabilityScratch_, stage);
      if (s.found) throw InstabilityError(s, describeInstability(s, settings.maxSpeed));
    });
  } else {
    pipeline.run(*this, device_, profile);
  }
  ++stepIndex_;
  time_ = double(stepIndex_) * settings.timeStep;
}

bool Simulation::maintenanceStep() const {
  return maintenanceInterval <= 1 || stepIndex_ % maintenanceInterval == 0;
}

StatsRow Simulation::collectStats() {
  if (!statsDownloads_) statsDownloads_ = std::make_unique<DownloadQueue>(device_);
  return frameStats(finishFrameCopy(startFrameCopy(*statsDownloads_), *statsDownloads_));
}

}  // namespace soak

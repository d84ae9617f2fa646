#include "Simulation/Simulation.h"
#include "Simulation/FrameCopy.h"

#include <algorithm>

#include "Backend/Primitives.h"
#include "Backend/ForEach.h"
#include "Simulation/Instability.h"

namespace soak {

Simulation::Simulation(Device device)
    : particles(device), grid(device), cloth(device), fluid(device), vertexFields(device), device_(device),
      stages_(device), instabilityScratch_(device), removeFlag_(device), removedMass_(device), colliderBuffer_(device) {}

Simulation::~Simulation() = default;

void Simulation::addModule(std::unique_ptr<Module> module, ModuleOrigin origin) {
  modules_.push_back(std::move(module));
  origins_.push_back(std::move(origin));
}

void Simulation::initialize() {
  for (auto& m : modules_) m->configure(*this);
  resolveClothSolverCounts(settings, clothModelsUsed);
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
  stages_.sinkCorners.upload(sinkCorners);
  addCoreStages(pipeline, stages_);
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
  } else if (device_ == Device::Cuda && settings.cudaGraph && !profile) {
    // The step's kernels are captured and replayed as graphs, one per
    // stretch between host waits; plain and maintenance steps keep their
    // own (CudaBackend.h). --profile and --check-stages queue them one by one.
    cudaGraphBeginStep(maintenanceStep() ? 1 : 0);
    try {
      pipeline.run(*this, device_, profile);
    } catch (...) {
      cudaGraphAbandonStep();
      throw;
    }
    cudaGraphEndStep();
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

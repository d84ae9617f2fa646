#include "Simulation/Simulation.h"

#include <algorithm>

#include "Backend/Primitives.h"
#include "Physics/Integrate.h"

namespace soak {

// Collision radius as a fraction of the support radius (h = 2 r0, so a
// particle's collision sphere has radius r0 / 2).
constexpr float kCollisionRadiusScale = 0.25f;

Simulation::Simulation(Device device)
    : particles(device), grid(device), device_(device), colliderBuffer_(device) {}

Simulation::~Simulation() = default;

void Simulation::addModule(std::unique_ptr<Module> module) { modules_.push_back(std::move(module)); }

void Simulation::initialize() {
  for (auto& m : modules_) m->configure(*this);
  maxSupportRadius_ = std::max(maxSupportRadius_, water.supportRadius);
  for (auto& m : modules_) m->setup(*this);
  addCoreStages();
  for (auto& m : modules_) m->addStages(pipeline, *this);
}

void Simulation::addCoreStages() {
  pipeline.append({"predict", [](Simulation& s) {
                     predictPositions(s.device(), s.particles.view(), s.settings.gravity, s.settings.timeStep);
                   }});
  pipeline.append({"neighbours", [](Simulation& s) { s.grid.build(s.particles, s.maxSupportRadius()); }});
  pipeline.append({"collide", [](Simulation& s) {
                     projectColliders(s.device(), s.particles.view(), s.deviceColliders(),
                                      static_cast<int>(s.colliders.size()), kCollisionRadiusScale,
                                      s.settings.timeStep);
                   }});
  pipeline.append({"finalize", [](Simulation& s) {
                     updateVelocities(s.device(), s.particles.view(), s.settings.timeStep);
                   }});
}

void Simulation::step(bool profile) {
  for (auto& m : modules_) m->beforeStep(*this);
  if (collidersDirty_) {
    colliderBuffer_.upload(colliders);
    collidersDirty_ = false;
  }
  pipeline.run(*this, device_, profile);
  ++stepIndex_;
  time_ = double(stepIndex_) * settings.timeStep;
}

StatsRow Simulation::collectStats() {
  StatsRow row;
  std::vector<int> phase = particles.downloadPhases();
  std::vector<float> mass = particles.downloadMasses();
  long long water = 0, cloth = 0;
  double waterMass = 0.0;
  for (std::size_t i = 0; i < phase.size(); ++i) {
    if (isWater(phase[i])) {
      ++water;
      waterMass += mass[i];
    } else if (isCloth(phase[i])) {
      ++cloth;
    }
  }
  row.add("water_particles", double(water));
  row.add("cloth_particles", double(cloth));
  row.add("free_water_mass", waterMass);
  row.add("drained_water_mass", drainedWaterMass);
  for (auto& m : modules_) m->addStats(*this, row);
  return row;
}

}  // namespace soak

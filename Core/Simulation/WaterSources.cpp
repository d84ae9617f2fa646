// Where water comes from and goes: <Nozzle> (a jet) and <Sink> (a drain box).
#include <algorithm>
#include <cmath>

#include "Base/Error.h"
#include "Backend/Buffer.h"
#include "Checkpoint/StateStream.h"
#include "Particles/NewParticles.h"
#include "Registry/ModuleRegistry.h"
#include "Simulation/ElementGroups.h"
#include "Simulation/Simulation.h"

namespace soak {

namespace {

// Emits a cylindrical jet: discs of particles on a square lattice of the
// water spacing, one disc each time the water has moved one layer spacing.
class NozzleModule : public Module {
 public:
  explicit NozzleModule(const ElementParams& p) : p_(p) {}
  void setup(Simulation& sim) override {
    const std::string& where = p_.where();
    Vec3 dir = p_.vector("direction");
    if (length(dir) < 1e-9f) throw InputError("<Nozzle>: direction must not be zero", where);
    dir_ = dir / length(dir);
    const Vec3 helper = fabsf(dir_.y) < 0.9f ? Vec3(0.f, 1.f, 0.f) : Vec3(1.f, 0.f, 0.f);
    const Vec3 u = normalizedOrZero(cross(dir_, helper)), v = cross(dir_, u);
    const float s = sim.water.spacing, radius = p_.realf("radius");
    // One disc must fit before it is built (a 100 m opening at 2 cm is 8e7 particles).
    const double across = double(radius) / double(s);
    sim.checkParticleBudget(3.14159265358979 * across * across + 4.0 * across + 1.0, "<Nozzle> (one disc of its jet)", where);
    const int reach = int(std::ceil(radius / s));
    for (int j = -reach; j <= reach; ++j)
      for (int i = -reach; i <= reach; ++i) {
        const float a = float(i) * s, b = float(j) * s;
        if (a * a + b * b <= radius * radius) disc_.push_back(u * a + v * b);
      }
    if (disc_.empty()) disc_.push_back(Vec3(0.f, 0.f, 0.f));
    discOnDevice_ = Buffer<Vec3>(sim.device());
    discOnDevice_.upload(disc_);
    speed_ = p_.realf("speed");
    layerSpacing_ = s;
    const double rate = p_.real("rate");
    if (rate > 0.0) {
      layerSpacing_ = float(speed_ * double(disc_.size()) / rate);
      if (layerSpacing_ < 0.9f * s)
        throw InputError("<Nozzle>: rate " + std::to_string(rate) + " particles/s needs layers " +
                             std::to_string(layerSpacing_) + " m apart, closer than the water spacing " +
                             std::to_string(s) + " m; lower the rate or raise speed or radius",
                         where);
    }
    if (p_.real("stop") <= p_.real("start")) throw InputError("<Nozzle>: stop must be after start", where);
  }
  void beforeStep(Simulation& sim) override {
    const double t = sim.time(), dt = sim.settings.timeStep;
    if (t + dt <= p_.real("start") || t >= p_.real("stop")) return;
    travelled_ += double(speed_) * dt;
    const int k = int(disc_.size());
    WaterLayer layer;
    layer.origin = p_.vector("position");
    layer.direction = dir_;
    layer.velocity = dir_ * speed_;
    layer.mass = sim.water.particleMass;
    layer.radius = sim.water.supportRadius;
    while (travelled_ >= layerSpacing_) {
      travelled_ -= layerSpacing_;
      // Born travelled_ / speed ago; predict() moves it one full step, so start it that much behind.
      layer.along = float(travelled_) - speed_ * float(dt);
      layer.firstId = sim.nextWaterId;
      sim.nextWaterId += k;
      // Written on the device: nothing crosses from the host inside the step.
      const int first = sim.particles.appendSlots(k);
      writeWaterLayer(sim.device(), sim.particles.view(), first, discOnDevice_.data(), k, layer);
      sim.emittedWaterMass += double(k) * double(sim.water.particleMass);
    }
  }
  // A disc each time the water moves layerSpacing_, while the jet is on.
  PlannedParticles plannedParticles(const Simulation& sim, double endTime) const override {
    if (disc_.empty()) return {};
    const double from = std::max(sim.time(), p_.real("start")), to = std::min(endTime, p_.real("stop"));
    const double discs = to > from ? std::ceil((to - from) * double(speed_) / double(layerSpacing_)) + 1.0 : 0.0;
    return {discs * double(disc_.size()), "<Nozzle>", p_.where()};
  }
  // How far the water has moved since the last layer: the phase of the jet.
  void saveState(StateWriter& out) const override { out.put<double>(travelled_); }
  void loadState(StateReader& in) override { travelled_ = in.get<double>(); }

 private:
  ElementParams p_;
  Vec3 dir_;
  std::vector<Vec3> disc_;
  Buffer<Vec3> discOnDevice_;
  float speed_ = 0.f, layerSpacing_ = 0.f;
  double travelled_ = 0.0;
};

class SinkModule : public Module {
 public:
  explicit SinkModule(const ElementParams& p) : p_(p) {}
  void setup(Simulation& sim) override {
    const Vec3 lo = p_.vector("min"), hi = p_.vector("max");
    if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z))
      throw InputError("<Sink>: max must exceed min on every axis", p_.where());
    sim.sinks.emplace_back(lo, hi);
  }

 private:
  ElementParams p_;
};

}  // namespace

void registerWaterSourceElements(ModuleRegistry& r) {
  r.add(ElementDecl("Nozzle",
                    "A water jet: discs of particles (water spacing apart) leave a circular opening at a given "
                    "speed (Figure 1: 4.0 m/s).",
                    "Water")
            .vector("position", "m", "0 1.5 0", "Centre of the opening.")
            .vector("direction", "", "0 -1 0", "Direction of the jet.")
            .real("radius", "m", "0.05", "Radius of the opening.", 0.0, 100.0, true)
            .real("speed", "m/s", "4", "Speed of the emitted water.", 0.0, 1e3, true)
            .real("rate", "1/s", "0",
                  "Particles per second (0: as many as speed x area at the water spacing gives).", 0.0, 1e9)
            .real("start", "s", "0", "Time the jet starts.", 0.0, 1e9)
            .real("stop", "s", "1e9", "Time the jet stops.", 0.0, 1e12)
            .create([](const ElementParams& p) { return std::make_unique<NozzleModule>(p); }));
  r.add(ElementDecl("Sink", "A box that removes water entering it; removed mass is counted as drained.", "Water")
            .vector("min", "m", "-1 -1 -1", "Lower corner.")
            .vector("max", "m", "1 -0.5 1", "Upper corner.")
            .create([](const ElementParams& p) { return std::make_unique<SinkModule>(p); }));
}

}  // namespace soak

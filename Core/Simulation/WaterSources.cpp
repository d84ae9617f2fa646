// Where water comes from and goes: <Nozzle> (a jet) and <Sink> (a drain box).
#include <algorithm>
#include <cmath>

#include "Base/Error.h"
#include "Backend/Buffer.h"
#include "Checkpoint/StateStream.h"
#include "Particles/NewParticles.h"
#include "Registry/ModuleRegistry.h"
#include "Registry/ParamBinding.h"
#include "Simulation/ElementGroups.h"
#include "Simulation/Simulation.h"

namespace soak {

namespace {

// <Nozzle>'s parameters (bound in registerWaterSourceElements; the defaults here).
struct NozzleParams {
  Vec3 position{0.f, 1.5f, 0.f};
  Vec3 direction{0.f, -1.f, 0.f};
  float radius = 0.05f;
  float speed = 4.f;
  double rate = 0.0;
  double start = 0.0;
  double stop = 1e9;
};

// Emits a cylindrical jet: discs of particles on a square lattice of the
// water spacing, one disc each time the water has moved one layer spacing.
class NozzleModule : public Module {
 public:
  NozzleModule(const NozzleParams& n, std::string where) : n_(n), where_(std::move(where)) {}
  void setup(Simulation& sim) override {
    const std::string& where = where_;
    Vec3 dir = n_.direction;
    if (length(dir) < 1e-9f) throw InputError("<Nozzle>: direction must not be zero", where);
    dir_ = dir / length(dir);
    const Vec3 helper = fabsf(dir_.y) < 0.9f ? Vec3(0.f, 1.f, 0.f) : Vec3(1.f, 0.f, 0.f);
    const Vec3 u = normalizedOrZero(cross(dir_, helper)), v = cross(dir_, u);
    const float s = sim.water.spacing, radius = n_.radius;
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
    speed_ = n_.speed;
    layerSpacing_ = s;
    const double rate = n_.rate;
    if (rate > 0.0) {
      layerSpacing_ = float(speed_ * double(disc_.size()) / rate);
      if (layerSpacing_ < 0.9f * s)
        throw InputError("<Nozzle>: rate " + std::to_string(rate) + " particles/s needs layers " +
                             std::to_string(layerSpacing_) + " m apart, closer than the water spacing " +
                             std::to_string(s) + " m; lower the rate or raise speed or radius",
                         where);
    }
    if (n_.stop <= n_.start) throw InputError("<Nozzle>: stop must be after start", where);
  }
  void beforeStep(Simulation& sim) override {
    const double t = sim.time(), dt = sim.settings.timeStep;
    if (t + dt <= n_.start || t >= n_.stop) return;
    travelled_ += double(speed_) * dt;
    const int k = int(disc_.size());
    WaterLayer layer;
    layer.origin = n_.position;
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
    const double from = std::max(sim.time(), n_.start), to = std::min(endTime, n_.stop);
    const double discs = to > from ? std::ceil((to - from) * double(speed_) / double(layerSpacing_)) + 1.0 : 0.0;
    return {discs * double(disc_.size()), "<Nozzle>", where_};
  }
  // How far the water has moved since the last layer: the phase of the jet.
  void saveState(StateWriter& out) const override { out.put<double>(travelled_); }
  void loadState(StateReader& in) override { travelled_ = in.get<double>(); }

 private:
  NozzleParams n_;
  std::string where_;
  Vec3 dir_;
  std::vector<Vec3> disc_;
  Buffer<Vec3> discOnDevice_;
  float speed_ = 0.f, layerSpacing_ = 0.f;
  double travelled_ = 0.0;
};

struct SinkParams {
  Vec3 min{-1.f, -1.f, -1.f};
  Vec3 max{1.f, -0.5f, 1.f};
};

class SinkModule : public Module {
 public:
  SinkModule(const SinkParams& b, std::string where) : b_(b), where_(std::move(where)) {}
  void setup(Simulation& sim) override {
    const Vec3 lo = b_.min, hi = b_.max;
    if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z))
      throw InputError("<Sink>: max must exceed min on every axis", where_);
    sim.sinks.emplace_back(lo, hi);
  }

 private:
  SinkParams b_;
  std::string where_;
};

}  // namespace

void registerWaterSourceElements(ModuleRegistry& r) {
  {
    ElementDecl decl("Nozzle",
                     "A water jet: discs of particles (water spacing apart) leave a circular opening at a given "
                     "speed (Figure 1: 4.0 m/s).",
                     "Water");
    ParamBinding<NozzleParams> nozzle(decl);
    using N = NozzleParams;
    nozzle.vector("position", &N::position, "m", "Centre of the opening.")
        .vector("direction", &N::direction, "", "Direction of the jet.")
        .real("radius", &N::radius, "m", "Radius of the opening.", 0.0, 100.0, true)
        .real("speed", &N::speed, "m/s", "Speed of the emitted water.", 0.0, 1e3, true)
        .real("rate", &N::rate, "1/s", "Particles per second (0: as many as speed x area at the water spacing gives).",
              0.0, 1e9)
        .real("start", &N::start, "s", "Time the jet starts.", 0.0, 1e9)
        .real("stop", &N::stop, "s", "Time the jet stops.", 0.0, 1e12);
    r.add(decl.create(
        [nozzle](const ElementParams& p) { return std::make_unique<NozzleModule>(nozzle.read(p), p.where()); }));
  }
  {
    ElementDecl decl("Sink", "A box that removes water entering it; removed mass is counted as drained.", "Water");
    ParamBinding<SinkParams> sink(decl);
    sink.vector("min", &SinkParams::min, "m", "Lower corner.").vector("max", &SinkParams::max, "m", "Upper corner.");
    r.add(decl.create([sink](const ElementParams& p) { return std::make_unique<SinkModule>(sink.read(p), p.where()); }));
  }
}

}  // namespace soak

// The scene elements Core provides, each declared once.
#include <cmath>

#include "Base/Error.h"
#include "Registry/ModuleRegistry.h"
#include "Simulation/Simulation.h"

namespace soak {

namespace {

class SimulationModule : public Module {
 public:
  explicit SimulationModule(const ElementParams& p) : p_(p) {}
  void configure(Simulation& sim) override {
    sim.settings.timeStep = p_.real("timeStep");
    sim.settings.duration = p_.real("duration");
    sim.settings.frameRate = p_.real("frameRate");
    sim.settings.gravity = p_.vector("gravity");
    sim.settings.maxSpeed = p_.realf("maxSpeed");
  }

 private:
  ElementParams p_;
};

class WaterModule : public Module {
 public:
  explicit WaterModule(const ElementParams& p) : p_(p) {}
  void configure(Simulation& sim) override {
    sim.water.spacing = p_.realf("spacing");
    sim.water.supportRadius = p_.realf("supportRadius");
    sim.water.restDensity = p_.realf("restDensity");
    sim.water.particleMass = p_.realf("particleMass");
  }

 private:
  ElementParams p_;
};

class WaterBlockModule : public Module {
 public:
  explicit WaterBlockModule(const ElementParams& p) : p_(p) {}
  void setup(Simulation& sim) override {
    const Vec3 lo = p_.vector("min"), hi = p_.vector("max"), v = p_.vector("velocity");
    const float s = sim.water.spacing;
    if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z))
      throw InputError("<WaterBlock>: max must exceed min on every axis", p_.where());
    const long long nx = std::llround(std::floor((hi.x - lo.x) / s + 1e-4)) + 0;
    const long long ny = std::llround(std::floor((hi.y - lo.y) / s + 1e-4)) + 0;
    const long long nz = std::llround(std::floor((hi.z - lo.z) / s + 1e-4)) + 0;
    const long long total = std::max(nx, 1LL) * std::max(ny, 1LL) * std::max(nz, 1LL);
    if (total > 200000000LL)
      throw InputError("<WaterBlock> would create " + std::to_string(total) + " particles (limit 2e8)", p_.where());
    std::vector<ParticleInit> batch;
    batch.reserve(static_cast<std::size_t>(total));
    for (long long k = 0; k < std::max(nz, 1LL); ++k)
      for (long long j = 0; j < std::max(ny, 1LL); ++j)
        for (long long i = 0; i < std::max(nx, 1LL); ++i) {
          ParticleInit q;
          q.position = Vec3(lo.x + (float(i) + 0.5f) * s, lo.y + (float(j) + 0.5f) * s, lo.z + (float(k) + 0.5f) * s);
          q.velocity = v;
          q.mass = sim.water.particleMass;
          q.radius = sim.water.supportRadius;
          q.phase = kPhaseWater;
          q.id = sim.nextWaterId++;
          batch.push_back(q);
        }
    sim.particles.append(batch);
  }

 private:
  ElementParams p_;
};

class ColliderModule : public Module {
 public:
  ColliderModule(const ElementParams& p, int shape) : p_(p), shape_(shape) {}
  void setup(Simulation& sim) override {
    Collider c;
    c.shape = shape_;
    c.friction = p_.realf("friction");
    if (shape_ == kColliderPlane) {
      c.a = p_.vector("point");
      Vec3 n = p_.vector("normal");
      if (length(n) < 1e-12f) throw InputError("<Plane>: normal must not be zero", p_.where());
      c.b = n / length(n);
    } else if (shape_ == kColliderBox) {
      c.a = p_.vector("min");
      c.b = p_.vector("max");
      if (!(c.b.x > c.a.x && c.b.y > c.a.y && c.b.z > c.a.z))
        throw InputError("<Box>: max must exceed min on every axis", p_.where());
      c.inside = p_.boolean("inside") ? 1 : 0;
    } else {
      c.a = p_.vector("center");
      c.radius = p_.realf("radius");
      c.inside = p_.boolean("inside") ? 1 : 0;
    }
    sim.colliders.push_back(c);
    sim.collidersChanged();
  }

 private:
  ElementParams p_;
  int shape_;
};

// <Plugin> is acted on by the scene loader (it loads the library before the
// other elements are checked); as a module it does nothing.
class NoModule : public Module {};

}  // namespace

void registerCoreElements(ModuleRegistry& r) {
  r.add(ElementDecl("Simulation", "Time stepping, output rate and gravity.", "Simulation")
            .real("timeStep", "s", "0.015", "Time step (Table 1).", 0.0, 1.0, true)
            .real("duration", "s", "4", "Simulated time of a run (`--time` and `--frames` override it).", 0.0,
                  1e9, true)
            .real("frameRate", "1/s", "30", "Output frames per simulated second, independent of the time step.",
                  0.0, 1e6, true)
            .vector("gravity", "m/s^2", "0 -9.81 0", "Gravitational acceleration; +y is up by default.")
            .real("maxSpeed", "m/s", "50", "A particle faster than this is reported as an instability.", 0.0,
                  1e9, true)
            .makeUnique()
            .create([](const ElementParams& p) { return std::make_unique<SimulationModule>(p); }));
  r.add(ElementDecl("Water", "Properties of water particles (Table 1).", "Water")
            .real("spacing", "m", "0.02", "Initial particle spacing r0.", 0.0, 10.0, true)
            .real("supportRadius", "m", "0.04", "SPH support radius h.", 0.0, 10.0, true)
            .real("restDensity", "kg/m^3", "1000", "Rest density rho0 of water.", 0.0, 1e6, true)
            .real("particleMass", "kg", "0.0082", "Mass of a full water particle.", 0.0, 1e6, true)
            .makeUnique()
            .create([](const ElementParams& p) { return std::make_unique<WaterModule>(p); }));
  r.add(ElementDecl("WaterBlock", "A box filled with water particles on a lattice of the water spacing.", "Water")
            .vector("min", "m", "0 0 0", "Lower corner.")
            .vector("max", "m", "0.2 0.2 0.2", "Upper corner.")
            .vector("velocity", "m/s", "0 0 0", "Initial velocity of every particle.")
            .create([](const ElementParams& p) { return std::make_unique<WaterBlockModule>(p); }));
  r.add(ElementDecl("Plane", "Infinite plane collider; particles stay on the side the normal points to.",
                    "Colliders")
            .vector("point", "m", "0 0 0", "A point on the plane.")
            .vector("normal", "", "0 1 0", "Normal (need not be unit length).")
            .real("friction", "", "0.1", "Fraction of tangential motion removed on contact.", 0.0, 1.0)
            .create([](const ElementParams& p) { return std::make_unique<ColliderModule>(p, kColliderPlane); }));
  r.add(ElementDecl("Box", "Axis-aligned box collider: a solid obstacle, or a container with inside=\"true\".",
                    "Colliders")
            .vector("min", "m", "-1 -1 -1", "Lower corner.")
            .vector("max", "m", "1 1 1", "Upper corner.")
            .boolean("inside", "false", "Keep particles inside the box (a tank) instead of outside.")
            .real("friction", "", "0.1", "Fraction of tangential motion removed on contact.", 0.0, 1.0)
            .create([](const ElementParams& p) { return std::make_unique<ColliderModule>(p, kColliderBox); }));
  r.add(ElementDecl("Sphere", "Sphere collider: a solid ball, or a spherical container with inside=\"true\".",
                    "Colliders")
            .vector("center", "m", "0 0 0", "Centre.")
            .real("radius", "m", "0.1", "Radius.", 0.0, 1e6, true)
            .boolean("inside", "false", "Keep particles inside the sphere instead of outside.")
            .real("friction", "", "0.1", "Fraction of tangential motion removed on contact.", 0.0, 1.0)
            .create([](const ElementParams& p) { return std::make_unique<ColliderModule>(p, kColliderSphere); }));
  r.add(ElementDecl("Plugin",
                    "Loads a plugin library before the rest of the scene is read: by name from the plugin "
                    "directory, or by path (relative to the scene file).",
                    "Plugins")
            .text("name", "", "Plugin name, e.g. WetCloth (file libsoak_<name>.so in the plugin directory).")
            .text("path", "", "Path of the plugin library; used instead of name when given.")
            .create([](const ElementParams&) { return std::make_unique<NoModule>(); }));
}

}  // namespace soak

// The scene elements Core provides, each declared once.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "Base/Error.h"
#include "Base/MessageText.h"
#include "Registry/ModuleRegistry.h"
#include "Registry/ParamBinding.h"
#include "Simulation/ElementGroups.h"
#include "Simulation/Simulation.h"

namespace soak {

namespace {


class SimulationModule : public Module {
 public:
  SimulationModule(const ElementParams& p, ParamBinding<SimulationSettings> settings,
                   ParamBinding<ResourceLimits> limits)
      : p_(p), settings_(std::move(settings)), limits_(std::move(limits)) {}
  void configure(Simulation& sim) override {
    settings_.fill(p_, sim.settings);
    limits_.fill(p_, sim.settings.limits);
    sim.settings.where = p_.where();
    const Vec3 lo = sim.settings.domainMin, hi = sim.settings.domainMax;
    if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z))
      throw InputError("<Simulation>: domainMax must exceed domainMin on every axis (water outside the domain is "
                       "drained: an empty domain would drain all of it in the first step)",
                       p_.where());
    // A frame every 1/frameRate s, a step every timeStep s.
    const double stepsPerFrame = std::ceil(1.0 / (sim.settings.frameRate * sim.settings.timeStep) - 1e-9);
    if (!(stepsPerFrame <= double(sim.settings.limits.maxStepsPerFrame)))
      throw InputError("<Simulation>: timeStep " + formatNumber(sim.settings.timeStep) + " s at frameRate " +
                           formatNumber(sim.settings.frameRate) + " needs " + formatNumber(stepsPerFrame) +
                           " steps per frame, more than maxStepsPerFrame = " +
                           std::to_string(sim.settings.limits.maxStepsPerFrame) +
                           "; raise timeStep or frameRate, or raise Simulation.maxStepsPerFrame",
                       p_.where());
  }

 private:
  ElementParams p_;
  ParamBinding<SimulationSettings> settings_;
  ParamBinding<ResourceLimits> limits_;
};

class WaterModule : public Module {
 public:
  WaterModule(const ElementParams& p, ParamBinding<WaterSettings> water) : p_(p), water_(std::move(water)) {}
  void configure(Simulation& sim) override {
    water_.fill(p_, sim.water);
    sim.water.where = p_.where();
  }

 private:
  ElementParams p_;
  ParamBinding<WaterSettings> water_;
};

// <WaterBlock>'s parameters (bound in registerCoreElements; the defaults here).
struct WaterBlockParams {
  Vec3 min{0.f, 0.f, 0.f};
  Vec3 max{0.2f, 0.2f, 0.2f};
  Vec3 velocity{0.f, 0.f, 0.f};
};

class WaterBlockModule : public Module {
 public:
  WaterBlockModule(const WaterBlockParams& b, std::string where) : b_(b), where_(std::move(where)) {}
  void setup(Simulation& sim) override {
    const Vec3 lo = b_.min, hi = b_.max, v = b_.velocity;
    const float s = sim.water.spacing;
    if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z))
      throw InputError("<WaterBlock>: max must exceed min on every axis", where_);
    // Counted in double first: 2^22 particles a side is 2^66, past any 64-bit count.
    auto along = [s](float extent) { return std::max(1.0, std::floor(double(extent / s) + 1e-4)); };
    const double nxd = along(hi.x - lo.x), nyd = along(hi.y - lo.y), nzd = along(hi.z - lo.z);
    sim.checkParticleBudget(nxd * nyd * nzd, "<WaterBlock>", where_);
    const long long nx = (long long)nxd, ny = (long long)nyd, nz = (long long)nzd, total = nx * ny * nz;
    std::vector<ParticleInit> batch;
    batch.reserve(static_cast<std::size_t>(total));
    for (long long k = 0; k < nz; ++k)
      for (long long j = 0; j < ny; ++j)
        for (long long i = 0; i < nx; ++i) {
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
  WaterBlockParams b_;
  std::string where_;
};

// The collider elements' parameters, one struct per shape (the defaults
// here); friction, name and path are common to all three.
struct PlaneParams {
  Vec3 point{0.f, 0.f, 0.f};
  Vec3 normal{0.f, 1.f, 0.f};
  float friction = 0.1f;
  std::string name, path;
};
struct BoxParams {
  Vec3 min{-1.f, -1.f, -1.f};
  Vec3 max{1.f, 1.f, 1.f};
  bool inside = false;
  float friction = 0.1f;
  std::string name, path;
};
struct SphereParams {
  Vec3 center{0.f, 0.f, 0.f};
  float radius = 0.1f;
  bool inside = false;
  float friction = 0.1f;
  std::string name, path;
};

// What a collider element gives its module: the collider at rest, its name and scripted path.
struct ColliderElement {
  Collider collider;
  std::string name, path, where;
};

// The parts every shape shares: its friction, name and path.
template <class P>
ColliderElement colliderBase(const P& p, int shape, const std::string& where) {
  ColliderElement e{Collider{}, p.name, p.path, where};
  e.collider.shape = shape;
  e.collider.friction = p.friction;
  return e;
}
ColliderElement colliderOf(const PlaneParams& p, const std::string& where) {
  ColliderElement e = colliderBase(p, kColliderPlane, where);
  if (length(p.normal) < 1e-12f) throw InputError("<Plane>: normal must not be zero", where);
  e.collider.a = p.point;
  e.collider.b = p.normal / length(p.normal);
  return e;
}
ColliderElement colliderOf(const BoxParams& p, const std::string& where) {
  if (!(p.max.x > p.min.x && p.max.y > p.min.y && p.max.z > p.min.z))
    throw InputError("<Box>: max must exceed min on every axis", where);
  ColliderElement e = colliderBase(p, kColliderBox, where);
  e.collider.a = p.min;
  e.collider.b = p.max;
  e.collider.inside = p.inside ? 1 : 0;
  return e;
}
ColliderElement colliderOf(const SphereParams& p, const std::string& where) {
  ColliderElement e = colliderBase(p, kColliderSphere, where);
  e.collider.a = p.center;
  e.collider.radius = p.radius;
  e.collider.inside = p.inside ? 1 : 0;
  return e;
}

class ColliderModule : public Module {
 public:
  explicit ColliderModule(ColliderElement e) : e_(std::move(e)), shape_(e_.collider.shape), base_(e_.collider) {}
  void setup(Simulation& sim) override {
    path_ = parsePath(e_.path, e_.where);
    index_ = int(sim.colliders.size());
    const std::string& name = e_.name;
    for (const auto& other : sim.colliderNames)
      if (!name.empty() && other == name)
        throw InputError("a collider named '" + name + "' already exists", e_.where);
    sim.colliders.push_back(base_);
    sim.colliderNames.push_back(name);
    sim.collidersChanged();
  }
  // A scripted collider moves to where its path is at the end of the step.
  void beforeStep(Simulation& sim) override {
    if (path_.size() < 2) return;
    const double dt = sim.settings.timeStep;
    const Vec3 now = offsetAt(sim.time()), next = offsetAt(sim.time() + dt);
    Collider c = base_;
    if (shape_ != kColliderPlane) c.b = c.b + (shape_ == kColliderBox ? next : Vec3(0.f, 0.f, 0.f));
    c.a = c.a + next;
    c.displacement = next;
    c.velocity = (next - now) / float(dt);
    sim.colliders[index_] = c;
    sim.collidersChanged();
  }

 private:
  struct Key {
    double time;
    Vec3 offset;
  };
  // "t x y z; t x y z; ..." with increasing times.
  static std::vector<Key> parsePath(const std::string& text, const std::string& where) {
    std::vector<Key> keys;
    std::istringstream all(text);
    for (std::string item; std::getline(all, item, ';');) {
      if (item.find_first_not_of(" \t\n") == std::string::npos) continue;
      std::istringstream in(item);
      Key k;
      std::string extra;
      if (!(in >> k.time >> k.offset.x >> k.offset.y >> k.offset.z) || (in >> extra))
        throw InputError("path: '" + item + "' is not 'time x y z'", where);
      if (!keys.empty() && k.time <= keys.back().time)
        throw InputError("path: key times must increase", where);
      keys.push_back(k);
    }
    return keys;
  }
  // Piecewise-linear offset; held constant before the first and after the last key.
  Vec3 offsetAt(double t) const {
    if (t <= path_.front().time) return path_.front().offset;
    for (std::size_t k = 1; k < path_.size(); ++k)
      if (t <= path_[k].time) {
        const float a = float((t - path_[k - 1].time) / (path_[k].time - path_[k - 1].time));
        return path_[k - 1].offset * (1.f - a) + path_[k].offset * a;
      }
    return path_.back().offset;
  }
  ColliderElement e_;
  int shape_;
  Collider base_;
  std::vector<Key> path_;
  int index_ = -1;
};

// <Plugin> is acted on by the scene loader (it loads the library before the
// other elements are checked); as a module it does nothing.
class NoModule : public Module {};

// friction, name and path: the parameters every collider element has.
template <class P>
void bindColliderCommon(ParamBinding<P>& binding) {
  binding.real("friction", &P::friction, "", "Fraction of tangential motion removed on contact.", 0.0, 1.0)
      .text("name", &P::name, "Name, for cloth attachTo.")
      .text("path", &P::path, "Scripted motion: 'time x y z; time x y z; ...' offsets, linear in between.");
}

}  // namespace

void registerCoreElements(ModuleRegistry& r) {
  // <Simulation> and <Water>: each parameter bound to the settings member
  // it fills, its default the member's (Registry/ParamBinding.h).
  {
    ElementDecl decl("Simulation", "Time stepping, output rate and gravity.", "Simulation");
    ParamBinding<SimulationSettings> settings(decl);
    using S = SimulationSettings;
    settings.real("timeStep", &S::timeStep, "s", "Time step (Table 1).", 0.0, 1.0, true)
        .real("duration", &S::duration, "s", "Simulated time of a run (`--time` and `--frames` override it).", 0.0,
              1e9, true)
        .real("frameRate", &S::frameRate, "1/s", "Output frames per simulated second, independent of the time step.",
              0.0, 1e6, true)
        .vector("gravity", &S::gravity, "m/s^2", "Gravitational acceleration; +y is up by default.")
        .real("maxSpeed", &S::maxSpeed, "m/s", "A particle faster than this is reported as an instability.", 0.0,
              1e9, true)
        .boolean("cudaGraph", &S::cudaGraph,
                 "GPU: capture each step's kernels into CUDA graphs, one per stretch of work between two waits of the "
                 "host, and replay them, updated with the step's parameters (Doc/design.md, \"Step graphs\"); false "
                 "queues every kernel from the host. No effect on the CPU.")
        .integer("clothIterations", &S::clothIterations,
                 "Cloth solver iterations n_s per step (Eq. 5), per cloth sub-step. 0: the solver's own (12 for "
                 "chebyshev and xpbd cloth, the paper's 8 for a scene of pbd cloth only).", 0, 1000)
        .integer("clothSubsteps", &S::clothSubsteps,
                 "Cloth sub-steps per step: gravity, constraints and colliders of the cloth advance in steps "
                 "of timeStep / clothSubsteps (less stretch than the same number of iterations in one step); with "
                 "clothSubstepTravel > 0, the fewest a step takes. 0: the solver's own (for chebyshev and xpbd "
                 "cloth 4, and with its strain rule (clothStrainTarget) from 4 at the start down to 2 where the "
                 "strain stays low; 1 for pbd only).",
                 0, 100)
        .real("clothSubstepTravel", &S::clothSubstepTravel, "",
              "> 0: each step takes as many cloth sub-steps as keep every cloth vertex within this fraction "
              "of its thickness (Cloth.thickness) of travel per sub-step, from clothSubsteps up to "
              "clothMaxSubsteps, each of clothIterations, so that contacts see fast cloth in short sub-steps "
              "and slow cloth costs few (Doc/design.md, \"How many sub-steps, and which run the contacts\"). Needs chebyshev or xpbd cloths: pbd's "
              "stiffness is per iteration. 0: always clothSubsteps. < 0: the solver's own (0.5 without pbd "
              "cloth, 0 with it).",
              -1.0, 100.0)
        .integer("clothMaxSubsteps", &S::clothMaxSubsteps,
                 "The most cloth sub-steps a step takes with clothSubstepTravel > 0.", 1, 100)
        .real("clothStrainTarget", &S::clothStrainTarget, "",
              "With clothSubstepTravel > 0: the 99th percentile of edge strain the cloth's sub-steps are raised "
              "to keep under, up to clothStrainMaxSubsteps. Each step counts the edges the step before left past "
              "it: over 1 % raises the sub-steps by one for the steps after, over 3 % by half. Strain grows "
              "with the square of the sub-step, so 10 steps in a row with under 1 % of edges whose strain so "
              "scaled to a quarter fewer sub-steps passes 0.8 of the target lower them by that quarter; after 20 "
              "steps without a raise the strain as it is under 0.9 of the target, and so scaled under 1.5 of "
              "it, decides (a probe, Doc/model.md, \"The default cloth solver\"). 0: sub-steps from the speed "
              "alone. < 0: the solver's own (0.02 where clothSubsteps is left to the solver and no cloth is pbd, "
              "else 0).",
              -1.0, 1.0)
        .boolean("clothStrainStretchOnly", &S::clothStrainStretchOnly,
                 "With clothStrainTarget > 0: the strain rule counts an edge's stretch alone, not its "
                 "compression. A sheet held at points wrinkles across the pulls, finer than its mesh, and shows it "
                 "as shortened edges that more sub-steps barely change (Doc/model.md, \"The default cloth "
                 "solver\"). false: |l - l0| / l0, the strain stats.csv's strain_p99_* columns report.")
        .real("clothStrainRedo", &S::clothStrainRedo, "",
              "With clothStrainTarget > 0: a step whose cloth sub-steps leave over 1 % of the edges with a "
              "strain |l - l0| / l0 (with clothStrainStretchOnly, stretch alone) past this times "
              "clothStrainTarget (3 % by default) runs them again from the step's start, half as many again, "
              "at most 3 times and within clothStrainMaxSubsteps: a load that grows within a few steps meets "
              "the count it needs in the step it comes (Doc/model.md, \"The default cloth solver\"). 0: no "
              "redo; under 1 the bound lies under the target, and most loaded steps are redone.",
              0.0, 100.0)
        .boolean("clothContactsBySpeed", &S::clothContactsBySpeed,
                 "With clothSubstepTravel > 0: the cloth's contact passes (particle and vertex-triangle contact) "
                 "run in as many of a step's sub-steps as its speed asks for (one a step for slow cloth), spread "
                 "evenly, the last always, each testing the path since the one before; the sub-steps that "
                 "clothSubsteps or clothStrainTarget add beyond those serve the solve's convergence alone "
                 "(Doc/model.md, \"Cloth sub-steps\"). false: contact passes in every sub-step.")
        .real("clothAccelerationLimit", &S::clothAccelerationLimit, "m/s^2",
              "With cloth sub-steps: a cloth vertex leaves a step with its last sub-step's velocity, but at most "
              "A x timeStep / 2 faster than its mean velocity over the step (its speed is scaled down, never up): "
              "smooth motion under an acceleration up to A passes unchanged, while a vertex that contacts and "
              "the solve push back and forth every sub-step, which moves a fraction of a thickness each way and "
              "gains a speed that grows with the sub-steps, keeps its mean motion (Doc/model.md, \"The end "
              "velocity's limit\"). 0: no limit. < 0: the solver's own (200 with the strain rule, where "
              "clothSubsteps is left to the solver and no cloth is pbd, else 0).",
              -1.0, 1e6)
        .integer("clothStrainMaxSubsteps", &S::clothStrainMaxSubsteps,
                 "The most cloth sub-steps clothStrainTarget raises a step to, within clothMaxSubsteps. 0: 8 times "
                 "the count the rule starts from, clothSubsteps (32 for the solver's own counts, which start at "
                 "4): a sheet carrying a water block on four pinned corners needs 32 (Doc/model.md, \"The "
                 "default cloth solver\").",
                 0, 100)
        .real("clothSpectralRadius", &S::clothSpectralRadius, "",
              "Cloth.model=chebyshev: the spectral radius rho its Chebyshev weights assume (Wang 2015); "
              "nearer 1 converges further per iteration. With the weights delayed (clothChebyshevDelay) a "
              "hanging sheet comes to rest up to 0.97 and keeps moving at 0.99 (Doc/model.md, \"Cloth solvers\").",
              0.0, 0.9999)
        .integer("clothChebyshevDelay", &S::clothChebyshevDelay,
                 "Cloth.model=chebyshev: plain Jacobi iterations at the start of each sub-step before the "
                 "Chebyshev weights (Wang 2015), while the vertices settle onto their tethers, colliders and "
                 "stretch limits. 0: weights from the first iteration, with which a hanging sheet keeps moving "
                 "from rho 0.8 (Doc/model.md, \"Cloth solvers\").",
                 0, 1000)
        .integer("couplingPasses", &S::couplingPasses, "Passes of the water-triangle constraint (Eq. 21) per step.",
                 1, 100)
        .integer("contactPasses", &S::contactPasses, "Passes of cloth self and cloth-cloth contact per step.", 0,
                 100)
        .integer("crossingGuardRounds", &S::crossingGuardRounds,
                 "Rounds per cloth sub-step of the crossing guard: an edge that ends the sub-step through a "
                 "triangle it was not through at its start puts its vertices and the triangle's back where the "
                 "sub-step started them, so a sheet never passes through itself or another (Doc/design.md, "
                 "\"Tangles and the crossing guard\"; Doc/performance.md, \"The crossing guard's cost (H100)\": 3 rounds take fig9b's worst p99 strain from 15-16 % to 10.6 % and add "
                 "about 1.6 ms a step on the H100; 1 or 2 rounds stretch the sheet more than none). 0: no guard.",
                 0, 100)
        .vector("domainMin", &S::domainMin, "m", "Water below this corner is removed (drained).")
        .vector("domainMax", &S::domainMax, "m", "Water above this corner is removed (drained).");
    ParamBinding<ResourceLimits> limits(decl);
    limits
        .integer("maxParticles", &ResourceLimits::maxParticles,
                 "Limit: most particles the run may hold, counting all its nozzles would emit up to its end "
                 "(0: as many as the memory the run may take holds at about 512 bytes each: on the CPU the smallest of "
                 "the machine's memory, ulimit -v and -d, the cgroup's memory limit and SOAK_MEMORY_LIMIT; on the GPU "
                 "its free memory).",
                 0, 2000000000)
        .integer("maxStepsPerFrame", &ResourceLimits::maxStepsPerFrame,
                 "Limit: most time steps between two output frames.", 1, 2000000000)
        .integer("maxCellParticles", &ResourceLimits::maxCellParticles,
                 "Limit: most particles a neighbour-grid cell (edge: the largest support radius) may hold at "
                 "rest spacing: (h / spacing)^3 for water, (h / edge length)^2 for a cloth sheet.",
                 1, 2000000000);
    r.add(decl.makeUnique().create([settings, limits](const ElementParams& p) {
      return std::make_unique<SimulationModule>(p, settings, limits);
    }));
  }
  {
    ElementDecl decl("Water", "Properties of water particles (Table 1).", "Water");
    ParamBinding<WaterSettings> water(decl);
    using W = WaterSettings;
    water.real("spacing", &W::spacing, "m", "Initial particle spacing r0.", 0.0, 10.0, true)
        .real("supportRadius", &W::supportRadius, "m", "SPH support radius h.", 0.0, 10.0, true)
        .real("restDensity", &W::restDensity, "kg/m^3", "Rest density rho0 of water.", 0.0, 1e6, true)
        .real("particleMass", &W::particleMass, "kg", "Mass of a full water particle.", 0.0, 1e6, true)
        .integer("iterations", &W::iterations, "Density constraint iterations per step.", 1, 1000)
        .real("relaxation", &W::relaxation, "",
              "Constraint relaxation epsilon, relative to the denominator of a particle at rest.", 0.0, 1e6)
        .real("artificialPressure", &W::artificialPressure, "",
              "k of the s_corr term, as a fraction of a full density error's correction.", 0.0, 1.0)
        .real("artificialPressureRadius", &W::artificialPressureRadius, "", "delta q of s_corr, relative to h.", 0.0,
              1.0, true)
        .real("viscosity", &W::viscosity, "", "XSPH viscosity c.", 0.0, 1.0)
        .real("vorticity", &W::vorticity, "m/s", "Vorticity confinement epsilon (0: off).", 0.0, 1e3)
        .real("neighbourSkin", &W::neighbourSkin, "",
              "The density iterations visit the pairs within (1 + skin) h found at the start of the step "
              "(a large value, e.g. 100, visits every grid candidate, as a query per iteration would).",
              0.0, 1e3);
    r.add(decl.makeUnique().create([water](const ElementParams& p) { return std::make_unique<WaterModule>(p, water); }));
  }
  {
    ElementDecl decl("WaterBlock", "A box filled with water particles on a lattice of the water spacing.", "Water");
    ParamBinding<WaterBlockParams> block(decl);
    block.vector("min", &WaterBlockParams::min, "m", "Lower corner.")
        .vector("max", &WaterBlockParams::max, "m", "Upper corner.")
        .vector("velocity", &WaterBlockParams::velocity, "m/s", "Initial velocity of every particle.");
    r.add(decl.create([block](const ElementParams& p) {
      return std::make_unique<WaterBlockModule>(block.read(p), p.where());
    }));
  }
  const auto addCollider = [&r](ElementDecl& decl, auto binding) {
    r.add(decl.create([binding](const ElementParams& p) {
      return std::make_unique<ColliderModule>(colliderOf(binding.read(p), p.where()));
    }));
  };
  {
    ElementDecl decl("Plane", "Infinite plane collider; particles stay on the side the normal points to.",
                     "Colliders");
    ParamBinding<PlaneParams> plane(decl);
    plane.vector("point", &PlaneParams::point, "m", "A point on the plane.")
        .vector("normal", &PlaneParams::normal, "", "Normal (need not be unit length).");
    bindColliderCommon(plane);
    addCollider(decl, plane);
  }
  {
    ElementDecl decl("Box", "Axis-aligned box collider: a solid obstacle, or a container with inside=\"true\".",
                     "Colliders");
    ParamBinding<BoxParams> box(decl);
    box.vector("min", &BoxParams::min, "m", "Lower corner.")
        .vector("max", &BoxParams::max, "m", "Upper corner.")
        .boolean("inside", &BoxParams::inside, "Keep particles inside the box (a tank) instead of outside.");
    bindColliderCommon(box);
    addCollider(decl, box);
  }
  {
    ElementDecl decl("Sphere", "Sphere collider: a solid ball, or a spherical container with inside=\"true\".",
                     "Colliders");
    ParamBinding<SphereParams> sphere(decl);
    sphere.vector("center", &SphereParams::center, "m", "Centre.")
        .real("radius", &SphereParams::radius, "m", "Radius.", 0.0, 1e6, true)
        .boolean("inside", &SphereParams::inside, "Keep particles inside the sphere instead of outside.");
    bindColliderCommon(sphere);
    addCollider(decl, sphere);
  }
  r.add(ElementDecl("Plugin",
                    "Loads a plugin library before the rest of the scene is read: by name from the plugin "
                    "directory, or by path (relative to the scene file).",
                    "Plugins")
            .text("name", "", "Plugin name, e.g. WetCloth (file libsoak_<name>.so in the plugin directory).")
            .text("path", "", "Path of the plugin library; used instead of name when given.")
            .create([](const ElementParams&) { return std::make_unique<NoModule>(); }));
  registerOutputElements(r);
  registerClothElement(r);
  registerWaterSourceElements(r);
}

}  // namespace soak

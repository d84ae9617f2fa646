// Simulation's part of a checkpoint (Checkpoint/Checkpoint.h writes the file).
#include <cmath>
#include <typeinfo>

#include "Checkpoint/StateStream.h"
#include "Neighbours/PairListsState.h"
#include "Simulation/Simulation.h"

namespace soak {

namespace {
bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// What the step takes for granted about the particles, checked on what a
// checkpoint loaded (a forged or damaged file must be refused, not indexed
// with): every phase is water, static, removed or one of the scene's cloths;
// each cloth vertex is there exactly once, with its cloth's phase; positions
// and velocities are finite; radii are within the grid's cell.
void checkLoadedParticles(const ParticleState& ps, const ClothSystem& cloth, float maxRadius, StateReader& in) {
  const std::vector<int> phase = ps.downloadPhases(), id = ps.downloadIds();
  const std::vector<Float4> x = ps.downloadPositions(), xs = ps.downloadPredicted();
  const std::vector<Vec3> v = ps.downloadVelocities();
  const std::vector<float> mass = ps.downloadMasses(), radius = ps.downloadRadii();
  const int clothCount = int(cloth.objects().size());
  std::vector<char> seen(std::size_t(cloth.vertexCount()), 0);
  for (std::size_t i = 0; i < phase.size(); ++i) {
    const std::string which = "particle " + std::to_string(i);
    if (!(phase[i] == kPhaseWater || phase[i] == kPhaseStatic || isRemoved(phase[i]) ||
          (isCloth(phase[i]) && phase[i] <= clothCount)))
      in.fail(which + " has phase " + std::to_string(phase[i]) + ", which the scene does not make");
    if (isCloth(phase[i])) {
      const ClothObject& c = cloth.objects()[std::size_t(phase[i] - 1)];
      if (id[i] < c.firstVertex || id[i] >= c.firstVertex + c.vertexCount || seen[std::size_t(id[i])]++)
        in.fail(which + " claims cloth vertex " + std::to_string(id[i]) + " of '" + c.name +
                "', which is not its or is claimed twice");
    }
    if (!finite(x[i].xyz()) || !finite(xs[i].xyz()) || !finite(v[i]) || !std::isfinite(x[i].w) ||
        !std::isfinite(mass[i]) || mass[i] < 0.f)
      in.fail(which + " has a non-finite position, velocity or mass");
    if (!(radius[i] > 0.f && radius[i] <= maxRadius))
      in.fail(which + " has support radius " + std::to_string(radius[i]) + ", outside (0, " +
              std::to_string(maxRadius) + "]");
  }
  for (std::size_t k = 0; k < seen.size(); ++k)
    if (!seen[k]) in.fail("cloth vertex " + std::to_string(k) + " has no particle");
}
}  // namespace

void Simulation::saveState(StateWriter& out) const {
  out.putString("simulation");
  out.put<std::int64_t>(stepIndex_);
  out.put<double>(drainedWaterMass);
  out.put<double>(emittedWaterMass);
  out.put<std::int32_t>(nextWaterId);
  out.put<std::int32_t>(cloth.vertexCount());
  particles.saveState(out);
  putListSizing(out, fluid.neighbourListSizing());
  out.put<std::int32_t>(stages_.cloth.strainSubsteps().substeps);  // Cloth/AdaptiveSubsteps.h
  out.put<std::int32_t>(stages_.cloth.strainSubsteps().calmSteps);
  out.put<std::int32_t>(stages_.cloth.strainSubsteps().leftBy);
  out.put<std::int32_t>(stages_.cloth.strainSubsteps().steadySteps);
  out.put<std::int32_t>(stages_.cloth.strainSubsteps().steadyWait);
  out.put<std::int32_t>(stages_.cloth.strainSubsteps().probeAge);
  out.put<std::int32_t>(static_cast<std::int32_t>(modules_.size()));
  for (const auto& m : modules_) {
    const Module& module = *m;
    out.putString(typeid(module).name());
    module.saveState(out);
  }
}

void Simulation::loadState(StateReader& in) {
  in.expect("simulation");
  const long long step = in.get<std::int64_t>();
  if (step < 0) in.fail("negative step index");
  const double drained = in.get<double>(), emitted = in.get<double>();
  const int nextId = in.get<std::int32_t>();
  const int clothVertices = in.get<std::int32_t>();
  if (clothVertices != cloth.vertexCount())
    in.fail("it was written for " + std::to_string(clothVertices) + " cloth vertices, the scene makes " +
            std::to_string(cloth.vertexCount()) + " (did a mesh change?)");
  particles.loadState(in);
  checkLoadedParticles(particles, cloth, maxSupportRadius_, in);
  if (nextId < 0) in.fail("negative next water id");
  const FluidListSizing lists = getListSizing(in, "neighbour list", maxListCapacity(particles.count()));
  StrainSubsteps strainSubsteps;
  strainSubsteps.substeps = in.get<std::int32_t>();
  strainSubsteps.calmSteps = in.get<std::int32_t>();
  strainSubsteps.leftBy = in.get<std::int32_t>();
  strainSubsteps.steadySteps = in.get<std::int32_t>();
  strainSubsteps.steadyWait = in.get<std::int32_t>();
  strainSubsteps.probeAge = in.get<std::int32_t>();
  if (strainSubsteps.substeps < 0 || strainSubsteps.substeps > 100 || strainSubsteps.calmSteps < 0 ||
      strainSubsteps.calmSteps > kStrainCalmSteps || strainSubsteps.leftBy < 0 || strainSubsteps.leftBy > 100 ||
      strainSubsteps.steadySteps < 0 || strainSubsteps.steadySteps > kStrainMostSteadySteps ||
      strainSubsteps.steadyWait < kStrainSteadySteps || strainSubsteps.steadyWait > kStrainMostSteadySteps ||
      strainSubsteps.probeAge < -1 || strainSubsteps.probeAge > kStrainProbeSteps)
    in.fail("cloth sub-steps from the strain (" + std::to_string(strainSubsteps.substeps) + ", calm " +
            std::to_string(strainSubsteps.calmSteps) + ", last step " + std::to_string(strainSubsteps.leftBy) +
            ", steady " + std::to_string(strainSubsteps.steadySteps) + " of " +
            std::to_string(strainSubsteps.steadyWait) + ", probe " + std::to_string(strainSubsteps.probeAge) +
            ") out of range");
  const int moduleCount = in.get<std::int32_t>();
  if (moduleCount != int(modules_.size()))
    in.fail("it was written for " + std::to_string(moduleCount) + " scene elements, the scene has " +
            std::to_string(modules_.size()));
  for (auto& m : modules_) {
    Module& module = *m;
    const std::string kind = in.getString();
    if (kind != typeid(module).name()) in.fail("scene element of kind '" + kind + "' where the scene has another");
    module.loadState(in);
  }
  stepIndex_ = step;
  time_ = double(stepIndex_) * settings.timeStep;
  drainedWaterMass = drained;
  emittedWaterMass = emitted;
  nextWaterId = nextId;
  fluid.setNeighbourListSizing(lists);
  stages_.cloth.setStrainSubsteps(strainSubsteps);
  cloth.updateSlots(particles.view());
  collidersDirty_ = true;
}

}  // namespace soak

// What a run may take, checked before anything is made or written
// (Settings.h, ResourceLimits; Doc/reliability.md, "Resource limits"): the
// particles it may hold, emission included, and how full a neighbour-grid
// cell may be.
#include <cmath>
#include <algorithm>
#include <cstdio>

#include "Base/Error.h"
#include "Base/MessageText.h"
#include "Simulation/Simulation.h"

namespace soak {

namespace {
std::string gib(double bytes) {
  char b[32];
  std::snprintf(b, sizeof(b), "%.3g GiB", bytes / double(1ull << 30));
  return b;
}
std::string count(double n) {
  char b[32];
  std::snprintf(b, sizeof(b), n < 1e7 ? "%.0f" : "%.3g", n);
  return b;
}
}  // namespace

double Simulation::particleBudget() const {
  if (settings.limits.maxParticles > 0) return double(std::min(settings.limits.maxParticles, kMaxParticles));
  const double available = deviceMemoryBudget(device_).bytes;
  const double fits = available >= 0 ? std::floor(available / double(kEstimatedBytesPerParticle)) : double(kMaxParticles);
  return std::min(fits, double(kMaxParticles));
}

// Counts are doubles here: a block of 2^22 particles a side is 2^66, which
// no 64-bit integer holds, and must be refused, not wrapped to 0.
void Simulation::checkParticleBudget(double added, const std::string& what, const std::string& where) const {
  const double total = added + double(particles.count());
  if (!(total <= particleBudget())) {
    const bool byMemory = settings.limits.maxParticles == 0 && particleBudget() < double(kMaxParticles);
    std::string why;
    if (byMemory) {
      const MemoryBound budget = deviceMemoryBudget(device_);
      why = "about " + gib(total * double(kEstimatedBytesPerParticle)) + " at ~" +
            std::to_string(kEstimatedBytesPerParticle) + " bytes per particle, more than the " +
            gib(budget.bytes) + " of memory the run may take on the " + deviceName(device_) + " (set by " +
            budget.source + "); use a coarser spacing or a smaller region, or set Simulation.maxParticles if the "
            "run needs fewer bytes per particle";
    }
    else if (settings.limits.maxParticles > 0 && settings.limits.maxParticles < kMaxParticles)
      why = "more than Simulation.maxParticles = " + std::to_string(settings.limits.maxParticles) +
            "; raise it (up to " + std::to_string(kMaxParticles) + ") or use a coarser spacing";
    else
      why = "a run holds at most " + std::to_string(kMaxParticles) + " (32-bit indices)";
    throw InputError(what + " would make " + count(added) + " particles (" + count(total) + " in all): " + why,
                     where);
  }
}

void Simulation::checkPlannedParticles(double endTime) const {
  double planned = 0.0;
  PlannedParticles largest;
  for (const auto& m : modules_) {
    const PlannedParticles p = m->plannedParticles(*this, endTime);
    planned += p.count;
    if (p.count > largest.count) largest = p;
  }
  if (planned > 0.0)
    checkParticleBudget(planned, largest.what + " (emitting until t = " + count(endTime) + " s" +
                                     (planned > largest.count ? ", with the other emitters" : "") + ")",
                        largest.where);
}

// A neighbour query visits the 27 cells around a particle; a cell's edge is
// the largest support radius. Water at rest spacing r0 puts (h / r0)^3
// particles in a cell, a flat sheet (h^2 x its vertices per square metre).
void Simulation::checkCellOccupancy() const {
  const double h = maxSupportRadius_, limit = double(settings.limits.maxCellParticles);
  auto refuse = [&](const std::string& what, double n, const std::string& where) {
    throw InputError(what + ": a neighbour-grid cell (edge " + formatNumber(h) +
                         " m, the largest support radius) would hold about " + count(n) +
                         " particles at rest, more than Simulation.maxCellParticles = " +
                         std::to_string(settings.limits.maxCellParticles) +
                         "; lower the support radius or coarsen the spacing, or raise the limit",
                     where);
  };
  bool hasWater = !water.where.empty() || particles.count() > cloth.vertexCount();
  for (const auto& m : modules_) hasWater = hasWater || m->plannedParticles(*this, 1e30).count > 0.0;
  const double waterPerCell = std::pow(h / double(water.spacing), 3.0);
  if (hasWater && !(waterPerCell <= limit))
    refuse("<Water> spacing " + formatNumber(double(water.spacing)) + " m", waterPerCell, water.where);
  for (const ClothObject& c : cloth.objects()) {
    const double perCell = h * h * double(c.vertexCount) / std::max(c.restArea, 1e-30);
    if (!(perCell <= limit)) refuse("<Cloth> '" + c.name + "'", perCell, c.where);
  }
}

}  // namespace soak

// How many particles a run can hold on its device, checked before any is made.
#include <cstdio>

#include "Base/Error.h"
#include "Simulation/Simulation.h"

namespace soak {

namespace {
std::string gib(double bytes) {
  char b[32];
  std::snprintf(b, sizeof(b), "%.1f GiB", bytes / double(1ull << 30));
  return b;
}
}  // namespace

void Simulation::checkParticleBudget(long long added, const std::string& what, const std::string& where) const {
  const long long total = added + particles.count();
  const double needed = double(total) * double(kEstimatedBytesPerParticle);
  const double available = double(deviceMemoryBytes(device_));
  if (available > 0 && needed > available)
    throw InputError(what + " would make " + std::to_string(added) + " particles (" + std::to_string(total) +
                         " in all): about " + gib(needed) + " at ~" + std::to_string(kEstimatedBytesPerParticle) +
                         " bytes per particle, more than the " + gib(available) + " of memory the device (" +
                         deviceName(device_) + ") has; use a coarser spacing or a smaller region",
                     where);
  if (total > kMaxParticles)
    throw InputError(what + " would make " + std::to_string(added) + " particles (" + std::to_string(total) +
                         " in all); a run holds at most " + std::to_string(kMaxParticles),
                     where);
}

}  // namespace soak

#include "Simulation/Instability.h"

#include <cmath>
#include <cstdio>

#include "Backend/ForEach.h"
#include "Backend/Primitives.h"
#include "Simulation/Simulation.h"

namespace soak {

Instability findInstability(Simulation& sim, Buffer<float>& scratch, const std::string& stage) {
  Instability s;
  ParticleView p = sim.particles.view();
  if (p.count == 0) return s;
  scratch.resize(p.count);
  float* bad = scratch.data();
  const float limit2 = sim.settings.maxSpeed * sim.settings.maxSpeed;
  forEach(sim.device(), p.count, SOAK_LAMBDA(int i) {
    const Vec3 x = p.position[i].xyz(), xp = p.predicted[i].xyz(), v = p.velocity[i];
    bad[i] = (!isFinite(x) || !isFinite(xp) || !isFinite(v) || lengthSquared(v) > limit2) ? 1.f : 0.f;
  }, "instability.check");
  if (reduceMax(sim.device(), bad, p.count) <= 0.f) return s;
  const std::vector<float> flags = scratch.download();
  const std::vector<Float4> x = sim.particles.downloadPositions();
  const std::vector<Float4> xp = sim.particles.downloadPredicted();
  const std::vector<Vec3> v = sim.particles.downloadVelocities();
  const std::vector<int> ids = sim.particles.downloadIds(), phases = sim.particles.downloadPhases();
  // The worst one: a non-finite value first, else the fastest.
  int worst = -1;
  float worstSpeed = -1.f;
  for (int i = 0; i < p.count; ++i) {
    if (flags[i] <= 0.f) continue;
    const bool fin = isFinite(x[i].xyz()) && isFinite(xp[i].xyz()) && isFinite(v[i]);
    const float speed = fin ? length(v[i]) : INFINITY;
    if (speed > worstSpeed) {
      worstSpeed = speed;
      worst = i;
    }
  }
  s.found = true;
  s.stage = stage;
  s.step = sim.stepIndex();
  s.time = sim.time();
  s.id = ids[worst];
  s.cloth = isCloth(phases[worst]);
  s.position = x[worst].xyz();
  s.velocity = v[worst];
  s.finite = isFinite(s.position) && isFinite(xp[worst].xyz()) && isFinite(s.velocity);
  s.speed = s.finite ? length(s.velocity) : INFINITY;
  return s;
}

std::string describeInstability(const Instability& s, float maxSpeed) {
  char where[160], what[200];
  if (s.stage.empty())
    std::snprintf(where, sizeof where, "found after step %lld (t = %.4f s)", s.step, s.time);
  else
    std::snprintf(where, sizeof where, "in step %lld (from t = %.4f s), after stage %s", s.step + 1, s.time,
                  s.stage.c_str());
  if (!s.finite)
    std::snprintf(what, sizeof what, "%s particle %d has a non-finite position, predicted position or velocity", s.cloth ? "cloth" : "water",
                  s.id);
  else
    std::snprintf(what, sizeof what,
                  "%s particle %d at (%.4g, %.4g, %.4g) moves at %.4g m/s, above Simulation.maxSpeed = %g m/s",
                  s.cloth ? "cloth" : "water", s.id, s.position.x, s.position.y, s.position.z, s.speed,
                  double(maxSpeed));
  return std::string("unstable: ") + where + ": " + what;
}

}  // namespace soak

// The CPU backend is deterministic: the same scene gives bit-identical
// particles on repeated runs and on 1 or 2 OpenMP threads (coloured
// Gauss-Seidel and gathered Jacobi corrections write each value from one
// thread, in an order that does not depend on the thread count).
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>
#include <map>
#include <vector>

#include "Support/TestScenes.h"

using namespace soak;

namespace {
// Water falls on a pinned wetting sheet and drips: fluid, cloth, contacts,
// coupling, absorption, diffusion and emission all run.
const char* kScene =
    "<Scene><Cloth origin='-0.2 0.5 -0.2' width='0.4' height='0.4' cellsU='20' cellsV='20' "
    "pinCorners='u0v0 u1v0 u0v1 u1v1' tetherSlack='0.1'/>"
    "<WaterBlock min='-0.08 0.53 -0.08' max='0.08 0.65 0.08'/><Plane/>"
    "<WetCloth initialSaturation='0.3'/></Scene>";

struct Snapshot {
  std::map<std::pair<int, int>, Float4> byPhaseAndId;  // (phase, id) -> position
  std::map<std::pair<int, int>, float> saturation;  // cloth vertices
  int count = 0;
};

Snapshot run(int threads, int steps) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  auto sim = test::makeSimulation(kScene, Device::Cpu, reg);
  for (int s = 0; s < steps; ++s) sim->step();
  Snapshot snap;
  const auto x = sim->particles.downloadPositions();
  const auto id = sim->particles.downloadIds();
  const auto phase = sim->particles.downloadPhases();
  for (std::size_t i = 0; i < x.size(); ++i) snap.byPhaseAndId[{phase[i], id[i]}] = x[i];
  snap.count = int(x.size());
  const int ch = sim->particles.findChannel("saturation");
  if (ch >= 0) {
    const auto s = sim->particles.downloadChannel(ch);
    for (std::size_t i = 0; i < x.size(); ++i) snap.saturation[{phase[i], id[i]}] = s[i];
  }
  omp_set_num_threads(saved);
  return snap;
}

bool bitIdentical(const Float4& a, const Float4& b) { return std::memcmp(&a, &b, sizeof(Float4)) == 0; }

void expectIdentical(const Snapshot& a, const Snapshot& b) {
  ASSERT_EQ(a.count, b.count);
  ASSERT_EQ(a.byPhaseAndId.size(), b.byPhaseAndId.size());
  int differing = 0;
  for (const auto& [key, xa] : a.byPhaseAndId) {
    auto it = b.byPhaseAndId.find(key);
    ASSERT_NE(it, b.byPhaseAndId.end());
    if (!bitIdentical(xa, it->second)) ++differing;
  }
  EXPECT_EQ(differing, 0) << "particles whose position differs in some bit";
  ASSERT_FALSE(a.saturation.empty());
  int satDiffering = 0;
  for (const auto& [key, sa] : a.saturation)
    if (std::memcmp(&sa, &b.saturation.at(key), sizeof(float)) != 0) ++satDiffering;
  EXPECT_EQ(satDiffering, 0) << "particles whose saturation differs in some bit";
}
}  // namespace

TEST(Determinism, RepeatedRunsAndThreadCountsAreBitIdentical) {
  const int steps = 80;
  const Snapshot one = run(1, steps), oneAgain = run(1, steps), two = run(2, steps);
  std::printf("determinism: %d particles after %d steps compared bit by bit (1 thread twice, 2 threads)\n",
              one.count, steps);
  expectIdentical(one, oneAgain);
  expectIdentical(one, two);
}

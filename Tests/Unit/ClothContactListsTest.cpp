// The cloth contact candidates found once a step (Cloth/ClothContactLists.h):
// no pair that touches by the end of a step is missing from them, they
// hold the grid's candidates that pass their test in the grid's order, and
// contact over them has the same bits as contact walking the grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "Cloth/ClothContact.h"
#include "Cloth/ClothContactLists.h"
#include "Support/TestScenes.h"

using namespace soak;

namespace {

// A sheet hanging edge-down, dropped on the floor: it crumples into folds
// whose layers touch. The figure scenes' chebyshev sub-steps (contact after
// each of 8).
const char* kCrumplingSheet =
    "<Scene><Simulation clothSubsteps='8' clothIterations='12'/>"
    "<Cloth model='chebyshev' origin='-0.2 0.45 0' axisU='1 0 0' axisV='0 -1 0.05' width='0.4' height='0.4' "
    "cellsU='24' cellsV='24' bendStiffness='0'/><Plane point='0 0 0' normal='0 1 0'/></Scene>";

struct VertexState {
  std::vector<Vec3> x, v;
};

VertexState byVertex(const Simulation& sim) {
  const std::vector<Float4> x = sim.particles.downloadPositions();
  const std::vector<Vec3> v = sim.particles.downloadVelocities();
  const std::vector<int> id = sim.particles.downloadIds(), phase = sim.particles.downloadPhases();
  VertexState s;
  s.x.resize(sim.cloth.vertexCount());
  s.v.resize(sim.cloth.vertexCount());
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!isCloth(phase[i])) continue;
    s.x[id[i]] = x[i].xyz();
    s.v[id[i]] = v[i];
  }
  return s;
}

bool same(Vec3 a, Vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

}  // namespace

TEST(ClothContactLists, EveryPairThatEndsAStepTouchingStartedItWithinReach) {
  // For each step: every pair of vertices that are not rest-shape
  // neighbours and end the step within 1.5 contact distances of each other
  // was within the lists' reach, kContactReachDistances c +
  // (kContactReachRelative |v_i - v_j| + kContactReachMotion (|v_i| +
  // |v_j|)) dt, at the step's start (c = the
  // thickness here: one cloth; the sheet is coarse enough that 3 c is more
  // than the triangle reach).
  test::TestRegistry reg;
  auto sim = test::makeSimulation(kCrumplingSheet, Device::Cpu, reg);
  const std::vector<Vec3> rest = sim->cloth.downloadVertexPositions(sim->particles, 0);
  const float dt = float(sim->settings.timeStep);
  const int n = sim->cloth.vertexCount();
  const float c = sim->cloth.view().thickness[0];  // a CPU run: host memory
  ASSERT_GT(c, 0.f);
  long touching = 0;
  double worst = 0.0;  // start distance over reach, largest
  for (int s = 0; s < 150; ++s) {
    const VertexState start = byVertex(*sim);
    sim->step();
    const VertexState end = byVertex(*sim);
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b) {
        if (lengthSquared(rest[a] - rest[b]) < 1.44f * c * c) continue;
        if (lengthSquared(end.x[a] - end.x[b]) >= 2.25f * c * c) continue;
        ++touching;
        const float reach = kContactReachDistances * c +
                            (kContactReachRelative * length(start.v[a] - start.v[b]) +
                             kContactReachMotion * (length(start.v[a]) + length(start.v[b]))) *
                                dt;
        const float d = length(start.x[a] - start.x[b]);
        worst = std::max(worst, double(d / reach));
        ASSERT_LT(d, reach) << "step " << s << ": vertices " << a << " and " << b;
      }
  }
  std::printf("crumpling sheet: %ld touching pair-steps, start distance at most %.2f of the reach\n", touching,
              worst);
  EXPECT_GT(touching, 1000);  // the sheet does fold onto itself
}

TEST(ClothContactLists, ListsAreTheGridsCandidatesThatMayTouchAndContactGivesTheSameBitsWithout) {
  test::TestRegistry reg;
  auto sim = test::makeSimulation(kCrumplingSheet, Device::Cpu, reg);
  for (int s = 0; s < 90; ++s) sim->step();
  // The state at a step's start: x and v now, x* after gravity and a
  // perturbation (as if mid-solve), so that contact has work to do.
  sim->settings.timeStep = 0.015;
  ParticleView p = sim->particles.view();
  for (int i = 0; i < p.count; ++i)
    p.predicted[i] = Float4(p.position[i].xyz() + Vec3(0.f, -0.004f, 0.f) * float((i * 7919) % 5), p.position[i].w);
  const ClothView c = sim->cloth.view();
  const ClothSlots cloth = clothSlots(c);
  const GridView g = sim->cloth.grid();
  const float dt = 0.015f;
  ClothContactLists lists(Device::Cpu);
  lists.build(p, g, c, dt, true);
  ASSERT_EQ(lists.itemsWithoutList(), 0);
  long listed = 0, walked = 0;
  for (int v = 0; v < cloth.count; ++v) {
    const int i = cloth.slot[v];
    std::vector<int> fromList, expected;
    forEachContactCandidate(lists.view(), v, i, Lanes{}, [&](int j) { fromList.push_back(j); });
    forEachCandidate(g, g.slotKey[i], [&](int j) {
      ++walked;
      if (j == i) return;
      const int vi = p.id[i], vj = p.id[j];
      const float contact = 0.5f * (c.thickness[vi] + c.thickness[vj]);
      const float triangles = 1.5f * c.maxEdgeLength + 0.5f * c.maxThickness;
      const float reach = std::max(kContactReachDistances * contact, triangles) +
                          (kContactReachRelative * length(p.velocity[i] - p.velocity[j]) +
                           kContactReachMotion * (length(p.velocity[i]) + length(p.velocity[j]))) *
                              dt;
      if (lengthSquared(p.position[i].xyz() - p.position[j].xyz()) < reach * reach) expected.push_back(j);
    });
    EXPECT_EQ(fromList, expected) << "cloth particle " << v;
    listed += long(fromList.size());
  }
  std::printf("contact lists: %.1f entries per cloth particle, %.1f grid candidates\n", double(listed) / cloth.count,
              double(walked) / cloth.count);
  EXPECT_LT(listed * 3, walked * 2);  // a falling sheet at coarse spacing: the reach is near the cell size
  // One contact pass over the lists, and over no lists (every item walks
  // the grid with the same test): the same corrections, bit for bit.
  const std::vector<Float4> before = sim->particles.downloadPredicted();
  Buffer<Float4> scratch(Device::Cpu);
  scratch.resize(p.count);
  resolveClothContacts(Device::Cpu, p, lists.view(), scratch.data(), 2);
  const std::vector<Float4> viaLists = sim->particles.downloadPredicted();
  for (int i = 0; i < p.count; ++i) p.predicted[i] = before[i];
  lists.setSizing(PairListSizing{});
  lists.build(p, g, c, dt, false);
  EXPECT_EQ(lists.itemsWithoutList(), cloth.count);
  resolveClothContacts(Device::Cpu, p, lists.view(), scratch.data(), 2);
  const std::vector<Float4> viaGrid = sim->particles.downloadPredicted();
  int moved = 0;
  for (int i = 0; i < p.count; ++i) {
    EXPECT_TRUE(same(viaLists[i].xyz(), viaGrid[i].xyz())) << "slot " << i;
    moved += same(viaLists[i].xyz(), before[i].xyz()) ? 0 : 1;
  }
  EXPECT_GT(moved, 10);  // contact did act
}

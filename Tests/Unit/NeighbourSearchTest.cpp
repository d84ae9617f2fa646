#include <gtest/gtest.h>

#include "Neighbours/NeighbourGrid.h"
#include "Support/NeighbourChecks.h"

using namespace soak;

TEST(NeighbourSearch, MatchesBruteForceOnCpu) {
  for (const test::PointCase& c : test::neighbourCases()) test::expectNeighboursMatchBruteForce(Device::Cpu, c);
}

TEST(NeighbourSearch, EachCandidateVisitedOncePerQuery) {
  // Many particles in few cells: every candidate of a query must come once.
  std::vector<ParticleInit> init;
  for (int i = 0; i < 500; ++i) {
    ParticleInit p;
    p.position = Vec3(0.001f * (i % 10), 0.001f * ((i / 10) % 10), 0.001f * (i / 100));
    p.radius = 0.04f;
    p.mass = 1.f;
    init.push_back(p);
  }
  ParticleState ps(Device::Cpu);
  ps.append(init);
  NeighbourGrid grid(Device::Cpu);
  grid.build(ps, 0.04f);
  GridView g = grid.view();
  std::vector<int> visits(ps.count(), 0);
  forEachCandidate(g, g.slotKey[0], [&](int j) { ++visits[j]; });
  for (int v : visits) EXPECT_EQ(v, 1);
}

TEST(NeighbourSearch, MemoryDoesNotGrowWithDomainExtent) {
  auto bytesFor = [](float spread) {
    std::vector<ParticleInit> init(1000);
    for (int i = 0; i < 1000; ++i) {
      init[i].position = Vec3(spread * float(i), 0.f, -spread * float(i % 7));
      init[i].radius = 0.04f;
      init[i].mass = 1.f;
    }
    ParticleState ps(Device::Cpu);
    ps.append(init);
    NeighbourGrid grid(Device::Cpu);
    grid.build(ps, 0.04f);
    return grid.bytes();
  };
  EXPECT_EQ(bytesFor(0.001f), bytesFor(1.0e5f));
}

TEST(NeighbourSearch, RejectsNonPositiveCellSize) {
  ParticleState ps(Device::Cpu);
  NeighbourGrid grid(Device::Cpu);
  EXPECT_THROW(grid.build(ps, 0.f), std::exception);
}

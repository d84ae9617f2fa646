// The cloth constraints in turns (Base/Turns.h, Cloth/ConstraintTurns.h):
// each constraint's turn on a vertex must be the number of constraints of
// earlier phases on that vertex, and the last of them must carry the
// vertex's counter into the next iteration.
#include <gtest/gtest.h>

#include <cstring>

#include "Cloth/ClothTopology.h"
#include "Cloth/ConstraintColoring.h"
#include "Cloth/ConstraintTurns.h"
#include "Support/TestScenes.h"

using namespace soak;

namespace {

// One iteration's constraints in phase order: a phase index and the vertices.
struct Use {
  int phase;
  std::vector<int> vertices;
};

}  // namespace

TEST(ClothTurns, EachTurnCountsTheVertexsConstraintsInEarlierPhases) {
  TriangleMesh sheet = makeRectangularSheet(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 1), 1.f, 1.f, 9, 7);
  ClothTopology topo = buildClothTopology(sheet);
  const int nv = int(sheet.vertices.size());
  std::vector<int> ev, bv;
  for (const auto& e : topo.edges) ev.insert(ev.end(), {e[0], e[1]});
  for (const auto& b : topo.bendPairs) bv.insert(bv.end(), b.begin(), b.end());
  const ColouredOrder ec = colourConstraints(ev, 2, nv), bc = colourConstraints(bv, 4, nv);
  // Colour order, as ClothSystem uploads them; every third vertex tethered.
  std::vector<int> edges, bends;
  for (int k : ec.order) edges.insert(edges.end(), {ev[2 * k], ev[2 * k + 1]});
  for (int k : bc.order) bends.insert(bends.end(), {bv[4 * k], bv[4 * k + 1], bv[4 * k + 2], bv[4 * k + 3]});
  std::vector<char> tethered(std::size_t(nv), 0);
  for (int v = 0; v < nv; v += 3) tethered[v] = 1;
  const ConstraintTurns t = constraintTurns(nv, tethered, edges, bends);
  ASSERT_TRUE(t.fits);
  ASSERT_EQ(t.edge.size(), topo.edges.size());
  ASSERT_EQ(t.bend.size(), topo.bendPairs.size());

  // The phases as the solve runs them, and each use's 16-bit turn.
  std::vector<Use> uses;
  std::vector<std::vector<std::uint32_t>> turns;
  for (int v = 0; v < nv; ++v)
    if (tethered[v]) {
      uses.push_back({0, {v}});
      turns.push_back({t.tether[v]});
    }
  for (int col = 0; col < ec.colours(); ++col)
    for (int e = ec.colourStart[col]; e < ec.colourStart[col + 1]; ++e) {
      uses.push_back({1 + col, {edges[2 * e], edges[2 * e + 1]}});
      turns.push_back({lowTurn(t.edge[e]), highTurn(t.edge[e])});
    }
  for (int col = 0; col < bc.colours(); ++col)
    for (int b = bc.colourStart[col]; b < bc.colourStart[col + 1]; ++b) {
      uses.push_back({1 + ec.colours() + col, {bends[4 * b], bends[4 * b + 1], bends[4 * b + 2], bends[4 * b + 3]}});
      turns.push_back({lowTurn(t.bend[b].word[0]), highTurn(t.bend[b].word[0]), lowTurn(t.bend[b].word[1]),
                       highTurn(t.bend[b].word[1])});
    }
  int lastFlags = 0, checked = 0;
  for (std::size_t u = 0; u < uses.size(); ++u)
    for (std::size_t a = 0; a < uses[u].vertices.size(); ++a) {
      const int v = uses[u].vertices[a];
      int before = 0, after = 0;
      for (const Use& other : uses)
        for (int w : other.vertices)
          if (w == v) {
            before += other.phase < uses[u].phase;
            after += other.phase > uses[u].phase;
          }
      const std::uint32_t turn = turns[u][a];
      EXPECT_EQ(int(turn & 0x7fffu), before) << "use " << u << " vertex " << v;
      EXPECT_EQ((turn & 0x8000u) != 0, after == 0) << "use " << u << " vertex " << v;
      lastFlags += (turn & 0x8000u) != 0;
      ++checked;
    }
  // Every vertex of the sheet has constraints: one last use each.
  EXPECT_EQ(lastFlags, nv);
  EXPECT_GT(checked, 10 * nv);
  // The counter's path: turn t of round r waits for r * K + t and leaves
  // t + 1, or the next round's start after the vertex's last use.
  EXPECT_EQ(turnInRound(3u, 2), 2 * kTurnsPerRound + 3);
  EXPECT_EQ(turnAfter(3u, 2), 2 * kTurnsPerRound + 4);
  EXPECT_EQ(turnAfter(3u | 0x8000u, 2), 3 * kTurnsPerRound);
}

TEST(ClothTurns, SolveInTurnsLeavesEveryCounterAtTheEndOfItsLastRoundAndTheBarriersBits) {
  // A sheet with tethers (two pinned corners) folding over a sphere, 4 sub-steps
  // of 6 iterations: the solve in turns (the default) and with barriers give
  // the same bits on the CPU, and every vertex's counter ends at the start of
  // a round past the last, having been passed on by its last constraint in
  // each round.
  const std::string xml =
      "<Scene><Simulation clothIterations='6' clothSubsteps='4'/>"
      "<Cloth origin='-0.2 0.6 -0.2' width='0.4' height='0.4' cellsU='16' cellsV='16' pinCorners='u0v0 u1v0'/>"
      "<Sphere center='0 0.4 0.05' radius='0.1'/></Scene>";
  test::TestRegistry r1, r2;
  auto turns = test::makeSimulation(xml, Device::Cpu, r1);
  auto barriers = test::makeSimulation(xml, Device::Cpu, r2);
  barriers->cloth.scheduleInTurns(false);
  ASSERT_TRUE(turns->cloth.inTurns());
  ASSERT_FALSE(barriers->cloth.inTurns());
  const std::vector<Float4> start = turns->particles.downloadPositions();
  for (int s = 0; s < 30; ++s) {
    turns->step();
    barriers->step();
  }
  const std::vector<Float4> a = turns->particles.downloadPositions(), b = barriers->particles.downloadPositions();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(Float4)), 0);
  float moved = 0.f;
  for (std::size_t i = 0; i < a.size(); ++i) moved = std::max(moved, length(a[i].xyz() - start[i].xyz()));
  EXPECT_GT(moved, 0.05f);  // the sheet fell and folded: the solve had work
  const std::vector<int> progress = turns->cloth.downloadVertexProgress();
  ASSERT_EQ(int(progress.size()), turns->cloth.vertexCount());
  for (std::size_t v = 0; v < progress.size(); ++v) EXPECT_EQ(progress[v], 6 * kTurnsPerRound) << "vertex " << v;
}

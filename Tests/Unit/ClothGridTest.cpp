// The cloth's own grid (Cloth/ClothSystem.h): its near bits may stop a
// query early, but only where the query would have found no cloth; and the
// cloth-cloth lists built from it (Cloth/ClothNeighbours.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "Cloth/ClothNeighbours.h"
#include "Cloth/ClothVolume.h"
#include "Neighbours/PairListsState.h"
#include "Neighbours/GridView.h"
#include "Support/TestScenes.h"

using namespace soak;

namespace {

std::vector<int> candidates(const GridView& g, std::uint32_t key) {
  std::vector<int> out;
  forEachCandidate(g, key, [&](int j) { out.push_back(j); });
  return out;
}

std::vector<int> candidatesInBox(const GridView& g, Vec3 lo, Vec3 hi) {
  std::vector<int> out;
  forEachCandidateInBox(g, lo, hi, [&](int j) { out.push_back(j); });
  return out;
}

}  // namespace

TEST(ClothGrid, NearBitsStopOnlyQueriesThatFindNoCloth) {
  // A sheet with a tall block of water over it: the water's upper layers are
  // many cells above the cloth, its lower ones touch it.
  test::TestRegistry reg;
  auto sim = test::makeSimulation(
      "<Scene><Cloth origin='-0.2 0.5 -0.2' width='0.4' height='0.4' cellsU='30' cellsV='30' "
      "pinCorners='u0v0 u1v0 u0v1 u1v1'/><WaterBlock min='-0.1 0.52 -0.1' max='0.1 0.9 0.1'/></Scene>",
      Device::Cpu, reg);
  sim->step();
  const GridView withBits = sim->cloth.grid();
  ASSERT_NE(withBits.nearBits, nullptr);
  GridView withoutBits = withBits;
  withoutBits.nearBits = nullptr;
  const ParticleView p = sim->particles.view();
  int stopped = 0, queries = 0;
  for (int i = 0; i < p.count; ++i) {
    const std::vector<int> full = candidates(withoutBits, withBits.slotKey[i]);
    EXPECT_EQ(candidates(withBits, withBits.slotKey[i]), full) << "slot " << i;
    const std::uint32_t b = bucketOfKey(withBits.slotKey[i], withBits.bucketMask);
    if (!mayHoldNear(withBits, b)) ++stopped;
    ++queries;
  }
  // Boxes of every size up to the 8-cell limit and past it, anywhere around.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> where(-0.3f, 1.0f), size(0.f, 0.5f);
  int boxesStopped = 0;
  const int boxes = 4000;
  for (int k = 0; k < boxes; ++k) {
    const Vec3 lo(where(rng) * 0.5f - 0.1f, where(rng), where(rng) * 0.5f - 0.1f);
    const Vec3 hi = lo + Vec3(size(rng), size(rng), size(rng));
    const std::vector<int> full = candidatesInBox(withoutBits, lo, hi);
    const std::vector<int> pruned = candidatesInBox(withBits, lo, hi);
    EXPECT_EQ(pruned, full) << "box " << k;
    if (pruned.empty() && full.empty()) {
      int a[3] = {cellCoordinate(lo.x, withBits.invCellSize), cellCoordinate(lo.y, withBits.invCellSize),
                  cellCoordinate(lo.z, withBits.invCellSize)};
      int c[3] = {cellCoordinate(hi.x, withBits.invCellSize), cellCoordinate(hi.y, withBits.invCellSize),
                  cellCoordinate(hi.z, withBits.invCellSize)};
      if (!mayHoldInBox(withBits, a, c)) ++boxesStopped;
    }
  }
  std::printf("near bits: %d of %d point queries and %d of %d boxes stopped at once\n", stopped, queries,
              boxesStopped, boxes);
  // The upper water is several cells from the cloth: a good share stops.
  EXPECT_GT(stopped, queries / 4);
  EXPECT_GT(boxesStopped, boxes / 10);
}

TEST(ClothNeighbours, ListsHoldTheGridsPairsInItsOrderAndGiveTheSameVolumes) {
  // A sheet falling onto a sphere and folding: pairs change from step to step.
  test::TestRegistry reg;
  auto sim = test::makeSimulation(
      "<Scene><Cloth origin='-0.2 0.6 -0.2' width='0.4' height='0.4' cellsU='24' cellsV='24'/>"
      "<Sphere center='0 0.3 0' radius='0.1'/></Scene>",
      Device::Cpu, reg);
  for (int s = 0; s < 40; ++s) sim->step();
  const ParticleView p = sim->particles.view();
  const ClothView c = sim->cloth.view();
  const ClothSlots cloth = clothSlots(c);
  const GridView g = sim->cloth.grid();
  ClothNeighbours lists(Device::Cpu);
  lists.build(p, g, cloth, c.thickness, true);
  ASSERT_EQ(lists.itemsWithoutList(), 0);
  // Every item's list: every grid candidate within reach, none much beyond,
  // in the grid's order (a subsequence of the grid's candidates).
  long long listed = 0, candidates = 0;
  for (int v = 0; v < cloth.count; ++v) {
    const int i = cloth.slot[v];
    std::vector<int> fromList, within, order;
    forEachClothNeighbour(lists.view(), v, Lanes{}, [&](int j) { fromList.push_back(j); });
    forEachCandidate(g, g.slotKey[i], [&](int j) {
      ++candidates;
      order.push_back(j);
      const float reach = std::max(0.5f * (p.radius[i] + p.radius[j]), c.thickness[p.id[i]] + c.thickness[p.id[j]]);
      const float r2 = lengthSquared(p.predicted[i].xyz() - p.predicted[j].xyz());
      if (r2 < reach * reach) within.push_back(j);
      const bool isListed = std::find(fromList.begin(), fromList.end(), j) != fromList.end();
      if (isListed) EXPECT_LT(r2, 1.001f * reach * reach) << "cloth particle " << v << " lists " << j;
    });
    std::size_t next = 0;
    for (int j : fromList) {  // grid order kept
      while (next < order.size() && order[next] != j) ++next;
      ASSERT_LT(next, order.size()) << "cloth particle " << v << ": " << j << " out of the grid's order";
      ++next;
    }
    for (int j : within)
      EXPECT_NE(std::find(fromList.begin(), fromList.end(), j), fromList.end()) << "cloth particle " << v << " misses " << j;
    listed += long(fromList.size());
  }
  std::printf("cloth lists: %.1f entries per cloth particle, %.1f grid candidates\n", double(listed) / cloth.count,
              double(candidates) / cloth.count);
  EXPECT_LT(listed * 2, candidates);  // the lists are what saves the passes their work
  // Volumes over the lists (as the porosity update sums them), over the
  // grid, and over lists with no room (every item walks the grid): the
  // same bits.
  const int n = p.count;
  std::vector<float> viaLists(n, -1.f), viaGrid(n, -1.f), viaFallback(n, -1.f);
  const auto listVolumes = [&](std::vector<float>& out) {
    for (int v = 0; v < cloth.count; ++v)
      out[cloth.slot[v]] = clothVolumeOf(p, cloth.slot[v], v, Lanes{}, ClothListWalk{lists.view()});
  };
  listVolumes(viaLists);
  computeClothVolumes(Device::Cpu, p, g, cloth, viaGrid.data());
  lists.setSizing(PairListSizing{});
  lists.build(p, g, cloth, c.thickness, false);
  EXPECT_EQ(lists.itemsWithoutList(), cloth.count);
  listVolumes(viaFallback);
  for (int v = 0; v < cloth.count; ++v) {
    const int i = cloth.slot[v];
    EXPECT_GT(viaGrid[i], 0.f);
    EXPECT_EQ(viaLists[i], viaGrid[i]) << "cloth particle " << v;
    EXPECT_EQ(viaFallback[i], viaGrid[i]) << "cloth particle " << v;
  }
}

TEST(ClothNeighbours, BetweenSizingsListsFillTheirVertexRoomsOrWalkTheGrid) {
  // Keyed lists (Neighbours/PairLists.h): a sizing gives every vertex a
  // room; a build between sizings fills each list into its vertex's room
  // in one pass. Here every other vertex's room is taken away and the spill
  // after the rooms holds 200 entries: the first of those vertices to
  // finish put their lists there, the others get none (and walk the grid),
  // the rest keep the same lists as an exact build, and the volumes come
  // out with the same bits either way.
  test::TestRegistry reg;
  auto sim = test::makeSimulation(
      "<Scene><Cloth origin='-0.2 0.6 -0.2' width='0.4' height='0.4' cellsU='24' cellsV='24' "
      "pinCorners='u0v0 u1v0'/></Scene>",
      Device::Cpu, reg);
  // A sheet swinging down from two corners: its particles cross cells at
  // different times (so the slots' order changes), its pairs hardly change.
  for (int s = 0; s < 10; ++s) sim->step();
  ClothNeighbours lists(Device::Cpu);
  {
    const ClothView c = sim->cloth.view();
    lists.build(sim->particles.view(), sim->cloth.grid(), clothSlots(c), c.thickness, true);
  }
  const PairListSizing sized = lists.sizing();
  std::vector<int> itemOfVertex(sim->cloth.vertexCount());
  {
    const ClothSlots before = clothSlots(sim->cloth.view());
    for (int v = 0; v < before.count; ++v) itemOfVertex[sim->particles.view().id[before.slot[v]]] = v;
  }
  const int vertices = sim->cloth.vertexCount();
  ASSERT_EQ(int(sized.roomStart.size()), vertices + 1);
  EXPECT_EQ(sized.headroomEighths, 1);
  // Rooms as sized, then every even vertex's taken away.
  PairListSizing cut = sized;
  for (int k = 0, at = 0; k < vertices; ++k) {
    const int room = sized.roomStart[k + 1] - sized.roomStart[k];
    EXPECT_GE(room, 2);
    cut.roomStart[k] = at;
    at += k % 2 == 0 ? 0 : room;
    cut.roomStart[k + 1] = at;
  }
  cut.capacity = cut.roomStart[vertices] + 200;
  // The sheet moves on (its slots reordered) before the next build.
  for (int s = 0; s < 3; ++s) sim->step();
  const ParticleView p = sim->particles.view();
  const ClothView c = sim->cloth.view();
  const ClothSlots cloth = clothSlots(c);
  const GridView g = sim->cloth.grid();
  ClothNeighbours exact(Device::Cpu);
  exact.build(p, g, cloth, c.thickness, true);
  const std::vector<std::vector<int>> exactLists = exact.download();
  lists.setSizing(cut);
  lists.build(p, g, cloth, c.thickness, false);
  const std::vector<std::vector<int>> roomLists = lists.download();
  int without = 0, spilled = 0, with = 0, outgrown = 0, moved = 0;
  std::vector<float> viaRooms(p.count, -1.f), viaGrid(p.count, -1.f);
  computeClothVolumes(Device::Cpu, p, g, cloth, viaGrid.data());
  for (int v = 0; v < cloth.count; ++v) {
    const int i = cloth.slot[v];
    const int vertex = p.id[i];
    moved += itemOfVertex[vertex] != v ? 1 : 0;
    if (vertex % 2 == 0 && !exactLists[v].empty()) {
      if (lists.view().lists.listed(v)) {
        EXPECT_EQ(roomLists[v], exactLists[v]) << "vertex " << vertex << " (spilled)";
        EXPECT_GE(lists.view().lists.start[v], cut.roomStart[vertices]);
        ++spilled;
      } else {
        ++without;
      }
    } else if (int(exactLists[v].size()) > cut.roomStart[vertex + 1] - cut.roomStart[vertex]) {
      EXPECT_FALSE(lists.view().lists.listed(v)) << "vertex " << vertex << " outgrew its room but has a list";
      ++outgrown;
    } else {
      EXPECT_TRUE(lists.view().lists.listed(v)) << "vertex " << vertex;
      EXPECT_EQ(roomLists[v], exactLists[v]) << "vertex " << vertex;
      ++with;
    }
    viaRooms[i] = clothVolumeOf(p, i, v, Lanes{}, ClothListWalk{lists.view()});
    EXPECT_EQ(viaRooms[i], viaGrid[i]) << "vertex " << vertex;
  }
  std::printf("keyed lists: of %d vertices %d without a room spilled, %d got no list, %d outgrew theirs, %d "
              "listed in their rooms; %d changed item\n", cloth.count, spilled, without, outgrown, with, moved);
  EXPECT_EQ(lists.itemsWithoutList(), without + outgrown);
  EXPECT_GE(spilled, 1);
  EXPECT_GT(without, cloth.count / 4);
  EXPECT_GT(moved, cloth.count / 10);  // the rooms follow the vertices, not the items
  EXPECT_GT(with, 4 * outgrown);  // a falling sheet keeps its pairs
  // The next sizing lists everyone again, with twice the headroom (items
  // went without a list since the last one).
  lists.build(p, g, cloth, c.thickness, true);
  EXPECT_EQ(lists.itemsWithoutList(), 0);
  EXPECT_EQ(lists.download(), exactLists);
  EXPECT_EQ(lists.sizing().headroomEighths, 2);
}

TEST(ClothNeighbours, CheckpointsKeepTheRoomsAndRefuseRoomsOutOfRange) {
  // Which vertices get a list between sizings depends on their rooms: a
  // resumed run must have the same ones (Neighbours/PairListsState.h).
  PairListSizing s;
  s.capacity = 40;
  s.headroomEighths = 2;
  s.overflowed = true;
  s.roomStart = {0, 5, 5, 17, 30};
  const auto roundTrip = [](const PairListSizing& in) {
    StateWriter out;
    putListSizing(out, in);
    StateReader reader(out.bytes().data(), out.bytes().size(), "test");
    return getListSizing(reader, "cloth neighbour list", 1000.0);
  };
  const PairListSizing back = roundTrip(s);
  EXPECT_EQ(back.capacity, 40);
  EXPECT_EQ(back.headroomEighths, 2);
  EXPECT_TRUE(back.overflowed);
  EXPECT_EQ(back.roomStart, s.roomStart);
  PairListSizing shrinking = s;
  shrinking.roomStart = {0, 5, 4, 17, 30};
  EXPECT_THROW(roundTrip(shrinking), std::exception);
  PairListSizing pastBuffer = s;
  pastBuffer.roomStart = {0, 5, 5, 17, 41};
  EXPECT_THROW(roundTrip(pastBuffer), std::exception);
  PairListSizing unkeyed = s;
  unkeyed.roomStart.clear();
  EXPECT_TRUE(roundTrip(unkeyed).roomStart.empty());
  // A capacity past what the lists can need (a forged file) is refused.
  PairListSizing huge = unkeyed;
  huge.capacity = 2000000000;
  EXPECT_THROW(roundTrip(huge), std::exception);
}

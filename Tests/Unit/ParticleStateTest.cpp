#include <gtest/gtest.h>

#include "Particles/ParticleState.h"

using namespace soak;

namespace {
std::vector<ParticleInit> line(int n, int firstId) {
  std::vector<ParticleInit> v(n);
  for (int i = 0; i < n; ++i) {
    v[i].position = Vec3(float(i), 0.f, 0.f);
    v[i].mass = 0.5f;
    v[i].radius = 0.04f;
    v[i].id = firstId + i;
  }
  return v;
}
}  // namespace

TEST(ParticleState, AppendSetsInverseMassAndPins) {
  ParticleState ps(Device::Cpu);
  auto init = line(3, 0);
  init[1].pinned = true;
  ps.append(init);
  auto pos = ps.downloadPositions();
  EXPECT_FLOAT_EQ(pos[0].w, 2.f);
  EXPECT_EQ(pos[1].w, 0.f);
  EXPECT_EQ(ps.downloadMasses()[1], 0.5f);  // a pinned particle keeps its mass
}

TEST(ParticleState, RemoveKeepsOrderAndChannelsFollow) {
  ParticleState ps(Device::Cpu);
  ps.append(line(10, 100));
  int ch = ps.addChannel("held_water");
  float* held = ps.channel(ch);
  for (int i = 0; i < 10; ++i) held[i] = float(i) * 10.f;
  std::vector<int> remove = {1, 0, 0, 1, 0, 0, 0, 0, 1, 1};
  EXPECT_EQ(ps.removeFlagged(remove.data()), 4);
  EXPECT_EQ(ps.count(), 6);
  EXPECT_EQ(ps.downloadIds(), (std::vector<int>{101, 102, 104, 105, 106, 107}));
  EXPECT_EQ(ps.downloadChannel(ch), (std::vector<float>{10.f, 20.f, 40.f, 50.f, 60.f, 70.f}));
  // Particles can be added after removal and have zeroed channels.
  ps.append(line(2, 200));
  EXPECT_EQ(ps.count(), 8);
  EXPECT_EQ(ps.downloadChannel(ch)[7], 0.f);
  EXPECT_EQ(ps.downloadIds()[7], 201);
}

TEST(ParticleState, GrowsPastCapacity) {
  ParticleState ps(Device::Cpu);
  ps.reserve(4);
  for (int k = 0; k < 10; ++k) ps.append(line(3, 3 * k));
  EXPECT_EQ(ps.count(), 30);
  auto ids = ps.downloadIds();
  for (int i = 0; i < 30; ++i) EXPECT_EQ(ids[i], i);
}

TEST(ParticleState, GatherPermutesEveryArray) {
  ParticleState ps(Device::Cpu);
  ps.append(line(4, 0));
  int ch = ps.addChannel("x");
  for (int i = 0; i < 4; ++i) ps.channel(ch)[i] = float(i);
  std::vector<std::uint32_t> order = {3, 1, 0, 2};
  ps.gather(order.data());
  EXPECT_EQ(ps.downloadIds(), (std::vector<int>{3, 1, 0, 2}));
  EXPECT_EQ(ps.downloadChannel(ch), (std::vector<float>{3.f, 1.f, 0.f, 2.f}));
  EXPECT_EQ(ps.downloadPositions()[0].x, 3.f);
}

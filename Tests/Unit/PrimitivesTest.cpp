#include <gtest/gtest.h>

#include <numeric>
#include <random>

#include "Backend/Buffer.h"
#include "Backend/ForEach.h"
#include "Backend/Primitives.h"

using namespace soak;

TEST(Primitives, ReduceSumIsExactForIntegersAndIndependentOfOrder) {
  std::vector<float> v(100003);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = float(i % 17);
  double expected = 0;
  for (float x : v) expected += x;
  EXPECT_EQ(reduceSum(Device::Cpu, v.data(), int(v.size())), expected);
  EXPECT_EQ(reduceMax(Device::Cpu, v.data(), int(v.size())), 16.f);
  EXPECT_EQ(reduceMin(Device::Cpu, v.data(), int(v.size())), 0.f);
  EXPECT_EQ(reduceSum(Device::Cpu, v.data(), 0), 0.0);
}

TEST(Primitives, ExclusiveScan) {
  std::vector<int> in = {3, 0, 2, 5, 1}, out(5);
  EXPECT_EQ(exclusiveScan(Device::Cpu, in.data(), out.data(), 5), 11);
  EXPECT_EQ(out, (std::vector<int>{0, 3, 3, 5, 10}));
}

TEST(Primitives, SortPairsIsStable) {
  std::mt19937 rng(3);
  std::vector<std::uint32_t> keys(5000), values(5000);
  for (std::uint32_t i = 0; i < keys.size(); ++i) {
    keys[i] = rng() % 37;
    values[i] = i;
  }
  sortPairs(Device::Cpu, keys.data(), values.data(), int(keys.size()), 8);
  for (std::size_t i = 1; i < keys.size(); ++i) {
    ASSERT_LE(keys[i - 1], keys[i]);
    if (keys[i - 1] == keys[i]) ASSERT_LT(values[i - 1], values[i]);
  }
}

TEST(Primitives, BufferGrowsAndKeepsContents) {
  Buffer<int> b(Device::Cpu);
  b.upload({1, 2, 3});
  b.reserve(100);
  EXPECT_EQ(b.download(), (std::vector<int>{1, 2, 3}));
  EXPECT_GE(deviceBytesInUse(Device::Cpu), 100 * sizeof(int));
}

// How many GPU threads share a particle's neighbour loop (ForEach.h).
TEST(Lanes, GroupWidthFillsTheGpuAndRespectsTheMinimum) {
  EXPECT_EQ(lanesFor(2500), 16);       // fig7's cloth: 16 lanes
  EXPECT_EQ(lanesFor(98000), 16);      // fig9b's particles
  EXPECT_EQ(lanesFor(250000), 4);      // the 1M scale scene's cloth
  EXPECT_EQ(lanesFor(1 << 20), 1);     // enough threads without sharing
  EXPECT_EQ(lanesFor(10000000, 4), 4); // a minimum is kept
  EXPECT_EQ(lanesFor(100, 32), 32);    // and may exceed 16
  // A pass may aim at fewer threads (the fluid's list passes: 400k).
  EXPECT_EQ(lanesFor(98000, 4, 400000), 8);   // fig9b's particles
  EXPECT_EQ(lanesFor(60400, 4, 400000), 8);   // fig5b's
  EXPECT_EQ(lanesFor(100200, 4, 400000), 4);  // the 100k scale scene's
  EXPECT_EQ(lanesFor(16500, 4, 400000), 16);  // fig1's
  EXPECT_EQ(lanesFor(1 << 20, 4, 400000), 4);
}

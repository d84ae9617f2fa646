#include "Support/NeighbourChecks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "Neighbours/NeighbourGrid.h"

namespace soak::test {

std::vector<PointCase> neighbourCases() {
  std::vector<PointCase> cases;
  std::mt19937 rng(1234);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  {
    PointCase c{"uniform", {}, {}};
    for (int i = 0; i < 4000; ++i) c.points.push_back(Vec3(u(rng) * 0.4f, u(rng) * 0.4f, u(rng) * 0.4f));
    c.radii.assign(c.points.size(), 0.04f);
    cases.push_back(c);
  }
  {
    PointCase c{"clustered", {}, {}};
    std::normal_distribution<float> g(0.f, 0.01f);
    for (int k = 0; k < 5; ++k) {
      Vec3 centre(u(rng), u(rng), u(rng));
      for (int i = 0; i < 700; ++i) c.points.push_back(centre + Vec3(g(rng), g(rng), g(rng)));
    }
    c.radii.assign(c.points.size(), 0.02f);
    cases.push_back(c);
  }
  {
    PointCase c{"duplicates", {}, {}};
    for (int i = 0; i < 300; ++i) {
      Vec3 p(u(rng) * 0.2f, u(rng) * 0.2f, u(rng) * 0.2f);
      for (int k = 0; k < 4; ++k) c.points.push_back(p);
    }
    c.radii.assign(c.points.size(), 0.03f);
    cases.push_back(c);
  }
  {
    PointCase c{"far_outliers", {}, {}};
    for (int i = 0; i < 2000; ++i) c.points.push_back(Vec3(u(rng) * 0.3f, u(rng) * 0.3f, u(rng) * 0.3f));
    // Far away points (huge domain extent), some of them close to each other,
    // and points exactly 1024 cells apart (the key wrap) that must not be neighbours.
    c.points.push_back(Vec3(1.0e6f, -2.0e6f, 3.0e5f));
    c.points.push_back(Vec3(1.0e6f + 0.01f, -2.0e6f, 3.0e5f));
    c.points.push_back(Vec3(-7.5e7f, 4.0e7f, 1.0e8f));
    c.points.push_back(Vec3(0.1f + 1024 * 0.04f, 0.1f, 0.1f));
    c.points.push_back(Vec3(0.1f, 0.1f + 2048 * 0.04f, 0.1f - 1024 * 0.04f));
    c.radii.assign(c.points.size(), 0.04f);
    cases.push_back(c);
  }
  {
    PointCase c{"variable_radii", {}, {}};
    for (int i = 0; i < 3000; ++i) {
      c.points.push_back(Vec3(u(rng) * 0.4f, u(rng) * 0.4f, u(rng) * 0.4f));
      c.radii.push_back(0.01f + 0.03f * u(rng));
    }
    cases.push_back(c);
  }
  cases.push_back(PointCase{"empty", {}, {}});
  cases.push_back(PointCase{"one_point", {Vec3(0.3f, -0.2f, 0.1f)}, {0.04f}});
  return cases;
}

void expectNeighboursMatchBruteForce(Device device, const PointCase& c) {
  SCOPED_TRACE(c.name + " on " + deviceName(device));
  const int n = static_cast<int>(c.points.size());
  std::vector<ParticleInit> init(n);
  float maxR = 0.f;
  for (int i = 0; i < n; ++i) {
    init[i].position = c.points[i];
    init[i].radius = c.radii[i];
    init[i].mass = 1.f;
    init[i].id = i;
    maxR = std::max(maxR, c.radii[i]);
  }
  ParticleState ps(device);
  ps.append(init);
  NeighbourGrid grid(device);
  grid.build(ps, maxR > 0.f ? maxR : 0.04f);
  ASSERT_EQ(ps.count(), n);

  // The arrays were reordered together: ids are a permutation and each slot's
  // position is the one its id had.
  std::vector<int> ids = ps.downloadIds();
  std::vector<Float4> pos = ps.downloadPositions();
  std::vector<float> radius = ps.downloadRadii();
  std::vector<int> seen(n, 0);
  for (int s = 0; s < n; ++s) {
    ASSERT_GE(ids[s], 0);
    ASSERT_LT(ids[s], n);
    ++seen[ids[s]];
    EXPECT_EQ(pos[s].x, c.points[ids[s]].x);
    EXPECT_EQ(radius[s], c.radii[ids[s]]);
  }
  for (int i = 0; i < n; ++i) EXPECT_EQ(seen[i], 1);

  // Neighbour counts from the grid against brute force.
  Buffer<int> counts(device, n);
  countNeighbours(device, grid.view(), ps.view(), counts.data());
  std::vector<int> got = counts.download();
  long long expectedPairs = 0;
  for (int s = 0; s < n; ++s) {
    int expected = 0;
    for (int t = 0; t < n; ++t) {
      if (t == s) continue;
      Vec3 d = pos[s].xyz() - pos[t].xyz();
      float r = std::max(radius[s], radius[t]);
      if (lengthSquared(d) < r * r) ++expected;
    }
    expectedPairs += expected;
    if (got[s] != expected) {
      ADD_FAILURE() << "particle id " << ids[s] << ": grid found " << got[s] << " neighbours, brute force "
                    << expected;
      return;
    }
  }
  if (c.name == "uniform") EXPECT_GT(expectedPairs, n);  // the case is not trivially empty
}

}  // namespace soak::test

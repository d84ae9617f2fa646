// Stretch limits on triangle meshes (Cloth/StretchLimits.h, Doc/model.md,
// "Stretch limits"): built along the mesh's lines of edges with the
// lines' rest lengths, they never resist an isometric motion (unfolding a
// creased mesh, folding a flat one onto itself) and only pull when
// stretched; on an irregular sheet they carry its stiffness across it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "Cloth/ClothJacobi.h"
#include "Cloth/StretchLimits.h"
#include "Support/JitteredSheet.h"
#include "Support/TempFiles.h"
#include "Support/TestScenes.h"

using namespace soak;

namespace {

// The largest |x_a - x_b| / rest - 1 over the limits, and the share of
// limits longer than their rest length, in configuration x.
struct LimitSlack {
  double worstExcess = -1.0, activeShare = 0.0;
};
LimitSlack slack(const std::vector<StretchLimit>& limits, const std::vector<Vec3>& x) {
  LimitSlack s;
  int active = 0;
  for (const StretchLimit& l : limits) {
    const double excess = double(length(x[l.a] - x[l.b])) / double(l.rest) - 1.0;
    s.worstExcess = std::max(s.worstExcess, excess);
    if (excess > 1e-6) ++active;
  }
  s.activeShare = limits.empty() ? 0.0 : double(active) / double(limits.size());
  return s;
}

// A 32 x 32 jittered sheet (0.8 m) whose middle column lies on x = 0, so
// that rotating its x > 0 half about the line x = 0, y = 1 moves every
// triangle rigidly: an isometry.
TriangleMesh creasableSheet() {
  TriangleMesh m = test::jitteredSheet(32, 0.8f, 0.3f, 1.f, 7);
  for (int j = 0; j <= 32; ++j) m.vertices[std::size_t(j * 33 + 16)].x = 0.f;
  return m;
}
// The sheet with its x > 0 half turned by `angle` (radians) about the line x = 0, y = 1.
std::vector<Vec3> creased(const std::vector<Vec3>& flat, float angle) {
  std::vector<Vec3> x = flat;
  for (Vec3& p : x)
    if (p.x > 0.f) p = Vec3(p.x * std::cos(angle), 1.f + p.x * std::sin(angle), p.z);
  return x;
}

}  // namespace

TEST(MeshStretchLimits, LinesCrossAnIrregularSheetAndTheirLimitsBoundTheRestDistance) {
  const TriangleMesh m = test::jitteredSheet(40, 1.2f, 0.3f, 1.f, 3);
  const ClothTopology topo = buildClothTopology(m);
  const std::vector<StretchLimit> limits = meshStretchLimits(m.vertices, topo);
  double ratioSum = 0.0, longest = 0.0;
  for (const StretchLimit& l : limits) {
    const double straight = double(length(m.vertices[l.a] - m.vertices[l.b]));
    // The path is a curve on the flat sheet: never shorter than the straight line.
    ASSERT_GE(double(l.rest), straight * (1.0 - 1e-6));
    ratioSum += double(l.rest) / straight;
    longest = std::max(longest, straight);
  }
  const double perVertex = double(limits.size()) / double(m.vertices.size());
  std::printf("jittered 40 x 40 sheet (1.2 m): %.1f limits per vertex, rest over straight distance %.4f on "
              "average, longest limit %.2f m\n",
              perVertex, ratioSum / double(limits.size()), longest);
  // Lines reach across the sheet (spans of 16 and 32 edges, about 0.5-1 m)
  // and are nearly straight (their slack is what the solve cannot use).
  EXPECT_GT(longest, 0.8);
  EXPECT_LT(ratioSum / double(limits.size()), 1.03);
  EXPECT_GT(perVertex, 6.0);
  EXPECT_LT(perVertex, 60.0);
}

TEST(MeshStretchLimits, NeverResistUnfoldingOrFoldingOnlyStretch) {
  const TriangleMesh flat = creasableSheet();
  // Built on the mesh creased at 90 degrees (a rest shape a garment has).
  TriangleMesh rest = flat;
  rest.vertices = creased(flat.vertices, 1.5707963f);
  const std::vector<StretchLimit> limits = meshStretchLimits(rest.vertices, buildClothTopology(rest));
  const LimitSlack atRest = slack(limits, rest.vertices);
  const LimitSlack unfolded = slack(limits, flat.vertices);                  // opened flat
  const LimitSlack folded = slack(limits, creased(flat.vertices, 3.1f));      // folded onto itself
  std::vector<Vec3> stretched = flat.vertices;
  for (Vec3& p : stretched) p.z *= 1.02f;  // 2 % along z, across the crease's lines too
  const LimitSlack pulled = slack(limits, stretched);
  std::printf("creased jittered sheet: limits longer than rest: %.4f %% at rest, %.2e unfolded flat, %.2e folded "
              "onto itself, %.1f %% of them when stretched 2 %% (worst %.2f %%)\n",
              100 * atRest.worstExcess, unfolded.worstExcess, folded.worstExcess, 100 * pulled.activeShare,
              100 * pulled.worstExcess);
  EXPECT_LE(unfolded.worstExcess, 1e-5);
  EXPECT_LE(folded.worstExcess, 1e-5);
  // Straight-line rest lengths would be stretched by unfolding: across the
  // crease the flat distance is up to sqrt(2) times the creased one.
  EXPECT_GT(pulled.activeShare, 0.3);
  EXPECT_GT(pulled.worstExcess, 0.01);
}

TEST(MeshStretchLimits, ALimitOnlyPulls) {
  // The solve's term for a unilateral spring (ClothJacobi.h): nothing at or
  // under its rest length, a pull back to it when longer.
  JacobiSums s;
  addStretchTerm(s, Vec3(0.5f, 0.f, 0.f), Vec3(0.f, 0.f, 0.f), 1.f, kStiffest, true);
  addStretchTerm(s, Vec3(1.f, 0.f, 0.f), Vec3(0.f, 0.f, 0.f), 1.f, kStiffest, true);
  EXPECT_EQ(s.weight, 0.f);
  addStretchTerm(s, Vec3(1.5f, 0.f, 0.f), Vec3(0.f, 0.f, 0.f), 1.f, kStiffest, true);
  EXPECT_EQ(s.weight, kStiffest);
  EXPECT_NEAR(s.weighted.x / s.weight, 1.f, 1e-6f);
}

namespace {
struct MeshSwing {
  double worstMean = 0.0, worstP99 = 0.0;
};
// The jittered 40 x 40 sheet (1.2 m) as an OBJ, held horizontally by two
// corners and let go: it swings down and hangs. Strain of all its edges
// every 1/30 s.
MeshSwing swingJitteredSheet(bool limits, double seconds, const std::vector<std::string>& overrides) {
  const std::string obj = test::processTempPath("jittered_sheet.obj");
  test::writeObjFile(test::jitteredSheet(40, 1.2f, 0.3f, 1.5f, 3), obj);
  test::TestRegistry reg;
  auto sim = test::makeSimulation("<Scene><Cloth mesh='" + obj + "' pin='0 40' stretchLimits='" +
                                      (limits ? "true" : "false") + "'/></Scene>",
                                  Device::Cpu, reg, overrides);
  MeshSwing r;
  const int steps = int(std::lround(seconds / sim->settings.timeStep));
  for (int s = 1; s <= steps; ++s) {
    sim->step();
    if (s % 2 != 0) continue;
    const StatsRow row = sim->collectStats();
    r.worstMean = std::max(r.worstMean, row.get("strain_mean_cloth"));
    r.worstP99 = std::max(r.worstP99, row.get("strain_p99_cloth"));
  }
  return r;
}
}  // namespace

TEST(MeshStretchLimits, CarryAnIrregularSheetsStiffnessAcrossIt) {
  // At a fixed 1 sub-step of 30 iterations (no counts chosen from the
  // strain, which would hide the difference in the cost), the iterations
  // leave the long modes of the swinging sheet stretched without the
  // limits; with them it holds its shape.
  const std::vector<std::string> fixed = {"Simulation.clothSubsteps=1", "Simulation.clothIterations=30",
                                          "Simulation.clothSubstepTravel=0"};
  const MeshSwing with = swingJitteredSheet(true, 1.0, fixed), without = swingJitteredSheet(false, 1.0, fixed);
  std::printf("jittered 40 x 40 OBJ sheet swinging from two corners, 1 s, chebyshev 1 x 30: worst strain mean "
              "%.2f %% p99 %.2f %% with the limits, mean %.2f %% p99 %.2f %% without\n",
              100 * with.worstMean, 100 * with.worstP99, 100 * without.worstMean, 100 * without.worstP99);
  EXPECT_LT(with.worstP99, 0.5 * without.worstP99);
  EXPECT_LT(with.worstMean, 0.5 * without.worstMean);
}

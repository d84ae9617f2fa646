// The cloth solvers (Doc/model.md, "Cloth solvers"): the chebyshev solve
// holds a swinging sheet to a few percent of stretch where the paper's PBD,
// given more dependent phases, does not; the strain statistics of stats.csv
// measure what they say.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "Pipeline/StageNames.h"
#include "Support/TestScenes.h"

using namespace soak;

namespace {

struct SwingResult {
  double worstMean = 0.0, worstP99 = 0.0;  // largest per-frame mean and 99th percentile over the run
  int phases = 0;  // dependent constraint phases per step
};

// A 40 x 40 sheet (1.2 m) held horizontally by two corners, let go: it
// swings down and hangs. Strain every 1/30 s.
SwingResult swing(const std::string& model, int iterations, int substeps, double seconds) {
  test::TestRegistry reg;
  auto sim = test::makeSimulation(
      "<Scene><Simulation clothIterations='" + std::to_string(iterations) + "' clothSubsteps='" +
          std::to_string(substeps) + "' clothSpectralRadius='0.9'/><Cloth model='" + model +
          "' origin='-0.6 1.5 0' axisU='1 0 0' axisV='0 0 1' width='1.2' height='1.2' cellsU='39' cellsV='39' "
          "pinCorners='u0v0 u1v0'/></Scene>",
      Device::Cpu, reg);
  SwingResult r;
  r.phases = sim->cloth.constraintPhasesPerStep(iterations, substeps);
  const int steps = int(std::lround(seconds / sim->settings.timeStep));
  for (int s = 1; s <= steps; ++s) {
    sim->step();
    if (s % 2 != 0) continue;
    const StatsRow row = sim->collectStats();
    r.worstMean = std::max(r.worstMean, row.get("strain_mean_cloth"));
    r.worstP99 = std::max(r.worstP99, row.get("strain_p99_cloth"));
    EXPECT_TRUE(std::isfinite(row.get("kinetic_energy"))) << "step " << s;
  }
  return r;
}

}  // namespace

TEST(ClothSolvers, ChebyshevHoldsASwingingSheetWherePbdWithMorePhasesStretches) {
  const SwingResult cheb = swing("chebyshev", 50, 2, 2.0);
  const SwingResult pbd = swing("pbd", 8, 1, 2.0);
  std::printf("swinging 40 x 40 sheet, 2 s: chebyshev 2 x 50 (%d phases/step) strain mean %.3f %% p99 %.2f %%; "
              "pbd 1 x 8 (%d phases/step) mean %.3f %% p99 %.2f %%\n",
              cheb.phases, 100 * cheb.worstMean, 100 * cheb.worstP99, pbd.phases, 100 * pbd.worstMean,
              100 * pbd.worstP99);
  // Measured: chebyshev 0.11 % / 0.46 % at 102 phases; pbd 4.7 % / 27 % at 216.
  EXPECT_LE(cheb.phases, 102);
  EXPECT_GT(pbd.phases, 2 * cheb.phases);
  EXPECT_LT(cheb.worstMean, 0.01);
  EXPECT_LT(cheb.worstP99, 0.03);
  EXPECT_GT(pbd.worstP99, 4 * cheb.worstP99);
}

TEST(ClothSolvers, StretchLimitsCarryTheSheetsStiffnessAcrossIt) {
  // The same solve without the multi-scale stretch limits leaves a long
  // sheet stretched: its low modes need more iterations than a step has.
  test::TestRegistry reg;
  auto worstP99 = [&](bool limits) {
    auto sim = test::makeSimulation(
        "<Scene><Simulation clothIterations='30' clothSpectralRadius='0.9'/><Cloth model='chebyshev' "
        "stretchLimits='" + std::string(limits ? "true" : "false") +
            "' origin='-0.6 1.5 0' axisU='1 0 0' axisV='0 0 1' width='1.2' height='1.2' cellsU='39' cellsV='39' "
            "pinCorners='u0v0 u1v0'/></Scene>",
        Device::Cpu, reg);
    double worst = 0.0;
    for (int s = 0; s < 60; ++s) {
      sim->step();
      worst = std::max(worst, sim->collectStats().get("strain_p99_cloth"));
    }
    return worst;
  };
  const double with = worstP99(true), without = worstP99(false);
  std::printf("swinging sheet, 1 x 30 iterations, 0.9 s: strain p99 %.2f %% with the limits, %.2f %% without\n",
              100 * with, 100 * without);
  EXPECT_LT(with, 0.5 * without);
}

namespace {
// ClothSystem::strain of a 10 x 10-cell sheet (1 m) with its rest positions
// scaled by `u` along its first axis and `v` along its second.
ClothStrain strainOfScaledSheet(float u, float v) {
  test::TestRegistry reg;
  auto sim = test::makeSimulation(
      "<Scene><Cloth name='s' origin='0 1 0' axisU='1 0 0' axisV='0 0 1' width='1' height='1' cellsU='10' "
      "cellsV='10'/></Scene>",
      Device::Cpu, reg);
  std::vector<Float4> pos = sim->particles.downloadPositions();
  for (Float4& p : pos) {
    p.x *= u;
    p.z *= v;
  }
  const std::vector<ClothStrain> s =
      sim->cloth.strain(pos, sim->cloth.vertexSlots(sim->particles.downloadIds(), sim->particles.downloadPhases()));
  EXPECT_EQ(s.size(), 1u);
  return s.empty() ? ClothStrain{} : s[0];
}
}  // namespace

TEST(ClothStrain, WarpAndWeftEdgesOfASheetStretchedAlongOneAxis) {
  // A 10 x 10-cell sheet stretched by 2 % along its first axis: its warp
  // edges (along u) are 2 % long, its weft edges unchanged; the diagonals,
  // not counted on a sheet, would add their own 1 %.
  const ClothStrain s = strainOfScaledSheet(1.02f, 1.f);
  EXPECT_NEAR(s.mean, 0.01, 1e-5);  // 110 warp edges at 2 %, 110 weft edges at 0
  EXPECT_NEAR(s.p99, 0.02, 1e-5);
  EXPECT_NEAR(s.max, 0.02, 1e-5);
  EXPECT_NEAR(s.stretchP99, 0.02, 1e-5);
  EXPECT_NEAR(s.compressionP99, 0.0, 1e-7);
}

TEST(ClothStrain, StretchAndCompressionAreCountedApart) {
  // The same sheet 3 % longer along u and 1 % shorter along v: |strain|
  // puts both sides together, stretch and compression each see their own
  // side of the edges.
  const ClothStrain s = strainOfScaledSheet(1.03f, 0.99f);
  EXPECT_NEAR(s.mean, 0.02, 1e-5);  // 110 edges at 3 %, 110 at 1 %
  EXPECT_NEAR(s.p99, 0.03, 1e-5);
  EXPECT_NEAR(s.stretchP99, 0.03, 1e-5);
  EXPECT_NEAR(s.stretchMean, 0.015, 1e-5);
  EXPECT_NEAR(s.compressionP99, 0.01, 1e-5);
  // Compressed the other way round: the sides swap.
  const ClothStrain t = strainOfScaledSheet(1.f / 1.03f, 1.f / 0.99f);
  EXPECT_NEAR(t.stretchP99, 1.0 / 0.99 - 1.0, 1e-5);
  EXPECT_NEAR(t.compressionP99, 1.0 - 1.0 / 1.03, 1e-5);
}

namespace {
// A 40 x 40 sheet (1.2 m) hung from two corners of one diagonal and let
// go: it falls, swings and hangs. Returns the kinetic energy of the last
// frame over its peak, and the largest per-frame 99th-percentile strain.
struct Settling {
  double finalOverPeak = 0.0, worstP99 = 0.0;
};
Settling hangFromTwoCorners(double rho, int delay, double seconds) {
  test::TestRegistry reg;
  auto sim = test::makeSimulation(
      "<Scene><Simulation clothSubsteps='8' clothIterations='12' clothSpectralRadius='" + std::to_string(rho) +
          "' clothChebyshevDelay='" + std::to_string(delay) + "'/><Cloth model='chebyshev' origin='-0.6 1.9 0' axisU='1 0 0' axisV='0 -1 0' width='1.2' height='1.2' "
          "cellsU='39' cellsV='39' pinCorners='u0v0 u1v1'/></Scene>",
      Device::Cpu, reg);
  Settling r;
  double peak = 0.0, last = 0.0;
  const int steps = int(std::lround(seconds / sim->settings.timeStep));
  for (int s = 1; s <= steps; ++s) {
    sim->step();
    if (s % 2 != 0) continue;
    const StatsRow row = sim->collectStats();
    last = row.get("kinetic_energy");
    peak = std::max(peak, last);
    r.worstP99 = std::max(r.worstP99, row.get("strain_p99_cloth"));
  }
  r.finalOverPeak = peak > 0.0 ? last / peak : 1.0;
  return r;
}
}  // namespace

TEST(ClothSolvers, ChebyshevHangingSheetComesToRestWithTheWeightsDelayed) {
  // At the default rho (0.95) with the weights delayed two iterations the
  // implicit-Euler solve's own damping brings the sheet to rest (measured
  // 2.6e-6 of the peak). Extrapolated from the first iteration, the moves
  // onto the tethers and stretch limits come back as motion and the sheet
  // keeps moving (about 7e-2); rho 0.6 comes to rest without the delay but
  // leaves more strain.
  const SimulationSettings defaults;
  const Settling settled = hangFromTwoCorners(defaults.clothSpectralRadius, defaults.clothChebyshevDelay, 4.0);
  const Settling undelayed = hangFromTwoCorners(defaults.clothSpectralRadius, 0, 4.0);
  const Settling slow = hangFromTwoCorners(0.6, 0, 4.0);
  std::printf("sheet hung from two corners, 4 s: kinetic energy / peak %.2e at rho %.2f delayed %d (strain p99 "
              "%.2f %%), %.2e undelayed; at rho 0.6 %.2e (strain p99 %.2f %%)\n",
              settled.finalOverPeak, double(defaults.clothSpectralRadius), defaults.clothChebyshevDelay,
              100 * settled.worstP99, undelayed.finalOverPeak, slow.finalOverPeak, 100 * slow.worstP99);
  EXPECT_LT(settled.finalOverPeak, 1e-4);
  EXPECT_GT(undelayed.finalOverPeak, 100 * settled.finalOverPeak);
  EXPECT_LT(settled.worstP99, 0.03);
  EXPECT_LT(settled.worstP99, slow.worstP99);
}

TEST(ClothSolvers, ChebyshevSheetLandingOnABallStretchesLittle) {
  // Scenes/small/fig9b_ball_sticky.xml without its water: a 40 x 40 sheet
  // (0.6 m) dropped 3 cm onto a 0.11 m ball, 8 sub-steps x 12. Its borders
  // swing down and under the ball at 0.25-0.35 s, the worst frames. The
  // contacts around the solve (particle contact before it, the colliders
  // as terms of its energy; Doc/design.md) keep that to a few percent;
  // with the layers pushed apart and the ball projected only after the
  // solve, p99 was 13.3 %.
  test::TestRegistry reg;
  auto sim = test::makeSimulation(
      "<Scene><Simulation clothIterations='12' clothSubsteps='8'/>"
      "<Sphere name='ball' center='0 0.31 0' radius='0.11' friction='0.4'/>"
      "<Cloth name='sheet' model='chebyshev' origin='-0.3 0.45 -0.3' width='0.6' height='0.6' cellsU='39' "
      "cellsV='39'/></Scene>",
      Device::Cpu, reg);
  double worstMean = 0.0, worstP99 = 0.0;
  const int steps = int(std::lround(0.45 / sim->settings.timeStep));
  for (int s = 1; s <= steps; ++s) {
    sim->step();
    const StatsRow row = sim->collectStats();
    worstMean = std::max(worstMean, row.get("strain_mean_sheet"));
    worstP99 = std::max(worstP99, row.get("strain_p99_sheet"));
  }
  std::printf("sheet landing on a ball, 0.45 s: worst per-step strain mean %.2f %%, p99 %.2f %%\n", 100 * worstMean,
              100 * worstP99);
  EXPECT_LT(worstP99, 0.08);
  EXPECT_LT(worstMean, 0.015);
}

namespace {
// Scenes/fig7_small.xml (a 50 x 50 sheet, 0.8 m, pinned at its four corners;
// a block of water lands on it at about 0.15 s) for 1.2 s with the given
// overrides: the largest per-frame mean and 99th-percentile warp and weft
// strain, and how far the sheet's lowest vertex hangs below its pins at the
// end.
struct PinnedSheet {
  double worstMean = 0.0, worstP99 = 0.0;
  double worstStretchP99 = 0.0, worstCompressionP99 = 0.0;  // each side apart (ClothStrain)
  float sag = 0.f;
};
PinnedSheet waterOnPinnedSheet(const std::vector<std::string>& overrides) {
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  std::ifstream in(std::string(SOAK_SOURCE_DIR) + "/Scenes/fig7_small.xml");
  const std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto sim = test::makeSimulation(xml, Device::Cpu, reg, overrides);
  PinnedSheet r;
  const int steps = int(std::lround(1.2 / sim->settings.timeStep));
  for (int s = 1; s <= steps; ++s) {
    sim->step();
    if (s % 2 != 0) continue;
    const StatsRow row = sim->collectStats();
    r.worstMean = std::max(r.worstMean, row.get("strain_mean_sheet"));
    r.worstP99 = std::max(r.worstP99, row.get("strain_p99_sheet"));
    r.worstStretchP99 = std::max(r.worstStretchP99, row.get("stretch_p99_sheet"));
    r.worstCompressionP99 = std::max(r.worstCompressionP99, row.get("compression_p99_sheet"));
  }
  const std::vector<Float4> x = sim->particles.downloadPositions();
  float lowest = 1e9f;
  for (int slot : sim->cloth.vertexSlots(sim->particles.downloadIds(), sim->particles.downloadPhases()))
    if (slot >= 0) lowest = std::min(lowest, x[std::size_t(slot)].y);
  r.sag = 0.5f - lowest;  // the pins are at y = 0.5
  return r;
}
}  // namespace

TEST(ClothSolvers, SheetPinnedAtFourCornersCarriesWaterWithinItsTetherSlack) {
  // The scene as it is (chebyshev 2 x 25, more sub-steps while the block
  // lands, tethers with 2 % slack) against the paper's PBD 1 x 8 with 10 %
  // slack. A flat sheet bent into a bowl must stretch; the tethers bound how
  // much, and the solve must hold the sheet there while the block lands.
  // Measured (CPU): 4.0 % p99, 0.92 % mean and 11 cm of sag against 46 %,
  // 15.7 % and 25 cm (Doc/design.md, "Cloth solver"). The chebyshev sheet's
  // p99 is its compressed edges (4.0 %), where it wrinkles along the pulls
  // to its corners; its stretch p99 is 2.5 %, the tethers' 2 % slack and a
  // few tenths. PBD's is stretch (46 %).
  const PinnedSheet scene = waterOnPinnedSheet({});
  const PinnedSheet paper = waterOnPinnedSheet(
      {"Cloth.model=pbd", "Simulation.clothSubsteps=1", "Simulation.clothIterations=8",
       "Simulation.clothSubstepTravel=0", "Cloth.tetherSlack=0.1"});
  std::printf("water on a sheet pinned at four corners, 1.2 s: chebyshev 2 x 25 (travel 0.5), 2 %% slack: strain mean %.2f %% "
              "p99 %.2f %%, sag %.3f m; pbd 1 x 8, 10 %% slack: mean %.2f %% p99 %.2f %%, sag %.3f m\n",
              100 * scene.worstMean, 100 * scene.worstP99, scene.sag, 100 * paper.worstMean, 100 * paper.worstP99,
              paper.sag);
  std::printf("  each side apart: chebyshev stretch p99 %.2f %%, compression p99 %.2f %%; pbd stretch p99 %.2f %%\n",
              100 * scene.worstStretchP99, 100 * scene.worstCompressionP99, 100 * paper.worstStretchP99);
  EXPECT_LT(scene.worstP99, 0.05);
  EXPECT_LT(scene.worstStretchP99, 0.03);
  EXPECT_GT(scene.worstCompressionP99, scene.worstStretchP99);
  EXPECT_LT(scene.worstMean, 0.012);
  EXPECT_GT(paper.worstStretchP99, 0.3);
  EXPECT_GT(scene.sag, 0.05f);  // it does carry the water in a bowl
  EXPECT_GT(paper.worstP99, 0.3);
}

namespace {
// Two balls 0.6 m apart and the given sheets over them, 4 sub-steps, 0.5 s:
// per ball (0 left, 1 right), the nearest any cloth vertex came to its
// surface and the lowest it hung.
struct OnBalls {
  float nearest[2] = {1.f, 1.f}, lowest[2] = {1.f, 1.f};
};
OnBalls dropOnBalls(const std::string& sheets) {
  test::TestRegistry reg;
  auto sim = test::makeSimulation(
      "<Scene><Simulation clothIterations='8' clothSubsteps='4' clothSubstepTravel='0'/>"
      "<Sphere name='left' center='-0.3 0.3 0' radius='0.08'/><Sphere name='right' center='0.3 0.3 0' "
      "radius='0.08'/>" + sheets + "</Scene>",
      Device::Cpu, reg);
  OnBalls r;
  const int steps = int(std::lround(0.5 / sim->settings.timeStep));
  for (int s = 1; s <= steps; ++s) {
    sim->step();
    for (const Float4& x : sim->particles.downloadPositions()) {
      const int side = x.x < 0.f ? 0 : 1;
      const Vec3 centre(side == 0 ? -0.3f : 0.3f, 0.3f, 0.f);
      r.nearest[side] = std::min(r.nearest[side], length(x.xyz() - centre) - 0.08f);
      r.lowest[side] = std::min(r.lowest[side], x.y);
    }
  }
  return r;
}
}  // namespace

TEST(ClothSolvers, SubsteppedSheetsOfBothModelsInOneSceneDrapeAsAlone) {
  // A pbd and a chebyshev sheet in one scene, 4 sub-steps, each dropped on
  // its own ball: the chebyshev sheet is projected out of the colliders in
  // its solve's last phase, the pbd sheet by the sub-step's colliders pass
  // (ClothSolve.cpp). Each must drape over its ball as it does alone (the
  // step's collide stage would keep a sheet that missed the sub-steps'
  // projections out of the ball, but it slides off further: lowest 0.148
  // instead of 0.222 m), and neither may end inside its ball.
  const std::string pbd =
      "<Cloth name='pbdSheet' model='pbd' origin='-0.45 0.4 -0.15' width='0.3' height='0.3' cellsU='14' "
      "cellsV='14'/>";
  const std::string cheb =
      "<Cloth name='jacobiSheet' model='chebyshev' origin='0.15 0.4 -0.15' width='0.3' height='0.3' cellsU='14' "
      "cellsV='14'/>";
  const OnBalls both = dropOnBalls(pbd + cheb), pbdAlone = dropOnBalls(pbd), chebAlone = dropOnBalls(cheb);
  std::printf("sheets on balls, 0.5 s: lowest %.4f m (pbd; alone %.4f), %.4f m (chebyshev; alone %.4f); nearest to "
              "the surface %.4f / %.4f m\n",
              both.lowest[0], pbdAlone.lowest[0], both.lowest[1], chebAlone.lowest[1], both.nearest[0],
              both.nearest[1]);
  EXPECT_NEAR(both.lowest[0], pbdAlone.lowest[0], 1e-3f);
  EXPECT_NEAR(both.lowest[1], chebAlone.lowest[1], 1e-3f);
  for (int side = 0; side < 2; ++side) {
    EXPECT_GT(both.nearest[side], -0.001f) << (side == 0 ? "pbd" : "chebyshev");
    EXPECT_LT(both.lowest[side], 0.3f) << (side == 0 ? "pbd" : "chebyshev");  // draped below the centre
  }
}

namespace {
// A 20 x 20 sheet (0.6 m) dropped on a 0.15 m ball, which from 1 s rises at
// 0.5 m/s, to 1.4 s: the vertex on the ball's top (nearest its axis at 1 s),
// its largest speed over a step of the lift (its displacement over dt) and
// its mean rise speed, and the worst per-step p99 strain of the lift.
struct Lift {
  double fastest = 0.0, rise = 0.0, worstP99 = 0.0;
};
Lift sheetLiftedByABall(int substeps) {
  test::TestRegistry reg;
  auto sim = test::makeSimulation(
      "<Scene><Simulation clothIterations='12' clothSubsteps='" + std::to_string(substeps) +
          "' clothSubstepTravel='0'/><Sphere name='ball' center='0 0.3 0' radius='0.15' friction='0.4' "
          "path='0 0 0 0; 1 0 0 0; 2 0 0.5 0'/><Cloth name='sheet' model='chebyshev' origin='-0.3 0.48 -0.3' "
          "width='0.6' height='0.6' cellsU='19' cellsV='19'/></Scene>",
      Device::Cpu, reg);
  const auto positions = [&] { return sim->cloth.downloadVertexPositions(sim->particles, 0); };
  const double dt = sim->settings.timeStep;
  const int liftStart = int(std::lround(1.0 / dt)), steps = int(std::lround(1.4 / dt));
  for (int s = 1; s <= liftStart; ++s) sim->step();
  std::vector<Vec3> before = positions();
  std::size_t top = 0;
  for (std::size_t v = 0; v < before.size(); ++v)
    if (before[v].x * before[v].x + before[v].z * before[v].z <
        before[top].x * before[top].x + before[top].z * before[top].z)
      top = v;
  const float startHeight = before[top].y;
  Lift r;
  for (int s = liftStart + 1; s <= steps; ++s) {
    sim->step();
    const std::vector<Vec3> after = positions();
    r.fastest = std::max(r.fastest, double(length(after[top] - before[top])) / dt);
    r.worstP99 = std::max(r.worstP99, sim->collectStats().get("strain_p99_sheet"));
    before = after;
  }
  r.rise = double(before[top].y - startHeight) / ((steps - liftStart) * dt);
  return r;
}
}  // namespace

TEST(ClothSolvers, ABallLiftingASheetMovesItAsFastAtAnySubsteps) {
  // A scripted collider is placed where its path is at the step's end; each
  // cloth sub-step sees it where it is at that sub-step's end
  // (colliderBefore). Seen at the step's end by every sub-step, the ball
  // moved its whole step in the first sub-step and kicked the vertices on
  // it at v dt / h, a speed that grows with the sub-steps, and the whole
  // fig9 runs on the H100 stretched more at 24 sub-steps than at 16
  // (Doc/performance.md, "Where the targets are not met (H100)").
  const Lift four = sheetLiftedByABall(4), sixteen = sheetLiftedByABall(16);
  std::printf("sheet lifted by a ball at 0.5 m/s, the vertex on its top: fastest %.3f / %.3f m/s, rise %.3f / %.3f "
              "m/s (4 / 16 sub-steps); worst p99 strain %.2f / %.2f %% (fewer sub-steps converge less)\n",
              four.fastest, sixteen.fastest, four.rise, sixteen.rise, 100 * four.worstP99, 100 * sixteen.worstP99);
  for (const Lift& l : {four, sixteen}) {
    EXPECT_NEAR(l.rise, 0.5, 0.05);  // it rides on the ball
    EXPECT_LT(l.fastest, 0.75);      // no kick
  }
  EXPECT_NEAR(sixteen.fastest, four.fastest, 0.1);
}

TEST(ClothSolvers, TheCollideStageLeavesTheClothToItsSolveAndProjectsTheWater) {
  // A 40 x 40 sheet landing on a ball with friction (the default counts),
  // and a water block falling on a second ball beside it, 0.45 s. The
  // cloth solve has projected the cloth out of the colliders with friction
  // in each sub-step; `collide` after it moves no cloth vertex (projecting
  // them again, with friction over the whole step, took fig9b's landing
  // from 1.58 % to 2.68 % p99, CPU), and keeps the water out of the balls.
  test::TestRegistry reg;
  auto sim = test::makeSimulation(
      "<Scene><Sphere name='ball' center='0 0.31 0' radius='0.11' friction='0.4'/>"
      "<Sphere name='pebble' center='1 0.3 0' radius='0.1' friction='0.4'/>"
      "<Cloth name='sheet' origin='-0.3 0.45 -0.3' width='0.6' height='0.6' cellsU='39' cellsV='39'/>"
      "<WaterBlock min='0.95 0.42 -0.05' max='1.05 0.52 0.05'/></Scene>",
      Device::Cpu, reg);
  std::vector<Float4> afterSolve;
  float clothMoved = 0.f, clothOnBall = 1e9f, waterInPebble = 1e9f;
  int waterChecked = 0;
  sim->pipeline.insertAfter(stage::kClothSolve, {"probe.solve", [&](Simulation& s) {
                              afterSolve = s.particles.downloadPredicted();
                            }});
  sim->pipeline.insertAfter(stage::kCollide, {"probe.collide", [&](Simulation& s) {
                              const std::vector<Float4> x = s.particles.downloadPredicted();
                              const std::vector<int> phase = s.particles.downloadPhases();
                              for (std::size_t i = 0; i < x.size(); ++i) {
                                const Vec3 p = x[i].xyz();
                                if (isCloth(phase[i])) {
                                  clothMoved = std::max(clothMoved, length(p - afterSolve[i].xyz()));
                                  clothOnBall = std::min(clothOnBall, length(p - Vec3(0.f, 0.31f, 0.f)));
                                } else {
                                  waterInPebble = std::min(waterInPebble, length(p - Vec3(1.f, 0.3f, 0.f)));
                                  ++waterChecked;
                                }
                              }
                            }});
  for (int s = 0; s < 30; ++s) sim->step();
  std::printf("after collide: largest cloth move %.3g m, cloth %.4f m from the ball's centre (radius 0.11), water "
              "%.4f m from the pebble's (radius 0.1)\n",
              clothMoved, clothOnBall, waterInPebble);
  EXPECT_LT(clothOnBall, 0.13f);  // the sheet lies on the ball
  EXPECT_EQ(clothMoved, 0.f);
  EXPECT_GT(waterChecked, 0);
  EXPECT_GE(waterInPebble, 0.1f);  // the water hit the pebble and stays out of it
  EXPECT_LT(waterInPebble, 0.13f);
}

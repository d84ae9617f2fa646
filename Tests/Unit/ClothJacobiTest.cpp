// The Jacobi cloth solve (<Simulation clothSolver="jacobi">, Doc/model.md,
// "Jacobi cloth"): every constraint computes its corrections from the same
// positions and each vertex takes the mean of its own. It converges more
// slowly per iteration than the colour-by-colour solve, and holds the cloth
// as well with more iterations.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "Support/TestScenes.h"

using namespace soak;

namespace {
// Worst edge strain of a 40 x 40 sheet hung by two corners without tethers
// (only the stretch constraints hold it), 4 sub-steps, over 1.5 s.
float worstStrain(const std::string& solver, int iterations, float relaxation = 1.5f) {
  test::TestRegistry reg;
  auto sim = test::makeSimulation(
      "<Scene><Simulation clothSubsteps='4' clothIterations='" + std::to_string(iterations) + "' clothSolver='" +
          solver + "' clothRelaxation='" + std::to_string(relaxation) +
          "'/><Cloth origin='-0.6 1.9 0' axisU='1 0 0' axisV='0 -1 0' width='1.2' height='1.2' cellsU='39' "
          "cellsV='39' pinCorners='u0v0 u1v0' tethers='false'/></Scene>",
      Device::Cpu, reg);
  float worst = 0.f;
  for (int s = 0; s < 100; ++s) {
    sim->step();
    const float strain = sim->cloth.maxStretch(sim->particles.view());
    EXPECT_TRUE(std::isfinite(strain));
    worst = std::max(worst, strain);
  }
  return worst;
}
}  // namespace

TEST(ClothJacobi, HoldsTheSheetWithMoreIterations) {
  const float gs = worstStrain("gauss-seidel", 10);
  const float jacobiSame = worstStrain("jacobi", 10);
  const float jacobiMore = worstStrain("jacobi", 40);
  std::printf("sheet on two corners, 4 sub-steps: worst strain gauss-seidel x 10 %.3f, jacobi x 10 %.3f, "
              "jacobi x 40 %.3f\n", gs, jacobiSame, jacobiMore);
  // Fewer rounds of information per iteration: more stretch at the same count...
  EXPECT_GT(jacobiSame, 1.2f * gs);
  // ...and at four times the iterations (still fewer GPU phases: 2 per
  // iteration instead of one per colour) no more than the coloured solve.
  EXPECT_LT(jacobiMore, 1.1f * gs);
}

TEST(ClothJacobi, RelaxationSpeedsConvergence) {
  const float plain = worstStrain("jacobi", 20, 1.f);
  const float relaxed = worstStrain("jacobi", 20, 1.5f);
  std::printf("jacobi x 20: worst strain relaxation 1.0 %.3f, 1.5 %.3f\n", plain, relaxed);
  EXPECT_LT(relaxed, plain);
}

// Issue 24: wet cloth bends easier and grips harder (<WetCloth
// wetBendSoftening, wetFriction>; the core's per-vertex fields
// bend_stiffness_scale and friction_scale). Wet weight is off in every run
// here, so what changes is the stiffness or the friction, not the weight.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "Support/TestScenes.h"

using namespace soak;

namespace {

// A 0.2 m x 0.06 m strip held level by its first two columns of vertices
// (a clamped cantilever along +x): the mean height of its free end's middle
// vertex from 1 s to 2.5 s (it swings about its rest shape: the mean is
// where it hangs).
float cantileverTip(const std::string& model, double saturation, double softening) {
  const int cellsU = 10, cellsV = 3;
  std::string pins;
  for (int j = 0; j <= cellsV; ++j)
    for (int i = 0; i < 2; ++i) pins += std::to_string(j * (cellsU + 1) + i) + " ";
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  auto sim = test::makeSimulation(
      "<Scene><Simulation clothSubsteps='4' clothIterations='12'/><Water/>"
      "<Cloth name='strip' model='" + model + "' origin='0 1 0' axisU='1 0 0' axisV='0 0 1' width='0.2' "
      "height='0.06' cellsU='" + std::to_string(cellsU) + "' cellsV='" + std::to_string(cellsV) +
          "' tethers='false' pin='" + pins + "'/>"
          "<WetCloth initialSaturation='" + std::to_string(saturation) +
          "' wetWeight='false' emission='false' sticking='false' diffusionIterations='0' wetBendSoftening='" +
          std::to_string(softening) + "'/></Scene>",
      Device::Cpu, reg);
  for (int s = 0; s < 67; ++s) sim->step();
  double sum = 0.0;
  for (int s = 0; s < 100; ++s) {
    sim->step();
    sum += sim->cloth.downloadVertexPositions(sim->particles, 0)[std::size_t((cellsV / 2) * (cellsU + 1) + cellsU)].y;
  }
  return float(sum / 100.0);
}

// A 0.2 m sheet laid on a plane tilted 20 degrees about z (friction 0.1),
// after 0.6 s: how far its centre has slid down the slope.
float slideDistance(double saturation, double wetFriction) {
  const double a = 20.0 * M_PI / 180.0;
  const double nx = std::sin(a), ny = std::cos(a);   // the plane's normal
  const double dx = std::cos(a), dy = -std::sin(a);  // down the slope
  const double lift = 0.01;                          // start just above the plane
  const std::string origin = std::to_string(-0.1 * dx + lift * nx) + " " + std::to_string(-0.1 * dy + lift * ny) +
                             " -0.1";
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  auto sim = test::makeSimulation(
      "<Scene><Simulation clothSubsteps='4' clothIterations='12'/><Water/>"
      "<Cloth name='sheet' model='chebyshev' origin='" + origin + "' axisU='" + std::to_string(dx) + " " +
          std::to_string(dy) + " 0' axisV='0 0 1' width='0.2' height='0.2' cellsU='10' cellsV='10'/>"
          "<Plane point='0 0 0' normal='" + std::to_string(nx) + " " + std::to_string(ny) +
          " 0' friction='0.1'/><WetCloth initialSaturation='" + std::to_string(saturation) +
          "' wetWeight='false' emission='false' sticking='false' diffusionIterations='0' wetFriction='" +
          std::to_string(wetFriction) + "'/></Scene>",
      Device::Cpu, reg);
  const auto centre = [&] {
    const std::vector<Vec3> x = sim->cloth.downloadVertexPositions(sim->particles, 0);
    Vec3 c(0.f, 0.f, 0.f);
    for (const Vec3& v : x) c += v;
    return c * (1.f / float(x.size()));
  };
  const Vec3 start = centre();
  for (int s = 0; s < 40; ++s) sim->step();
  const Vec3 d = centre() - start;
  return float(d.x * dx + d.y * dy);
}

}  // namespace

TEST(WetStiffness, AWetStripBendsLowerThanADryOneOfTheSameWeight) {
  // XPBD, whose bends have a physical stiffness (compliance 1/(N m), the
  // default): the paper's PBD holds the strip at bendStiffness 1 only by
  // overshooting (edge strain above 100 % at the clamp) and not at all at
  // 0.5, and chebyshev's one bend pass a sub-step barely holds it
  // (Doc/model.md, "Wet stiffness and friction").
  for (const char* model : {"xpbd"}) {
    const float dry = cantileverTip(model, 0.0, 0.8);
    const float wetStiff = cantileverTip(model, 0.3, 0.0);
    const float wetSoft = cantileverTip(model, 0.3, 0.8);
    std::printf("%s cantilever tip: dry %.4f m, wet as stiff %.4f m, wet softened %.4f m (root at 1 m)\n", model, dry,
                wetStiff, wetSoft);
    EXPECT_NEAR(wetStiff, dry, 1e-4f) << model << ": the same weight and stiffness, the same droop";
    EXPECT_LT(wetSoft, dry - 0.015f) << model << ": the softened wet strip droops further";
  }
}

TEST(WetFriction, AWetSheetSlidesLessOnASlopeThanADryOne) {
  const float dry = slideDistance(0.0, 3.0);
  const float wetPlain = slideDistance(0.3, 0.0);
  const float wetGrip = slideDistance(0.3, 3.0);
  std::printf("slide in 0.6 s: dry %.4f m, wet without wetFriction %.4f m, wet with it %.4f m\n", dry, wetPlain,
              wetGrip);
  EXPECT_GT(dry, 0.05f);  // it does slide
  EXPECT_NEAR(wetPlain, dry, 1e-4f);
  EXPECT_LT(wetGrip, 0.6f * dry);
}

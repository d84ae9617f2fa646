// Issue 24: drying (<WetCloth dryingRate=...>, Plugin/WetCloth/Drying.h).
// The two periods of drying against their exact solutions, the water
// budget with an evaporated column, and no dependence on the time step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "Support/TestScenes.h"

using namespace soak;

namespace {

constexpr double kSide = 0.4;  // m, the sheet
constexpr int kCells = 16;

// A horizontal sheet pinned at its corners that starts at `saturation`,
// with the drying attributes `drying`; no diffusion or drips unless `extra`
// brings water.
std::unique_ptr<Simulation> wetSheet(test::TestRegistry& reg, double dt, double saturation,
                                     const std::string& drying, const std::string& extra = "") {
  const std::string n = std::to_string(kCells), side = std::to_string(kSide);
  return test::makeSimulation(
      "<Scene><Simulation timeStep='" + std::to_string(dt) + "'/><Water/><Cloth origin='-0.2 0.5 -0.2' axisU='1 0 0' "
          "axisV='0 0 1' width='" + side + "' height='" + side + "' cellsU='" + n + "' cellsV='" + n +
          "' pinCorners='u0v0 u1v0 u0v1 u1v1'/>" + extra + "<WetCloth initialSaturation='" +
          std::to_string(saturation) + "' diffusionIterations='0' emission='false' " + drying + "/></Scene>",
      Device::Cpu, reg);
}

void advance(Simulation& sim, double seconds, double dt) {
  const int steps = int(std::lround(seconds / dt));
  for (int s = 0; s < steps; ++s) sim.step();
}

}  // namespace

TEST(Drying, ConstantRatePeriodLosesTheFluxTimesTheArea) {
  // Every particle stays above the critical saturation: the sheet loses
  // E0 (1 - RH) A t, whatever the time step.
  const double E0 = 0.02, RH = 0.25, seconds = 0.6;
  const double expected = E0 * (1.0 - RH) * kSide * kSide * seconds;
  for (double dt : {0.015, 0.0075}) {
    test::TestRegistry reg(SOAK_PLUGIN_DIR);
    auto sim = wetSheet(reg, dt, 0.3,
                        "dryingRate='" + std::to_string(E0) + "' ambientHumidity='" + std::to_string(RH) +
                            "' dryingCriticalSaturation='0.1'");
    sim->step();
    const StatsRow start = sim->collectStats();
    advance(*sim, seconds, dt);
    const StatsRow end = sim->collectStats();
    const double evaporated = end.get("evaporated_water_mass") - start.get("evaporated_water_mass");
    const double heldLost = start.get("held_water_mass") - end.get("held_water_mass");
    std::printf("dt %.4f: evaporated %.6e kg, held lost %.6e kg, expected %.6e kg\n", dt, evaporated, heldLost,
                expected);
    EXPECT_NEAR(evaporated, expected, 0.01 * expected);
    EXPECT_NEAR(heldLost, evaporated, 1e-3 * expected);
    EXPECT_NEAR(end.get("total_water_mass"), start.get("total_water_mass"), 1e-5 * start.get("total_water_mass"));
  }
}

TEST(Drying, FallingRatePeriodDecaysExponentially) {
  // Below the critical saturation a particle of area A and volume V keeps
  // exp(-E0 (1 - RH) A c t / (S_c V)) of its water (c = 0.001 m^3/kg).
  // A fast drier than any air (the test wants the decay within 0.75 s).
  const double E0 = 20.0, RH = 0.5, Sc = 0.4, c = 0.001, dt = 0.015, seconds = 0.75;
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  auto sim = wetSheet(reg, dt, 0.2,
                      "dryingRate='" + std::to_string(E0) + "' ambientHumidity='" + std::to_string(RH) +
                          "' dryingCriticalSaturation='" + std::to_string(Sc) + "'");
  sim->step();
  const int heldChannel = sim->particles.findChannel("held_water"), volumeChannel = sim->particles.findChannel("volume");
  // Held water and volume per cloth vertex (the particles are sorted by cell every step).
  const auto perVertex = [&](int channel) {
    const std::vector<int> id = sim->particles.downloadIds(), phase = sim->particles.downloadPhases();
    const std::vector<float> value = sim->particles.downloadChannel(channel);
    std::vector<double> out(std::size_t((kCells + 1) * (kCells + 1)), 0.0);
    for (std::size_t i = 0; i < id.size(); ++i)
      if (isCloth(phase[i])) out[std::size_t(id[i])] = value[i];
    return out;
  };
  const std::vector<double> held0 = perVertex(heldChannel), volume0 = perVertex(volumeChannel);
  advance(*sim, seconds, dt);
  const std::vector<double> held1 = perVertex(heldChannel), volume1 = perVertex(volumeChannel);
  // A vertex's area is a third of each of its triangles: on the sheet's
  // alternating diagonals two thirds or four thirds of a cell.
  const std::vector<float> area = sim->cloth.vertexRestAreas();
  double worst = 0.0, meanKept = 0.0;
  int interior = 0;
  for (int u = 2; u <= kCells - 2; ++u)
    for (int v = 2; v <= kCells - 2; ++v) {  // away from the pins
      const std::size_t k = std::size_t(v * (kCells + 1) + u);
      const double V = 0.5 * (volume0[k] + volume1[k]);
      const double predicted = std::exp(-E0 * (1.0 - RH) * double(area[k]) * c * seconds / (Sc * V));
      const double kept = held1[k] / held0[k];
      worst = std::max(worst, std::fabs(kept - predicted) / predicted);
      meanKept += kept;
      ++interior;
    }
  meanKept /= interior;
  std::printf("falling rate: %d interior particles keep %.4f of their water on average; worst error %.3f %%\n",
              interior, meanKept, 100.0 * worst);
  EXPECT_LT(meanKept, 0.8);  // the decay is visible, not a rounding
  EXPECT_LT(worst, 0.02);
}

TEST(Drying, SaturatedAirDriesNothingAndTheBudgetClosesWithWater) {
  // RH = 1: no evaporation. With a water drop landing and drying on, held,
  // buffered, free, drained and evaporated water add up to the start's.
  const std::string drop = "<WaterBlock min='-0.04 0.55 -0.04' max='0.04 0.63 0.04'/>";
  {
    test::TestRegistry reg(SOAK_PLUGIN_DIR);
    auto sim = wetSheet(reg, 0.015, 0.3, "dryingRate='0.05' ambientHumidity='1'");
    advance(*sim, 0.3, 0.015);
    EXPECT_EQ(sim->collectStats().get("evaporated_water_mass"), 0.0);
  }
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  auto sim = wetSheet(reg, 0.015, 0.05, "dryingRate='0.05' ambientHumidity='0.2'", drop);
  sim->step();
  const double total0 = sim->collectStats().get("total_water_mass");
  advance(*sim, 0.6, 0.015);
  const StatsRow end = sim->collectStats();
  std::printf("budget: total %.8f -> %.8f kg, evaporated %.6f kg, held %.6f kg\n", total0,
              end.get("total_water_mass"), end.get("evaporated_water_mass"), end.get("held_water_mass"));
  EXPECT_GT(end.get("evaporated_water_mass"), 1e-4);
  EXPECT_NEAR(end.get("total_water_mass"), total0, 1e-5 * total0);
}

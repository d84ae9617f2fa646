// Issue 4: the wetting model (WetCloth plugin) as numbers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numeric>

#include "Support/TestScenes.h"
#include "WetScenes.h"

using namespace soak;
using test::channel;
using test::kStill;
using test::wetScene;

namespace {

// Sets the held water of cloth particles (CPU run) from f(vertex position).
template <class F>
void setHeld(Simulation& sim, F f) {
  const int c = sim.particles.findChannel("held_water");
  ASSERT_GE(c, 0);
  ParticleView p = sim.particles.view();
  float* held = sim.particles.channel(c);
  for (int i = 0; i < p.count; ++i)
    if (isCloth(p.phase[i])) held[i] = f(i, p.position[i].xyz());
}

double clothSum(Simulation& sim, const std::string& name) {
  std::vector<float> v = channel(sim, name);
  std::vector<int> phase = sim.particles.downloadPhases();
  double s = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (isCloth(phase[i])) s += v[i];
  return s;
}

}  // namespace

TEST(WetCloth, AbsorptionFavoursClothBelowWaterByTheGravityTerm) {
  // Figure 4: one water particle between two identical sheets 1 cm above and
  // 1 cm below it. Eq. 11 gives the vertex straight below
  // (1 + eta^a) / (1 - eta^a) = 1.4 / 0.6 = 2.333 times what the vertex
  // straight above takes.
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  auto sim = wetScene(std::string(kStill) +
                          "<Cloth name='below' origin='-0.04 0.49 -0.04' axisU='1 0 0' axisV='0 0 1' width='0.08' "
                          "height='0.08' cellsU='4' cellsV='4' pinCorners='u0v0 u1v0 u0v1 u1v1' tethers='false'/>"
                          "<Cloth name='above' origin='-0.04 0.51 -0.04' axisU='1 0 0' axisV='0 0 1' width='0.08' "
                          "height='0.08' cellsU='4' cellsV='4' pinCorners='u0v0 u1v0 u0v1 u1v1' tethers='false'/>"
                          "<WaterBlock min='-0.01 0.49 -0.01' max='0.01 0.51 0.01'/>"
                          "<WetCloth emission='false' sticking='false' diffusionIterations='0'/>",
                      reg);
  ASSERT_EQ(sim->particles.count(), 51);
  sim->step();
  const std::vector<float> held = channel(*sim, "held_water");
  const std::vector<Float4> x = sim->particles.downloadPositions();
  const std::vector<int> phase = sim->particles.downloadPhases();
  float below = -1.f, above = -1.f;
  for (std::size_t i = 0; i < held.size(); ++i) {
    // The centre vertices (the sheets' vertices are 0.02 m apart).
    if (!isCloth(phase[i]) || std::fabs(x[i].x) > 0.005f || std::fabs(x[i].z) > 0.005f) continue;
    (x[i].y < 0.5f ? below : above) = held[i];
  }
  ASSERT_GT(above, 0.f);
  const float ratio = below / above;
  std::printf("absorbed straight below %.4g kg, straight above %.4g kg: ratio %.4f (Eq. 11: 2.3333)\n", below, above,
              ratio);
  EXPECT_NEAR(ratio, 1.4f / 0.6f, 0.02f * 1.4f / 0.6f);
}

TEST(WetCloth, JetOnHangingSheetConservesWaterAndKeepsSaturationInBounds) {
  // Figure 1 in small, wet: 2000 steps. Free + held + buffered + drained
  // water equals the emitted water to 1e-5 at every frame; 0 <= S <= S^MAX
  // at every step; no NaN.
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  std::ifstream in(std::string(SOAK_SOURCE_DIR) + "/Scenes/fig1_jet_dry.xml");
  std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  xml.replace(xml.find("</Scene>"), 8, "<WetCloth/></Scene>");
  auto sim = test::makeSimulation(xml, Device::Cpu, reg,
                                  {"Cloth.cellsU=24", "Cloth.cellsV=24", "Nozzle.radius=0.03", "Nozzle.stop=15"});
  double worstDrift = 0.0, emitted = 0.0;
  float worstS = 0.f, lowestS = 0.f;
  for (int s = 0; s < 2000; ++s) {
    sim->step();
    const std::vector<float> S = channel(*sim, "saturation");
    for (float v : S) {
      ASSERT_TRUE(std::isfinite(v)) << "step " << s;
      worstS = std::max(worstS, v);
      lowestS = std::min(lowestS, v);
    }
    if (s % 25 != 24) continue;
    StatsRow row = sim->collectStats();
    emitted = row.get("emitted_water_mass");
    const double total = row.get("total_water_mass");
    worstDrift = std::max(worstDrift, std::fabs(total - emitted) / emitted);
    for (const Float4& p : sim->particles.downloadPositions()) ASSERT_TRUE(isFinite(p.xyz())) << "step " << s;
  }
  StatsRow row = sim->collectStats();
  std::printf("2000 steps: emitted %.3f kg, held %.3f, buffered %.3f, drained %.3f, drips %.0f; worst relative "
              "drift %.2e; S in [%.3g, %.7g]\n",
              emitted, row.get("held_water_mass"), row.get("buffered_water_mass"), row.get("drained_water_mass"),
              row.get("drips_spawned"), worstDrift, lowestS, worstS);
  EXPECT_GT(row.get("held_water_mass"), 0.0);
  EXPECT_LE(worstDrift, 1e-5);
  EXPECT_GE(lowestS, 0.f);
  EXPECT_LE(worstS, 0.4f * (1.f + 1e-6f));  // S^MAX, to float round-off
}

namespace {

// A vertical 0.6 m sheet (41 x 41 vertices) with a wet band 0.1 m tall
// across its middle, held still; returns how far (m) the wet region has
// grown downwards and upwards after `steps`, and the water it holds before
// and after.
struct BandSpread {
  float down = 0.f, up = 0.f;
  double before = 0.0, after = 0.0;
};
BandSpread spreadOfWetBand(float etaD, const std::string& form, int steps) {
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  auto sim = wetScene(std::string(kStill) +
                          "<Cloth origin='-0.3 1 0' axisU='1 0 0' axisV='0 -1 0' width='0.6' height='0.6' cellsU='40' "
                          "cellsV='40' pinCorners='u0v0 u1v0' tethers='false'/>"
                          "<WetCloth emission='false' sticking='false' wetWeight='false' diffusionGravity='" +
                          std::to_string(etaD) + "' diffusionForm='" + form + "'/>",
                      reg);
  sim->step();  // volumes
  const std::vector<float> V = channel(*sim, "volume");
  setHeld(*sim, [&](int i, Vec3 x) { return (x.y <= 0.75f && x.y >= 0.65f) ? 0.3f * V[i] / 0.001f : 0.f; });
  BandSpread r;
  r.before = clothSum(*sim, "held_water");
  float previousMax = 1.f;
  for (int s = 0; s < steps; ++s) {
    sim->step();
    // No oscillation: diffusion never makes a new maximum or a negative value.
    const std::vector<float> S = channel(*sim, "saturation");
    const float mx = *std::max_element(S.begin(), S.end()), mn = *std::min_element(S.begin(), S.end());
    EXPECT_LE(mx, previousMax * (1.f + 1e-5f)) << "step " << s;
    EXPECT_GE(mn, 0.f) << "step " << s;
    previousMax = mx;
  }
  r.after = clothSum(*sim, "held_water");
  const std::vector<float> S = channel(*sim, "saturation");
  const std::vector<Float4> x = sim->particles.downloadPositions();
  float lo = 0.65f, hi = 0.75f;
  for (std::size_t i = 0; i < S.size(); ++i)
    if (S[i] > 0.03f && std::fabs(x[i].x) < 0.2f) lo = std::min(lo, x[i].y), hi = std::max(hi, x[i].y);
  r.down = 0.65f - lo;
  r.up = hi - 0.75f;
  return r;
}

}  // namespace

TEST(WetCloth, GravityDrivesTheWetFrontDownwards) {
  // Figure 5: with eta^d = 0.6 the front (S > 0.03) moves further down than
  // up; with eta^d = 0 the spread is symmetric within 5 % (one row, 15 mm,
  // is the resolution of the front).
  const BandSpread g = spreadOfWetBand(0.6f, "conservative", 60);
  const BandSpread n = spreadOfWetBand(0.f, "conservative", 60);
  std::printf("eta_d 0.6: down %.3f m, up %.3f m (ratio %.2f); eta_d 0: down %.3f, up %.3f\n", g.down, g.up,
              g.down / std::max(g.up, 1e-6f), n.down, n.up);
  EXPECT_GT(g.down, g.up + 0.014f);
  EXPECT_NEAR(n.down, n.up, std::max(0.05f * n.up, 0.016f));
  EXPECT_NEAR(g.after, g.before, 1e-5 * g.before);
}

TEST(WetCloth, LiteralEq17LosesOrMakesWaterAndTheConservativeFormDoesNot) {
  // Eq. 17 as printed updates S_i alone; with the gravity term the pair
  // weights are not symmetric and the held water changes. The conservative
  // form exchanges it pairwise.
  const BandSpread literal = spreadOfWetBand(0.6f, "literal", 60);
  const BandSpread conservative = spreadOfWetBand(0.6f, "conservative", 60);
  const double literalChange = (literal.after - literal.before) / literal.before;
  const double conservativeChange = (conservative.after - conservative.before) / conservative.before;
  std::printf("held water change over 60 steps: literal %+.3f %%, conservative %+.2e\n", 100.0 * literalChange,
              conservativeChange);
  EXPECT_GT(std::fabs(literalChange), 0.01);
  EXPECT_LT(std::fabs(conservativeChange), 1e-5);
  // Both spread the band downwards more than upwards.
  EXPECT_GT(literal.down, literal.up);
}

TEST(WetCloth, WetSpotOnHorizontalSheetSpreadsSymmetricallyWithLinearVariance) {
  // Figure 5's diffusion without a preferred direction: on a horizontal
  // sheet (gravity normal to it) a wet spot's second moment grows linearly
  // in time, as for diffusion, and its centre stays put.
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  auto sim = wetScene(std::string(kStill) +
                          "<Cloth origin='-0.4 0.5 -0.4' axisU='1 0 0' axisV='0 0 1' width='0.8' height='0.8' "
                          "cellsU='40' cellsV='40' pinCorners='u0v0 u1v0 u0v1 u1v1' tethers='false'/>"
                          "<WetCloth emission='false' sticking='false' wetWeight='false'/>",
                      reg);
  sim->step();
  const std::vector<float> V = channel(*sim, "volume");
  setHeld(*sim, [&](int i, Vec3 x) { return (x.x * x.x + x.z * x.z < 0.03f * 0.03f) ? 0.35f * V[i] / 0.001f : 0.f; });
  std::vector<double> t, var;
  double cx = 0.0, cz = 0.0;
  for (int s = 1; s <= 60; ++s) {
    sim->step();
    if (s % 5 != 0) continue;
    const std::vector<float> held = channel(*sim, "held_water");
    const std::vector<Float4> x = sim->particles.downloadPositions();
    double m = 0.0, mx = 0.0, mz = 0.0, m2 = 0.0;
    for (std::size_t i = 0; i < held.size(); ++i) {
      m += held[i];
      mx += held[i] * x[i].x;
      mz += held[i] * x[i].z;
      m2 += held[i] * (x[i].x * x[i].x + x[i].z * x[i].z);
    }
    cx = mx / m, cz = mz / m;
    t.push_back(s);
    var.push_back(m2 / m - cx * cx - cz * cz);
  }
  // Least-squares line and R^2.
  const double n = double(t.size());
  const double mt = std::accumulate(t.begin(), t.end(), 0.0) / n, mv = std::accumulate(var.begin(), var.end(), 0.0) / n;
  double stt = 0, stv = 0, svv = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    stt += (t[k] - mt) * (t[k] - mt);
    stv += (t[k] - mt) * (var[k] - mv);
    svv += (var[k] - mv) * (var[k] - mv);
  }
  const double r2 = stv * stv / (stt * svv);
  std::printf("wet spot: variance %.3g -> %.3g m^2 over %d steps, slope %.3g m^2/step, R^2 %.4f, centre (%.2g, %.2g)\n",
              var.front(), var.back(), int(t.back()), stv / stt, r2, cx, cz);
  EXPECT_GT(stv / stt, 0.0);
  EXPECT_GE(r2, 0.98);
  EXPECT_LT(std::fabs(cx) + std::fabs(cz), 0.005);
}

TEST(WetCloth, SaturatedHangingSheetDripsOnlyFromItsLowestEdge) {
  // Figure 6: a fully saturated sheet held by two corners. Every drip has
  // mass m_threshold and starts below the lowest cloth row; a sheet wet
  // below S^EW never drips.
  auto run = [](float saturation, int steps, std::vector<float>& dripMass, float& highestDripAboveBottom) {
    test::TestRegistry reg(SOAK_PLUGIN_DIR);
    auto sim = wetScene(
        "<Cloth origin='-0.2 1 0' axisU='1 0 0' axisV='0 -1 0' width='0.4' height='0.4' cellsU='20' cellsV='20' "
        "pinCorners='u0v0 u1v0'/><WetCloth initialSaturation='" +
            std::to_string(saturation) + "'/>",
        reg);
    highestDripAboveBottom = -1e9f;
    std::map<int, bool> seen;
    // New drips join in beforeStep; a stage ahead of predict sees them as born.
    std::map<int, float> birthMass;
    sim->pipeline.insertBefore("predict", {"probe.births", [&birthMass](Simulation& s) {
                                             const std::vector<int> phase = s.particles.downloadPhases();
                                             const std::vector<int> id = s.particles.downloadIds();
                                             const std::vector<float> mass = s.particles.downloadMasses();
                                             for (std::size_t i = 0; i < phase.size(); ++i)
                                               if (isWater(phase[i]) && !birthMass.count(id[i]))
                                                 birthMass[id[i]] = mass[i];
                                           }});
    for (int s = 0; s < steps; ++s) {
      sim->step();
      const std::vector<int> phase = sim->particles.downloadPhases(), id = sim->particles.downloadIds();
      const std::vector<float> mass = sim->particles.downloadMasses();
      const std::vector<Float4> x = sim->particles.downloadPositions();
      const std::vector<Vec3> cloth = sim->cloth.downloadVertexPositions(sim->particles, 0);
      float bottom = 1e9f;
      for (const Vec3& v : cloth) bottom = std::min(bottom, v.y);
      for (std::size_t i = 0; i < phase.size(); ++i) {
        if (!isWater(phase[i]) || seen[id[i]]) continue;
        seen[id[i]] = true;  // first frame of a new drip
        highestDripAboveBottom = std::max(highestDripAboveBottom, x[i].y - bottom);
      }
    }
    // One more step brings the drips queued in the last one in.
    const double spawned = sim->collectStats().get("drips_spawned");
    sim->step();
    for (const auto& [id, m] : birthMass) dripMass.push_back(m);
    return spawned;
  };
  std::vector<float> masses, none;
  float highest = 0.f, unused = 0.f;
  const double drips = run(0.4f, 150, masses, highest);
  const double dryDrips = run(0.3f, 150, none, unused);
  std::printf("saturated sheet: %.0f drips in 150 steps, highest start %.4f m above the lowest cloth point; "
              "sheet at S = 0.3: %.0f drips\n",
              drips, highest, dryDrips);
  ASSERT_GT(drips, 0.0);
  EXPECT_EQ(double(masses.size()), drips);
  for (float m : masses) EXPECT_NEAR(m, 0.002f, 1e-7f);
  EXPECT_LT(highest, 0.02f);  // within one row spacing (0.02 m) of the lowest point
  EXPECT_EQ(dryDrips, 0.0);
}

TEST(WetCloth, DripsPastTheRoomOfAStepWaitAndNoWaterIsLost) {
  // Drips are taken into a room of slots the host sizes on maintenance steps
  // (at most one per 32 cloth vertices: 13 for this 441-vertex sheet). The
  // whole bottom row of a saturated sheet wants to drip at once: the drips
  // past the room keep their water and drip in later steps. The water held,
  // buffered, free and drained stays what the sheet held at the start.
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  auto sim = wetScene(
      "<Cloth origin='-0.2 1 0' axisU='1 0 0' axisV='0 -1 0' width='0.4' height='0.4' cellsU='20' cellsV='20' "
      "pinCorners='u0v0 u1v0'/><Sink min='-2 -1 -2' max='2 0.3 2'/><WetCloth initialSaturation='0.4'/>",
      reg);
  sim->step();
  const double start = sim->collectStats().get("total_water_mass");
  double worstDrift = 0.0;
  for (int s = 0; s < 300; ++s) {
    sim->step();
    if (s % 10 != 9) continue;
    const double total = sim->collectStats().get("total_water_mass");
    worstDrift = std::max(worstDrift, std::fabs(total - start) / start);
  }
  const StatsRow row = sim->collectStats();
  std::printf("saturated sheet, 300 steps: %.0f drips, %.0f drip-steps deferred, %.4f kg drained, worst drift %.2e\n",
              row.get("drips_spawned"), row.get("drips_deferred"), row.get("drained_water_mass"), worstDrift);
  EXPECT_GT(row.get("drips_deferred"), 0.0);
  EXPECT_GT(row.get("drips_spawned"), 13.0);
  EXPECT_GT(row.get("drained_water_mass"), 0.0);
  EXPECT_LE(worstDrift, 1e-5);
}

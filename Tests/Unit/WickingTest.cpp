// Issue 24: vertical wicking (the AATCC 197 set-up, Scenes/wicking_strip.xml)
// with diffusionForm="fick". The wet front climbs as h^2 = K t with the K
// the diffusivity was set from, and levels off where gravity's drainage
// balances the diffusion (Doc/model.md, "Fick diffusion").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>

#include "Support/TestScenes.h"

using namespace soak;

namespace {

constexpr int kColumns = 6, kRows = 81;  // the strip's vertices (cellsU 5, cellsV 80)
constexpr double kDiffusivity = 0.00879, kDrainage = 0.0305;  // as in the scene
constexpr double kErfcInvHalf = 0.4769362762044699;            // erfc^-1(0.5)

constexpr double kRowSpacing = 0.01;  // m, in the fabric's rest shape

struct Sample {
  double t, h;  // h: the wet front's distance up the fabric from its lower edge
};

// The front is where a row's mean saturation falls to half the wettest
// row's (the row at the bath), interpolated between rows and measured in
// the fabric's rest shape: wicking runs through the fabric, and a strip
// that stretches under its water would otherwise add its stretch.
Sample measureFront(Simulation& sim) {
  const std::vector<float> S = sim.particles.downloadChannel(sim.particles.findChannel("saturation"));
  const std::vector<int> phase = sim.particles.downloadPhases(), id = sim.particles.downloadIds();
  std::vector<double> rowS(kRows, 0.0);
  for (std::size_t i = 0; i < S.size(); ++i)
    if (isCloth(phase[i])) rowS[id[i] / kColumns] += S[i] / kColumns;
  const double half = 0.5 * *std::max_element(rowS.begin(), rowS.end());
  double front = 0.0;  // rows from the lower edge (row kRows - 1; row 0 is the top)
  for (int r = 1; r < kRows; ++r)
    if (rowS[r] >= half && rowS[r - 1] < half) {
      front = double(kRows - 1 - r) + (rowS[r] - half) / (rowS[r] - rowS[r - 1]);
      break;
    }
  return {sim.time(), front * kRowSpacing};
}

std::vector<Sample> wick(double seconds, const std::vector<std::string>& overrides) {
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  std::ifstream in(std::string(SOAK_SOURCE_DIR) + "/Scenes/wicking_strip.xml");
  const std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto sim = test::makeSimulation(xml, Device::Cpu, reg, overrides);
  std::vector<Sample> samples;
  while (sim->time() < seconds) {
    for (int s = 0; s < 17; ++s) sim->step();  // about 0.25 s
    samples.push_back(measureFront(*sim));
  }
  return samples;
}

struct WashburnFit {
  double edge = 0.0, K = 0.0, r2 = 0.0;
};
// h = edge + sqrt(K t) by least squares in sqrt(t) (edge: how far up the
// bath wets the fabric at once: its depth in the water and the water's reach); R^2 of (h - edge)^2 = K t.
WashburnFit fitWashburn(const std::vector<Sample>& s, double from, double to) {
  std::vector<double> x, y;
  for (const Sample& q : s)
    if (q.t >= from && q.t <= to) x.push_back(std::sqrt(q.t)), y.push_back(q.h);
  const double n = double(x.size());
  double mx = 0, my = 0;
  for (std::size_t k = 0; k < x.size(); ++k) mx += x[k] / n, my += y[k] / n;
  double sxy = 0, sxx = 0;
  for (std::size_t k = 0; k < x.size(); ++k) sxy += (x[k] - mx) * (y[k] - my), sxx += (x[k] - mx) * (x[k] - mx);
  WashburnFit f;
  const double slope = sxy / sxx;
  f.edge = my - slope * mx;
  f.K = slope * slope;
  // R^2 of the line (h - edge)^2 against t.
  double mt = 0, mh = 0;
  for (std::size_t k = 0; k < x.size(); ++k) mt += x[k] * x[k] / n, mh += (y[k] - f.edge) * (y[k] - f.edge) / n;
  double stt = 0, sth = 0, shh = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double t = x[k] * x[k] - mt, h2 = (y[k] - f.edge) * (y[k] - f.edge) - mh;
    stt += t * t, sth += t * h2, shh += h2 * h2;
  }
  f.r2 = sth * sth / (stt * shh);
  return f;
}

}  // namespace

TEST(Wicking, FrontRisesAsLucasWashburnWithTheKSetAndLevelsOffUnderGravity) {
  const double kSet = 4.0 * kDiffusivity * kErfcInvHalf * kErfcInvHalf;
  // Without drainage: the rise alone.
  const std::vector<Sample> rise = wick(8.0, {"WetCloth.drainageSpeed=0"});
  const WashburnFit fit = fitWashburn(rise, 0.4, 8.0);
  std::printf("no drainage, 0.4-8 s: K %.5f m^2/s (set %.5f, %+.1f %%), R^2 %.4f, wetted edge %.3f m\n", fit.K, kSet,
              100.0 * (fit.K / kSet - 1.0), fit.r2, fit.edge);
  EXPECT_GE(fit.r2, 0.98);
  EXPECT_NEAR(fit.K / kSet, 1.0, 0.15);
  // With drainage (the scene as written): the front levels off near
  // (D / u) ln 2 above the wetted edge.
  const std::vector<Sample> drained = wick(20.0, {});
  const auto heightAt = [&](double t) {
    return std::min_element(drained.begin(), drained.end(), [&](const Sample& a, const Sample& b) {
             return std::fabs(a.t - t) < std::fabs(b.t - t);
           })->h;
  };
  const double early = heightAt(5.0) - heightAt(0.5), late = heightAt(20.0) - heightAt(15.0);
  const double level = heightAt(20.0) - fit.edge, predicted = kDiffusivity / kDrainage * std::log(2.0);
  std::printf("drainage %.4f m/s: front rose %.3f m in 0.5-5 s, %.3f m in 15-20 s; %.3f m above the wetted edge at "
              "20 s (levels at %.3f m)\n",
              kDrainage, early, late, level, predicted);
  EXPECT_LT(late, 0.25 * early);
  EXPECT_NEAR(level / predicted, 1.0, 0.2);
  // The same 20 s without drainage climbs far higher.
  EXPECT_GT(fit.edge + std::sqrt(kSet * 20.0), heightAt(20.0) + 0.1);
}

TEST(Wicking, WarpAndWeftDiffusivitiesSpreadAWetSpotIntoAnEllipse) {
  // A wet spot on a horizontal sheet (gravity normal to it, so no
  // drainage) spreads with the diffusivity of each direction: the water's
  // second moment along the warp (x) grows as 2 D_warp t and along the weft
  // (z) as 2 D_weft t, so the patch (S > 0.005) becomes an ellipse with axes in the
  // ratio sqrt(D_warp / D_weft) = 1.73 (3, the largest ratio the pair
  // weights reproduce exactly: Stages/FickDiffusion.cpp).
  const double Du = 0.003, Dv = 0.001;
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  auto sim = test::makeSimulation(
      "<Scene><Simulation gravity='0 -0.000001 0'/>"
      "<Cloth origin='-0.4 0.5 -0.4' axisU='1 0 0' axisV='0 0 1' width='0.8' height='0.8' cellsU='40' cellsV='40' "
      "pinCorners='u0v0 u1v0 u0v1 u1v1' tethers='false'/>"
      "<WetCloth diffusionForm='fick' diffusivity='" +
          std::to_string(Du) + "' diffusivityWeft='" + std::to_string(Dv) +
          "' emission='false' sticking='false' wetWeight='false'/></Scene>",
      Device::Cpu, reg);
  sim->step();  // volumes
  const int heldChannel = sim->particles.findChannel("held_water");
  {
    const std::vector<float> V = sim->particles.downloadChannel(sim->particles.findChannel("volume"));
    ParticleView p = sim->particles.view();
    float* held = sim->particles.channel(heldChannel);
    for (int i = 0; i < p.count; ++i) {
      const Vec3 x = p.position[i].xyz();
      held[i] = isCloth(p.phase[i]) && x.x * x.x + x.z * x.z < 0.03f * 0.03f ? 0.3f * V[i] / 0.001f : 0.f;
    }
  }
  const auto moments = [&](double& mx, double& mz, double& total, double& extentX, double& extentZ) {
    const std::vector<float> held = sim->particles.downloadChannel(heldChannel);
    const std::vector<float> S = sim->particles.downloadChannel(sim->particles.findChannel("saturation"));
    const std::vector<Float4> x = sim->particles.downloadPositions();
    double m = 0, sx = 0, sz = 0;
    extentX = extentZ = 0;
    for (std::size_t i = 0; i < held.size(); ++i) {
      m += held[i], sx += held[i] * x[i].x * x[i].x, sz += held[i] * x[i].z * x[i].z;
      if (S[i] > 0.005f) extentX = std::max(extentX, double(std::fabs(x[i].x))), extentZ = std::max(extentZ, double(std::fabs(x[i].z)));
    }
    mx = sx / m, mz = sz / m, total = m;
  };
  double x0, z0, m0, ex, ez;
  moments(x0, z0, m0, ex, ez);
  const double t0 = sim->time();
  while (sim->time() < t0 + 2.0) sim->step();
  double x1, z1, m1;
  moments(x1, z1, m1, ex, ez);
  const double t = sim->time() - t0;
  const double fitDu = (x1 - x0) / (2 * t), fitDv = (z1 - z0) / (2 * t);
  std::printf("after %.2f s: D along the warp %.5f m^2/s (set %.5f), along the weft %.5f (set %.5f); wet patch "
              "%.3f x %.3f m (ratio %.2f); water %.6f -> %.6f kg\n",
              t, fitDu, Du, fitDv, Dv, 2 * ex, 2 * ez, ex / ez, m0, m1);
  EXPECT_NEAR(fitDu / Du, 1.0, 0.1);
  EXPECT_NEAR(fitDv / Dv, 1.0, 0.1);
  EXPECT_NEAR(ex / ez, std::sqrt(Du / Dv), 0.25);
  EXPECT_NEAR(m1, m0, 1e-5 * m0);
}

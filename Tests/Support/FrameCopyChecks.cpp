#include "Support/FrameCopyChecks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "Backend/Buffer.h"
#include "Backend/DownloadQueue.h"
#include "Backend/Primitives.h"
#include "Plugins/PluginLoader.h"
#include "Support/TestScenes.h"

namespace soak::test {

namespace {
std::vector<float> ramp(std::size_t n, float start) {
  std::vector<float> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = start + float(i);
  return v;
}
std::vector<float> hostCopy(const DownloadQueue::Transfer& t, std::size_t k) {
  const float* p = static_cast<const float*>(t.part(k));
  return std::vector<float>(p, p + t.partBytes(k) / sizeof(float));
}
}  // namespace

void expectDownloadKeepsQueuedValues(Device d) {
  DownloadQueue queue(d);
  Buffer<float> a(d), b(d);
  a.upload(ramp(1000, 1.f));
  b.upload(ramp(37, -5.f));
  const unsigned long long waitsBefore = hostWaits();
  std::unique_ptr<DownloadQueue::Transfer> first = queue.download({{a.data(), 1000 * sizeof(float)},
                                                                   {b.data(), 37 * sizeof(float)}});
  if (d == Device::Cuda) EXPECT_EQ(hostWaits(), waitsBefore) << "queueing a download made the host wait";
  a.fillZero();  // the next step changes the arrays at once
  b.upload(ramp(37, 100.f));
  // A larger download before the first is read: the staging block grows.
  Buffer<float> c(d);
  c.upload(ramp(50000, 7.f));
  std::unique_ptr<DownloadQueue::Transfer> second = queue.download({{c.data(), 50000 * sizeof(float)}});
  c.fillZero();
  first->wait();
  second->wait();
  ASSERT_EQ(first->partCount(), 2u);
  EXPECT_EQ(hostCopy(*first, 0), ramp(1000, 1.f));
  EXPECT_EQ(hostCopy(*first, 1), ramp(37, -5.f));
  EXPECT_EQ(hostCopy(*second, 0), ramp(50000, 7.f));
  // Recycled host memory serves the next download.
  queue.recycle(std::move(first));
  queue.recycle(std::move(second));
  std::unique_ptr<DownloadQueue::Transfer> third = queue.download({{b.data(), 37 * sizeof(float)}});
  third->wait();
  EXPECT_EQ(hostCopy(*third, 0), ramp(37, 100.f));
}

void expectFrameStatsMatchDeviceReductions(Device d) {
  TestRegistry reg(defaultPluginDirectory());
  const std::string xml =
      "<Scene><Cloth origin='-0.3 0.5 -0.3' axisU='1 0 0' axisV='0 0 1' width='0.6' height='0.6' cellsU='30' "
      "cellsV='30' pinCorners='u0v0 u1v0 u0v1 u1v1'/><WaterBlock min='-0.1 0.53 -0.1' max='0.1 0.63 0.1'/>"
      "<WetCloth/></Scene>";
  auto sim = makeSimulation(xml, d, reg);
  for (int s = 0; s < 60; ++s) sim->step();
  const StatsRow row = sim->collectStats();

  double mean = 0.0;
  float max = 0.f;
  sim->fluid.densityError(sim->particles.view(), sim->fluidContext(), mean, max);
  const float stretch = sim->cloth.maxStretch(sim->particles.view());
  const int n = sim->particles.count();
  const int held = sim->particles.findChannel("held_water");
  const int saturation = sim->particles.findChannel("saturation");
  ASSERT_GE(held, 0);
  ASSERT_GE(saturation, 0);
  const double heldSum = reduceSum(d, sim->particles.channel(held), n);
  const float maxSaturation = reduceMax(d, sim->particles.channel(saturation), n);
  std::printf("%s: density error mean %.6g (device %.6g), max %.6g (%.6g); stretch %.6g (%.6g); held %.6g kg "
              "(%.6g); max S %.6g (%.6g)\n",
              deviceName(d), row.get("mean_density_error"), mean, row.get("max_density_error"), double(max),
              row.get("max_stretch"), double(stretch), row.get("held_water_mass"), heldSum,
              row.get("max_saturation"), double(maxSaturation));
  // The state is not trivial: water is compressed, the sheet stretched and wet.
  ASSERT_GT(max, 0.f);
  ASSERT_GT(stretch, 0.f);
  ASSERT_GT(heldSum, 0.0);
  EXPECT_NEAR(row.get("mean_density_error"), mean, 1e-9 + 1e-6 * mean);
  EXPECT_NEAR(row.get("max_density_error"), double(max), 1e-6 * double(max));
  // The GPU's kernel contracts the edge length to fused multiply-adds; the
  // host's loop rounds each product: they part by an ulp or two.
  EXPECT_NEAR(row.get("max_stretch"), double(stretch), 1e-5 * double(stretch));
  EXPECT_NEAR(row.get("held_water_mass"), heldSum, 1e-9 * heldSum);
  EXPECT_NEAR(row.get("max_saturation"), double(maxSaturation), 1e-7);
}

}  // namespace soak::test

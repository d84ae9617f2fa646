#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "Backend/ForEach.h"
#include "Pipeline/Pipeline.h"
#include "Simulation/Simulation.h"

using namespace soak;

TEST(Pipeline, ModulesInsertRelativeToAnchors) {
  Simulation sim(Device::Cpu);
  sim.initialize();
  std::vector<std::string> order;
  sim.pipeline.insertAfter("predict", {"a", [&](Simulation&) { order.push_back("a"); }});
  sim.pipeline.insertBefore("finalize", {"b", [&](Simulation&) { order.push_back("b"); }});
  sim.pipeline.insertBefore("a", {"c", [&](Simulation&) { order.push_back("c"); }});
  std::vector<std::string> names = sim.pipeline.names();
  EXPECT_EQ(names, (std::vector<std::string>{"predict", "c", "a", "drain", "neighbours", "fluid.solve", "cloth.solve",
                                              "collide", "coupling", "b", "finalize"}));
  sim.step();
  sim.step();
  EXPECT_EQ(order, (std::vector<std::string>{"c", "a", "b", "c", "a", "b"}));
  for (const StageTiming& t : sim.pipeline.timings()) EXPECT_EQ(t.calls, 2) << t.name;
}

TEST(Pipeline, MissingAnchorListsStages) {
  Simulation sim(Device::Cpu);
  sim.initialize();
  try {
    sim.pipeline.insertAfter("fluid.slove", {"x", [](Simulation&) {}});
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("predict, drain, neighbours, fluid.solve, cloth.solve"), std::string::npos) << e.what();
  }
  EXPECT_THROW(sim.pipeline.append({"predict", [](Simulation&) {}}), std::invalid_argument);
}

// A profiled stage's time is its own: not the work between stages (the
// instability check's callback), nor the next stage's. And every forEach a
// stage runs counts as one launch of that stage.
TEST(Pipeline, ProfiledStagesTimeOnlyThemselvesAndCountTheirLaunches) {
  Pipeline pipeline;
  auto sleepMs = [](int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); };
  std::vector<int> sink(64, 0);
  int* out = sink.data();
  pipeline.append({"slow", [&](Simulation&) {
                     sleepMs(40);
                     for (int k = 0; k < 3; ++k) forEach(Device::Cpu, 64, [=](int i) { out[i] += 1; });
                   }});
  pipeline.append({"quick", [&](Simulation&) { sleepMs(2); }});
  Simulation unused(Device::Cpu);
  pipeline.run(unused, Device::Cpu, true, [&](const std::string& stage) {
    if (stage == "slow") sleepMs(300);  // between the stages: nobody's time
  });
  const std::vector<StageTiming>& t = pipeline.timings();
  ASSERT_EQ(t.size(), 2u);
  EXPECT_GE(t[0].meanMs(), 40.0);
  // Wide margins: a loaded 2-core CI machine can oversleep by tens of ms.
  EXPECT_LT(t[0].meanMs(), 290.0);  // not the 300 ms that follow it
  EXPECT_GE(t[1].meanMs(), 2.0);
  EXPECT_LT(t[1].meanMs(), 250.0);  // not the 300 ms before it
  EXPECT_EQ(t[0].meanLaunches(), 3.0);
  EXPECT_EQ(t[1].meanLaunches(), 0.0);
  EXPECT_EQ(sink[5], 3);
}

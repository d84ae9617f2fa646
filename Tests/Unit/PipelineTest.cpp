#include <gtest/gtest.h>

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

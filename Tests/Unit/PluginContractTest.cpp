// The plugin contract (issue 25): a plugin's element may stand anywhere in
// the scene, a stage may anchor on a stage added later, and an anchor that
// nothing provides is bad input at the element that asked for it.
#include <gtest/gtest.h>

#include "Base/Error.h"
#include "Pipeline/StageNames.h"
#include "Support/TestScenes.h"

using namespace soak;

namespace {

// A module that adds one stage next to an anchor.
class AnchoredStage : public Module {
 public:
  AnchoredStage(std::string name, std::string anchor, std::vector<std::string>* ran)
      : name_(std::move(name)), anchor_(std::move(anchor)), ran_(ran) {}
  void addStages(Pipeline& p, Simulation&) override {
    p.insertAfter(anchor_, {name_, [this](Simulation&) { ran_->push_back(name_); }});
  }

 private:
  std::string name_, anchor_;
  std::vector<std::string>* ran_;
};

const char* kSheetAndWater =
    "<Cloth origin='-0.1 0.5 -0.1' axisU='1 0 0' axisV='0 0 1' width='0.2' height='0.2' cellsU='10' cellsV='10' "
    "pinCorners='u0v0 u1v0 u0v1 u1v1'/>"
    "<WaterBlock min='-0.04 0.53 -0.04' max='0.04 0.6 0.04'/>";

}  // namespace

TEST(PluginContract, AStageMayAnchorOnAStageAddedLater) {
  std::vector<std::string> ran;
  Simulation sim(Device::Cpu);
  // The first module's anchor is the second module's stage.
  sim.addModule(std::make_unique<AnchoredStage>("late.b", "late.a", &ran), {"scene.xml:2", true});
  sim.addModule(std::make_unique<AnchoredStage>("late.a", stage::kCoupling, &ran), {"scene.xml:3", true});
  sim.initialize();
  const std::vector<std::string> names = sim.pipeline.names();
  const auto at = [&](const std::string& n) { return std::find(names.begin(), names.end(), n) - names.begin(); };
  EXPECT_EQ(at("late.a"), at(stage::kCoupling) + 1);
  EXPECT_EQ(at("late.b"), at("late.a") + 1);
  sim.step();
  EXPECT_EQ(ran, (std::vector<std::string>{"late.a", "late.b"}));
}

TEST(PluginContract, AnAnchorNothingProvidesIsBadInputAtItsElement) {
  std::vector<std::string> ran;
  Simulation sim(Device::Cpu);
  sim.addModule(std::make_unique<AnchoredStage>("x.apply", "fluid.slove", &ran), {"scene.xml:7", true});
  try {
    sim.initialize();
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.where(), "scene.xml:7");
    EXPECT_NE(what.find("stage 'x.apply' goes after 'fluid.slove'"), std::string::npos) << what;
    EXPECT_NE(what.find("fluid.solve"), std::string::npos) << what;  // the stages there are
  }
}

TEST(PluginContract, ADuplicateStageIsBadInputAtItsElement) {
  std::vector<std::string> ran;
  Simulation sim(Device::Cpu);
  sim.addModule(std::make_unique<AnchoredStage>("dup", stage::kPredict, &ran), {"scene.xml:4", true});
  sim.addModule(std::make_unique<AnchoredStage>("dup", stage::kPredict, &ran), {"scene.xml:5", true});
  try {
    sim.initialize();
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "scene.xml:5");
  }
}

TEST(PluginContract, WetClothBeforeItsClothRunsAsAfterIt) {
  // The same scene with <WetCloth> first and last: the same stages, the same
  // particles, bit for bit, after 20 steps.
  const std::string wet = "<WetCloth/>";
  test::TestRegistry regA(SOAK_PLUGIN_DIR), regB(SOAK_PLUGIN_DIR);
  auto first = test::makeSimulation("<Scene>" + wet + kSheetAndWater + "</Scene>", Device::Cpu, regA);
  auto last = test::makeSimulation(std::string("<Scene>") + kSheetAndWater + wet + "</Scene>", Device::Cpu, regB);
  EXPECT_EQ(first->pipeline.names(), last->pipeline.names());
  for (int s = 0; s < 20; ++s) {
    first->step();
    last->step();
  }
  const std::vector<Float4> a = first->particles.downloadPositions(), b = last->particles.downloadPositions();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].x, b[i].x) << i;
    EXPECT_EQ(a[i].y, b[i].y) << i;
  }
  const int held = first->particles.findChannel("held_water");
  ASSERT_GE(held, 0);
  double heldSum = 0.0;
  for (float v : first->particles.downloadChannel(held)) heldSum += v;
  EXPECT_GT(heldSum, 0.0) << "the water never touched the sheet: the test shows nothing";
  EXPECT_EQ(first->particles.downloadChannel(held), last->particles.downloadChannel(held));
}

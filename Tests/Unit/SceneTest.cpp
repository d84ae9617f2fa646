#include <gtest/gtest.h>

#include "Base/Error.h"
#include "Support/TestScenes.h"

using namespace soak;

namespace {
std::string errorOf(const std::string& xml, const std::vector<std::string>& overrides = {}) {
  test::TestRegistry reg;
  try {
    Scene::parse(xml, "scene.xml", overrides, reg.registry, nullptr);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST(Scene, ValidSceneFillsDefaults) {
  test::TestRegistry reg;
  Scene s = Scene::parse("<Scene>\n  <Simulation timeStep=\"0.01\"/>\n  <Sphere radius=\"0.5\"/>\n</Scene>\n",
                         "scene.xml", {}, reg.registry, nullptr);
  ASSERT_EQ(s.elements().size(), 2u);
  EXPECT_DOUBLE_EQ(s.elements()[0].params.real("timeStep"), 0.01);
  EXPECT_DOUBLE_EQ(s.elements()[0].params.real("frameRate"), 30.0);  // default
  EXPECT_FALSE(s.elements()[0].params.given("frameRate"));
  EXPECT_EQ(s.elements()[1].line, 3);
  EXPECT_FLOAT_EQ(s.elements()[1].params.vector("center").y, 0.f);
}

TEST(Scene, MisspeltAttributeNamesLineAndSuggestion) {
  std::string e = errorOf("<Scene>\n\n  <Sphere radus=\"0.5\"/>\n</Scene>");
  EXPECT_NE(e.find("scene.xml:3"), std::string::npos) << e;
  EXPECT_NE(e.find("'radus'"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean 'radius'"), std::string::npos) << e;
}

TEST(Scene, UnknownElementSuggestsClosest) {
  std::string e = errorOf("<Scene>\n  <Plnae/>\n</Scene>");
  EXPECT_NE(e.find("scene.xml:2"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean 'Plane'"), std::string::npos) << e;
}

TEST(Scene, PluginElementWithoutItsPluginSaysHowToLoadIt) {
  // The core names no plugin: an element no loaded plugin declares gets
  // the ways a plugin is loaded.
  std::string e = errorOf("<Scene>\n  <WetCloth/>\n</Scene>");
  EXPECT_NE(e.find("unknown element <WetCloth>"), std::string::npos) << e;
  EXPECT_NE(e.find(":2"), std::string::npos) << e;
  EXPECT_NE(e.find("<Plugin name="), std::string::npos) << e;
  EXPECT_NE(e.find("--plugin"), std::string::npos) << e;
}

TEST(Scene, WrongTypeAndRange) {
  EXPECT_NE(errorOf("<Scene><Simulation timeStep=\"fast\"/></Scene>").find("not a finite number"), std::string::npos);
  std::string e = errorOf("<Scene><Simulation timeStep=\"-0.1\"/></Scene>");
  EXPECT_NE(e.find("out of range"), std::string::npos) << e;
  EXPECT_NE(e.find("(0, 1]"), std::string::npos) << e;
  EXPECT_NE(errorOf("<Scene><Plane normal=\"0 1\"/></Scene>").find("three finite numbers"), std::string::npos);
  EXPECT_NE(errorOf("<Scene><Box inside=\"maybe\"/></Scene>").find("true or false"), std::string::npos);
  EXPECT_NE(errorOf("<Scene><Plane friction=\"nan\"/></Scene>").find("not a finite number"), std::string::npos);
}

TEST(Scene, MalformedXmlHasLine) {
  std::string e = errorOf("<Scene>\n  <Plane>\n</Scene>");
  EXPECT_NE(e.find("malformed XML"), std::string::npos) << e;
  EXPECT_NE(e.find("scene.xml:3"), std::string::npos) << e;
}

TEST(Scene, StructuralErrors) {
  EXPECT_NE(errorOf("").find("empty scene"), std::string::npos);
  EXPECT_NE(errorOf("<Scenery/>").find("expected <Scene>"), std::string::npos);
  EXPECT_NE(errorOf("<Scene><Simulation/><Simulation/></Scene>").find("only once"), std::string::npos);
  EXPECT_NE(errorOf("<Scene><Plane><Sphere/></Plane></Scene>").find("attributes only"), std::string::npos);
  EXPECT_NE(errorOf("<Scene>hello</Scene>").find("unexpected text"), std::string::npos);
}

TEST(Scene, OverridesApplyBeforeValidation) {
  test::TestRegistry reg;
  Scene s = Scene::parse("<Scene><Sphere radius=\"0.5\"/><Sphere/></Scene>", "scene.xml",
                         {"Sphere[1].radius=0.25", "Simulation.timeStep=0.005"}, reg.registry, nullptr);
  EXPECT_DOUBLE_EQ(s.elements()[1].params.real("radius"), 0.25);
  EXPECT_DOUBLE_EQ(s.elements()[2].params.real("timeStep"), 0.005);  // element added for the override
  EXPECT_NE(s.textAsRun().find("0.25"), std::string::npos);
  EXPECT_NE(errorOf("<Scene><Sphere/><Sphere/></Scene>", {"Sphere.radius=1"}).find("Sphere[0]"), std::string::npos);
  EXPECT_NE(errorOf("<Scene/>", {"Sphere.radius=1"}).find("no <Sphere>"), std::string::npos);
  EXPECT_NE(errorOf("<Scene/>", {"Simulation.timeStp=1"}).find("did you mean 'timeStep'"), std::string::npos);
  EXPECT_NE(errorOf("<Scene/>", {"nonsense"}).find("Element.attribute=value"), std::string::npos);
}

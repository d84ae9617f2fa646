// Doc/scene-format.md is generated from the registry (`soak params`); this
// test fails when the two drift apart.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "Support/TestScenes.h"

using namespace soak;

TEST(RegistryDoc, SceneFormatPageMatchesRegistry) {
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  std::ifstream in(std::string(SOAK_SOURCE_DIR) + "/Doc/scene-format.md");
  ASSERT_TRUE(in) << "Doc/scene-format.md is missing";
  std::stringstream page;
  page << in.rdbuf();
  EXPECT_EQ(page.str(), registryMarkdown(reg.registry))
      << "Doc/scene-format.md is out of date: regenerate it with `build/bin/soak params > Doc/scene-format.md`";
}

TEST(RegistryDoc, EveryParameterHasDescriptionAndValidDefault) {
  test::TestRegistry reg(SOAK_PLUGIN_DIR);
  for (const ElementDecl& e : reg.registry.elements()) {
    EXPECT_FALSE(e.description.empty()) << e.name;
    for (const ParamDecl& p : e.params) EXPECT_FALSE(p.description.empty()) << e.name << "." << p.name;
    // Parsing an element with no attributes validates every default.
    if (e.name == "Plugin") continue;
    EXPECT_NO_THROW(Scene::parse("<Scene><" + e.name + "/></Scene>", "d.xml", {}, reg.registry, nullptr)) << e.name;
  }
}

TEST(RegistryDoc, DuplicateElementIsRejected) {
  test::TestRegistry reg;
  EXPECT_THROW(registerCoreElements(reg.registry), std::invalid_argument);
}

#include "Support/TestScenes.h"

namespace soak::test {

TestRegistry::TestRegistry(const std::string& pluginDir) {
  registerCoreElements(registry);
  if (!pluginDir.empty()) {
    loader.addSearchDirectory(pluginDir);
    loader.loadDirectory(pluginDir);
  }
}

std::unique_ptr<Simulation> makeSimulation(const std::string& sceneXml, Device device, TestRegistry& reg,
                                           const std::vector<std::string>& overrides) {
  Scene scene = Scene::parse(sceneXml, "test.xml", overrides, reg.registry,
                             [&](const std::string& what, bool isPath, const std::string& where) {
                               if (isPath) reg.loader.loadFile(what, where);
                               else reg.loader.loadByName(what, where);
                             });
  auto sim = std::make_unique<Simulation>(device);
  for (const SceneElement& e : scene.elements()) sim->addModule(e.decl->factory(e.params), {e.params.where(), e.decl->provider != "Core"});
  sim->initialize();
  return sim;
}

}  // namespace soak::test

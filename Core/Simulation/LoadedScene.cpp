#include "Simulation/LoadedScene.h"

namespace soak {

void loadStandardPlugins(PluginLoader& loader, const std::vector<std::string>& extra) {
  loader.addSearchDirectory(defaultPluginDirectory());
  loader.loadDirectory(defaultPluginDirectory());
  for (const std::string& p : extra) loader.loadFile(p, "--plugin");
}

std::unique_ptr<LoadedScene> loadScene(const SceneSource& source, Device device) {
  auto run = std::make_unique<LoadedScene>();
  registerCoreElements(run->registry);
  run->loader = std::make_unique<PluginLoader>(run->registry);
  PluginLoader& loader = *run->loader;
  loadStandardPlugins(loader, source.plugins);
  const PluginRequest request = [&](const std::string& what, bool isPath, const std::string& where) {
    if (isPath) loader.loadFile(what, where);
    else loader.loadByName(what, where);
  };
  run->scene = source.text.empty()
                   ? Scene::load(source.path, source.overrides, run->registry, request)
                   : Scene::parse(source.text, source.path, source.overrides, run->registry, request);
  run->sim = std::make_unique<Simulation>(device);
  for (const SceneElement& e : run->scene.elements()) run->sim->addModule(e.decl->factory(e.params), {e.params.where(), e.decl->provider != "Core"});
  run->sim->initialize();
  return run;
}

}  // namespace soak

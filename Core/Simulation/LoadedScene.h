#pragma once
// A scene file (or text) read with the core elements and the standard
// plugins, and built into a Simulation: what `soak run` and `soak-bench`
// both start from. Everything that can fail because of the input (parsing,
// validation, building) happens here, before any output is written.
#include <memory>
#include <string>
#include <vector>

#include "Plugins/PluginLoader.h"
#include "Registry/ModuleRegistry.h"
#include "Scene/Scene.h"
#include "Simulation/Simulation.h"

namespace soak {

struct LoadedScene {
  ModuleRegistry registry;
  std::unique_ptr<PluginLoader> loader;  // plugins stay loaded while the simulation lives
  Scene scene;
  std::unique_ptr<Simulation> sim;
  ~LoadedScene() { sim.reset(); }  // modules hold plugin code: release them first
};

struct SceneSource {
  std::string path;                    // file to read, or the name used in messages when `text` is given
  std::string text;                    // scene XML; empty: read `path`
  std::vector<std::string> overrides;  // "Element.attr=value"
  std::vector<std::string> plugins;    // extra plugin libraries (--plugin)
};

// The plugins of the default plugin folder, then `extra` (--plugin paths).
void loadStandardPlugins(PluginLoader& loader, const std::vector<std::string>& extra);

std::unique_ptr<LoadedScene> loadScene(const SceneSource& source, Device device);

}  // namespace soak

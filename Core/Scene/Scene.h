#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "Registry/ModuleRegistry.h"

namespace soak {

// One validated element of a scene.
struct SceneElement {
  const ElementDecl* decl = nullptr;
  ElementParams params;
  int line = 0;
};

// Loads a plugin named in the scene: (name or path, isPath, "file:line").
using PluginRequest = std::function<void(const std::string&, bool, const std::string&)>;

// A scene file, read with pugixml and checked against the registry.
//
// Every element and attribute is checked: an unknown name, a wrong type or
// an out-of-range value throws InputError naming file, line, the bad name
// and the closest valid names. Overrides "Element.attr=value" or
// "Element[i].attr=value" are applied before checking.
class Scene {
 public:
  static Scene load(const std::string& path, const std::vector<std::string>& overrides, ModuleRegistry& registry,
                    const PluginRequest& loadPlugin);
  // Same, from text (path is used in messages and to resolve relative files).
  static Scene parse(const std::string& text, const std::string& path, const std::vector<std::string>& overrides,
                     ModuleRegistry& registry, const PluginRequest& loadPlugin);

  const std::vector<SceneElement>& elements() const { return elements_; }
  const std::string& path() const { return path_; }
  // The scene as run: the file with overrides applied.
  const std::string& textAsRun() const { return textAsRun_; }
  // The files the run reads: the scene file, its meshes (parameters declared
  // with ElementDecl::inputFile) and plugin libraries given by path, as
  // written or resolved from the scene's folder. The output folder may not
  // hold them (Output/OutputFolder.h).
  const std::vector<std::string>& inputFiles() const { return inputFiles_; }

 private:
  std::string path_;
  std::string textAsRun_;
  std::vector<SceneElement> elements_;
  std::vector<std::string> inputFiles_;
};

}  // namespace soak

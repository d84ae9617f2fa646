#pragma once
#include <string>
#include <vector>

#include "Registry/ModuleRegistry.h"

namespace soak {

// Loads plugin libraries into a registry. Libraries stay loaded for the
// lifetime of the loader (modules hold code from them).
class PluginLoader {
 public:
  explicit PluginLoader(ModuleRegistry& registry) : registry_(registry) {}
  ~PluginLoader();
  PluginLoader(const PluginLoader&) = delete;
  PluginLoader& operator=(const PluginLoader&) = delete;

  // Loads one library file. Throws InputError (with `where` if given) if it
  // cannot be opened or is not a Soak plugin. Loading the same plugin twice
  // is a no-op.
  void loadFile(const std::string& path, const std::string& where = {});
  // Loads libsoak_<name>.so from the plugin directories.
  void loadByName(const std::string& name, const std::string& where = {});
  // Loads every libsoak_*.so in a directory (missing directory: nothing).
  void loadDirectory(const std::string& dir);

  void addSearchDirectory(const std::string& dir) { dirs_.push_back(dir); }
  const std::vector<std::string>& searchDirectories() const { return dirs_; }

 private:
  ModuleRegistry& registry_;
  std::vector<std::string> dirs_;
  std::vector<void*> handles_;
};

// The standard plugin directory: soak-plugins beside the core library
// (lib/soak-plugins), else <exe dir>/../lib/soak-plugins.
std::string defaultPluginDirectory();

}  // namespace soak

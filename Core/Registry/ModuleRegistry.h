#pragma once
#include <string>
#include <vector>

#include "Registry/ElementDecl.h"

namespace soak {

// Maps scene element names to their declarations and module factories.
// One registry object is owned by the program (no singleton); Core adds its
// elements with registerCoreElements(), plugins through their entry point.
class ModuleRegistry {
 public:
  // Throws std::invalid_argument if the name is taken or a declaration is malformed.
  void add(ElementDecl decl);
  const ElementDecl* find(const std::string& name) const;
  std::vector<std::string> names() const;
  const std::vector<ElementDecl>& elements() const { return elements_; }

  // Plugin bookkeeping: which plugins have registered (name and file).
  void notePlugin(const std::string& name, const std::string& file);
  const std::vector<std::pair<std::string, std::string>>& plugins() const { return plugins_; }
  bool hasPlugin(const std::string& name) const;
  // Name given to elements added while a plugin registers.
  void setProvider(const std::string& provider) { provider_ = provider; }

 private:
  std::vector<ElementDecl> elements_;
  std::vector<std::pair<std::string, std::string>> plugins_;
  std::string provider_ = "Core";
};

// Adds every element Core provides (Simulation, colliders, emitters, ...).
void registerCoreElements(ModuleRegistry& registry);

// Markdown reference of every registered element and parameter; this is
// what `soak params` prints and what Doc/scene-format.md holds.
std::string registryMarkdown(const ModuleRegistry& registry);

}  // namespace soak

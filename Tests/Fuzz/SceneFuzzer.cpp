// libFuzzer target: the scene loader (XML parsing, element and attribute
// checks, value parsing, overrides) on arbitrary bytes. Anything may be
// refused with InputError; nothing may crash, leak or hit undefined
// behaviour (the sanitize preset builds this with ASan and UBSan).
#include <cstddef>
#include <cstdint>
#include <string>

#include "Base/Error.h"
#include "Simulation/ElementGroups.h"
#include "Simulation/LoadedScene.h"

namespace {
soak::ModuleRegistry& registry() {
  static soak::ModuleRegistry* r = [] {
    auto* reg = new soak::ModuleRegistry;
    soak::registerCoreElements(*reg);
    static soak::PluginLoader loader(*reg);
    soak::loadStandardPlugins(loader, {});
    return reg;
  }();
  return *r;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The first line, if it starts with "--set ", is an override (so that the
  // override parser is fuzzed too); the rest is the scene.
  std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> overrides;
  if (text.rfind("--set ", 0) == 0) {
    const std::size_t eol = text.find('\n');
    overrides.push_back(text.substr(6, eol == std::string::npos ? std::string::npos : eol - 6));
    text = eol == std::string::npos ? std::string() : text.substr(eol + 1);
  }
  // Plugins named by the scene are refused: the fuzzer must not dlopen files.
  const soak::PluginRequest noPlugins = [](const std::string& what, bool, const std::string& where) {
    throw soak::InputError("plugin '" + what + "' not loaded while fuzzing", where);
  };
  try {
    soak::Scene scene = soak::Scene::parse(text, "fuzz.xml", overrides, registry(), noPlugins);
    for (const soak::SceneElement& e : scene.elements()) (void)e.decl->factory(e.params);
  } catch (const soak::InputError&) {
  }
  return 0;
}

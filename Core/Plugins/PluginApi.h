#pragma once
// What a plugin library exports. A plugin is a shared library that defines
//
//   SOAK_PLUGIN(WetCloth) { registry.add(ElementDecl(...)...); }
//
// Loading it (plugin directory, --plugin PATH, or <Plugin .../> in a scene)
// calls that function with the program's registry. No static initialisers
// and no singletons are involved, so the library can be loaded and unloaded
// freely.
#include "Registry/ModuleRegistry.h"

#define SOAK_PLUGIN_API_VERSION 1

// The Soak version a plugin was compiled against. Plugins share C++ types
// (Simulation, views, the registry) with the program, so the loader takes
// only plugins built against its own version (InputError, exit 2, otherwise).
#ifndef SOAK_PLUGIN_BUILT_FOR
#define SOAK_PLUGIN_BUILT_FOR SOAK_VERSION
#endif

#define SOAK_PLUGIN(NAME)                                                                          \
  static void soakPluginRegister_##NAME(soak::ModuleRegistry& registry);                        \
  extern "C" __attribute__((visibility("default"))) int soakPluginApiVersion() {                 \
    return SOAK_PLUGIN_API_VERSION;                                                               \
  }                                                                                               \
  extern "C" __attribute__((visibility("default"))) const char* soakPluginName() { return #NAME; } \
  extern "C" __attribute__((visibility("default"))) const char* soakPluginBuiltFor() { return SOAK_PLUGIN_BUILT_FOR; } \
  extern "C" __attribute__((visibility("default"))) void soakPluginRegister(soak::ModuleRegistry* r) { \
    soakPluginRegister_##NAME(*r);                                                                \
  }                                                                                               \
  static void soakPluginRegister_##NAME(soak::ModuleRegistry& registry)

#pragma once
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "Backend/Device.h"
#include "Plugins/PluginLoader.h"
#include "Scene/Scene.h"
#include "Simulation/Simulation.h"

// Skips (visibly) where no GPU is present; the reason is printed.
#define SOAK_SKIP_WITHOUT_GPU()                                         \
  do {                                                                  \
    std::string why_;                                                   \
    if (!soak::cudaDeviceAvailable(&why_)) GTEST_SKIP() << "no GPU: " << why_; \
  } while (0)

namespace soak::test {

// A registry with Core's elements and, if `pluginDir` is given, every plugin in it.
struct TestRegistry {
  ModuleRegistry registry;
  PluginLoader loader{registry};
  explicit TestRegistry(const std::string& pluginDir = {});
};

// Builds and initializes a simulation from scene XML text.
std::unique_ptr<Simulation> makeSimulation(const std::string& sceneXml, Device device, TestRegistry& reg,
                                           const std::vector<std::string>& overrides = {});

}  // namespace soak::test

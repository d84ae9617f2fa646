#include "Output/CatalystLoader.h"

#include <dlfcn.h>
#include <sys/stat.h>

#include <cstdlib>

#include "Base/Error.h"

namespace soak {

namespace {
// What libsoak_catalyst.so exports (Output/Catalyst/CatalystEntry.cpp).
using CreateFn = FrameSink* (*)(const CatalystSettings*, const char*, std::string*);
using BuiltForFn = const char* (*)();
}  // namespace

std::string catalystLibraryPath() {
  if (const char* env = std::getenv("SOAK_CATALYST_LIBRARY"); env && *env) return env;
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&catalystLibraryPath), &info) != 0 && info.dli_fname) {
    const std::string core(info.dli_fname);
    const std::size_t slash = core.find_last_of('/');
    if (slash != std::string::npos) return core.substr(0, slash) + "/libsoak_catalyst.so";
  }
  return "libsoak_catalyst.so";
}

std::unique_ptr<FrameSink> loadCatalyst(const CatalystSettings& settings, const std::string& runDirectory) {
  const std::string path = catalystLibraryPath();
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw InputError("Catalyst was asked for, but its adaptor " + path +
                         " is not there: this Soak was built without ParaView's Catalyst (Debian: paraview-dev, "
                         "python3-paraview; bash Demos/scripts/install-deps.sh)",
                     settings.where);
  // RTLD_GLOBAL: ParaView's Python modules, imported by the scripts, must
  // find the VTK and ParaView libraries the adaptor brought in.
  void* h = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
  if (!h)
    throw InputError(std::string("cannot load the Catalyst adaptor (is ParaView 5.11 installed? Debian: paraview, "
                                 "python3-paraview): ") + dlerror(),
                     settings.where);
  auto create = reinterpret_cast<CreateFn>(dlsym(h, "soakCatalystCreate"));
  auto builtFor = reinterpret_cast<BuiltForFn>(dlsym(h, "soakCatalystBuiltFor"));
  if (!create || !builtFor) throw InputError("'" + path + "' is not Soak's Catalyst adaptor", settings.where);
  if (std::string(builtFor()) != SOAK_VERSION)
    throw InputError("the Catalyst adaptor " + path + " was built for Soak " + builtFor() + ", this is Soak " +
                         SOAK_VERSION,
                     settings.where);
  std::string error;
  FrameSink* sink = create(&settings, runDirectory.c_str(), &error);
  if (!sink) throw InputError(error);  // the adaptor's message names the file
  return std::unique_ptr<FrameSink>(sink);
}

}  // namespace soak

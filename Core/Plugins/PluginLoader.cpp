#include "Plugins/PluginLoader.h"

#include <dirent.h>
#include <dlfcn.h>
#include <limits.h>
#include <unistd.h>

#include <algorithm>
#include <sys/stat.h>

#include "Base/Error.h"
#include "Plugins/PluginApi.h"

namespace soak {

PluginLoader::~PluginLoader() {
  // Libraries are deliberately kept loaded until exit: modules and stage
  // closures created from them may outlive the loader.
}

void PluginLoader::loadFile(const std::string& path, const std::string& where) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) throw InputError("plugin library '" + path + "' does not exist", where);
  // A name without a slash would send dlopen to the library search path:
  // the file meant is the one beside us.
  const std::string file = path.find('/') == std::string::npos ? "./" + path : path;
  void* h = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!h) throw InputError(std::string("cannot load plugin '") + path + "': " + dlerror(), where);
  if (std::find(handles_.begin(), handles_.end(), h) != handles_.end()) {
    dlclose(h);
    return;
  }
  using VersionFn = int (*)();
  using NameFn = const char* (*)();
  using RegisterFn = void (*)(ModuleRegistry*);
  auto version = reinterpret_cast<VersionFn>(dlsym(h, "soakPluginApiVersion"));
  auto name = reinterpret_cast<NameFn>(dlsym(h, "soakPluginName"));
  auto reg = reinterpret_cast<RegisterFn>(dlsym(h, "soakPluginRegister"));
  auto builtFor = reinterpret_cast<NameFn>(dlsym(h, "soakPluginBuiltFor"));
  if (!version || !name || !reg) {
    dlclose(h);
    throw InputError("'" + path + "' is not a Soak plugin (no soakPluginRegister entry point)", where);
  }
  if (version() != SOAK_PLUGIN_API_VERSION) {
    int v = version();
    dlclose(h);
    throw InputError("plugin '" + path + "' was built for plugin API " + std::to_string(v) + ", this program has " +
                         std::to_string(SOAK_PLUGIN_API_VERSION),
                     where);
  }
  const std::string against = builtFor ? builtFor() : "an unknown version";
  if (!builtFor || against != SOAK_VERSION) {
    dlclose(h);
    throw InputError("plugin '" + path + "' was built against Soak " + against + ", this is Soak " + SOAK_VERSION +
                         ": rebuild it against this Soak (find_package(Soak " + SOAK_VERSION + "))",
                     where);
  }
  handles_.push_back(h);
  if (registry_.hasPlugin(name())) return;
  registry_.setProvider(name());
  try {
    reg(&registry_);
  } catch (const std::exception& e) {
    registry_.setProvider("Core");
    throw InputError("plugin '" + path + "' failed to register: " + e.what(), where);
  }
  registry_.setProvider("Core");
  registry_.notePlugin(name(), path);
}

void PluginLoader::loadByName(const std::string& name, const std::string& where) {
  if (registry_.hasPlugin(name)) return;
  std::string tried;
  for (const std::string& d : dirs_) {
    std::string file = d + "/libsoak_" + name + ".so";
    struct stat st {};
    if (stat(file.c_str(), &st) == 0) return loadFile(file, where);
    tried += (tried.empty() ? "" : ", ") + file;
  }
  throw InputError("plugin '" + name + "' not found (looked for " + (tried.empty() ? "nothing: no plugin directory" : tried) +
                       "); use --plugin PATH or <Plugin path=\"...\"/>",
                   where);
}

void PluginLoader::loadDirectory(const std::string& dir) {
  DIR* d = opendir(dir.c_str());
  if (!d) return;
  std::vector<std::string> files;
  while (dirent* e = readdir(d)) {
    std::string n = e->d_name;
    if (n.rfind("libsoak_", 0) == 0 && n.size() > 3 && n.substr(n.size() - 3) == ".so") files.push_back(dir + "/" + n);
  }
  closedir(d);
  std::sort(files.begin(), files.end());
  for (const std::string& f : files) loadFile(f);
}

std::string defaultPluginDirectory() {
  // Beside the core library: lib/libsoak_core.so and lib/soak-plugins, in
  // the build tree and in a bundle alike, whatever program loaded the core
  // (soak, a test, or Python for the soak module).
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&defaultPluginDirectory), &info) != 0 && info.dli_fname) {
    const std::string lib(info.dli_fname);
    const std::size_t slash = lib.find_last_of('/');
    struct stat st {};
    if (slash != std::string::npos) {
      const std::string dir = lib.substr(0, slash) + "/soak-plugins";
      if (::stat(dir.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) return dir;
    }
  }
  char buf[PATH_MAX];
  ssize_t len = readlink("/proc/self/exe", buf, sizeof(buf) - 1);
  if (len <= 0) return "lib/soak-plugins";
  buf[len] = 0;
  std::string exe(buf);
  std::string dir = exe.substr(0, exe.find_last_of('/'));
  return dir + "/../lib/soak-plugins";
}

}  // namespace soak

#include "XDisplay.h"

#include <dlfcn.h>

#include <cstdlib>

namespace soak {

bool canOpenXDisplay(std::string* why) {
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display) {
    *why = "DISPLAY is not set";
    return false;
  }
  // libX11 through dlopen: the adaptor links nothing of X itself.
  void* x11 = dlopen("libX11.so.6", RTLD_NOW | RTLD_LOCAL);
  if (!x11) {
    *why = std::string("libX11 cannot be loaded: ") + dlerror();
    return false;
  }
  using OpenFn = void* (*)(const char*);
  using CloseFn = int (*)(void*);
  auto open = reinterpret_cast<OpenFn>(dlsym(x11, "XOpenDisplay"));
  auto close = reinterpret_cast<CloseFn>(dlsym(x11, "XCloseDisplay"));
  void* d = open ? open(nullptr) : nullptr;
  if (!d) {
    *why = std::string("the X display '") + display + "' cannot be opened";
    return false;
  }
  close(d);
  return true;
}

}  // namespace soak

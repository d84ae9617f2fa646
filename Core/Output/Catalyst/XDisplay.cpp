#include "XDisplay.h"

#include <dlfcn.h>
#include <unistd.h>

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
  // Xlib's first call in a program that draws from a thread of its own
  // (the Catalyst thread, beside the simulation's).
  using InitThreadsFn = int (*)();
  if (auto initThreads = reinterpret_cast<InitThreadsFn>(dlsym(x11, "XInitThreads"))) initThreads();
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

// ParaView aborts the process when it cannot connect to the X server, and
// an X server under load (Xvfb beside a busy simulation) refuses a few
// connections in a hundred. Defined here, in the library the adaptor's
// dlopen brings ParaView in with, this XOpenDisplay comes before libX11's
// for ParaView's libraries: it tries again for up to two seconds before it
// gives up as libX11's does.
extern "C" __attribute__((visibility("default"))) void* XOpenDisplay(const char* name) {
  using OpenFn = void* (*)(const char*);
  static const OpenFn next = reinterpret_cast<OpenFn>(dlsym(RTLD_NEXT, "XOpenDisplay"));
  if (!next) return nullptr;
  for (int attempt = 0;; ++attempt) {
    if (void* display = next(name)) return display;
    if (attempt == 40) return nullptr;
    usleep(50000);
  }
}

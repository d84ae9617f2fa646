// What libsoak_catalyst.so exports to the core's loader
// (Output/CatalystLoader.cpp).
#include <string>

#include "Base/Error.h"
#include "CatalystAdaptor.h"

extern "C" __attribute__((visibility("default"))) const char* soakCatalystBuiltFor() { return SOAK_VERSION; }

// The started adaptor, or null with `error` set (the message of the
// InputError the loader then throws).
extern "C" __attribute__((visibility("default"))) soak::FrameSink* soakCatalystCreate(
    const soak::CatalystSettings* settings, const char* runDirectory, std::string* error) {
  try {
    return new soak::CatalystAdaptor(*settings, runDirectory);
  } catch (const std::exception& e) {
    *error = e.what();
    return nullptr;
  }
}

#pragma once
// Loads the Catalyst adaptor (libsoak_catalyst.so, Output/Catalyst/) only
// when a run asks for Catalyst, so that the core and every other run stay
// free of ParaView's Python and Catalyst libraries.
#include <memory>
#include <string>

#include "Output/CatalystSettings.h"
#include "Output/FrameSink.h"

namespace soak {

// The adaptor's file: $SOAK_CATALYST_LIBRARY where set, else
// libsoak_catalyst.so beside libsoak_core.so.
std::string catalystLibraryPath();

// Loads the adaptor and starts it: its scripts are read and checked, Live
// is set up. InputError (exit 2) with the reason when the library, ParaView
// or a script cannot be loaded. `runDirectory` is the run's output folder
// (scripts find it in $SOAK_OUTPUT).
std::unique_ptr<FrameSink> loadCatalyst(const CatalystSettings& settings, const std::string& runDirectory);

}  // namespace soak

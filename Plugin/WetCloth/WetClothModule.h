#pragma once
#include <memory>
#include <string>

#include "Drying.h"
#include "Registry/Module.h"
#include "WetParams.h"

namespace soak::wet {

// The module <WetCloth> makes: sets the wetting state up (channels,
// per-vertex arrays, the core's fields it writes), inserts the stages
// (Stages/StageTable.cpp), places the drips at each step's start, keeps
// its state in checkpoints and adds its stats.csv columns.
std::unique_ptr<Module> makeWetClothModule(const WetParams& params, const DryingParams& drying,
                                           const std::string& where);

}  // namespace soak::wet

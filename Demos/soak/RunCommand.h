#pragma once
#include "Arguments.h"

namespace soak::cli {

// `soak run`: returns the exit code.
int runCommand(const RunArguments& args);
// `soak params`: prints the registry as Markdown (plugins from the plugin dir
// and --plugin PATH arguments included).
int paramsCommand(const std::vector<std::string>& args);
// `soak version`.
int versionCommand();

}  // namespace soak::cli

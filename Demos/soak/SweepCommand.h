#pragma once
// `soak sweep plan|run|status|collect|task` (Doc/sweeps.md).
#include <string>
#include <vector>

namespace soak::cli {

// The arguments after "sweep"; returns the exit code. Throws InputError
// for a bad command line or sweep description.
int sweepCommand(const std::vector<std::string>& args);

extern const char* kSweepUsage;

}  // namespace soak::cli

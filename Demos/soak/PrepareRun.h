#pragma once
// The first half of `soak run`: everything that can fail because of the
// input (the options, the scene and its meshes, the limits, the output
// folder, the checkpoint of a resumed run), done without writing anything.
// runCommand writes only once this has returned; the command-line fuzzer
// (Tests/Fuzz/CliFuzzer.cpp) drives it with arbitrary arguments.
#include <memory>
#include <optional>
#include <string>

#include "Arguments.h"
#include "Checkpoint/Checkpoint.h"
#include "Output/RunFolder.h"
#include "Simulation/LoadedScene.h"
#include "Simulation/Runner.h"

namespace soak::cli {

struct PreparedRun {
  Device device = Device::Cpu;
  std::string out;                       // the output folder
  FolderClaim claim = FolderClaim::Fresh;  // how the run takes it (RunFolder.h)
  std::optional<Checkpoint> checkpoint;  // when resuming
  std::unique_ptr<LoadedScene> loaded;
  RunOptions options;
  int plannedFrames = 0;
};

// Throws InputError (or DeviceError) on anything the run would refuse.
PreparedRun prepareRun(const RunArguments& args);

}  // namespace soak::cli

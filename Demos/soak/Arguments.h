#pragma once
#include <string>
#include <vector>

namespace soak::cli {

// Exit codes of the soak program (documented in README and Doc/cli.md).
enum ExitCode {
  kExitOk = 0,
  kExitInternal = 1,    // a bug or an unexpected failure
  kExitInput = 2,       // bad scene, mesh, option or output folder; nothing written
  kExitDevice = 3,      // the device asked for is unavailable or failed
  kExitUnstable = 4,    // the simulation went unstable (NaN, runaway speed)
  kExitStorage = 5,     // the machine failed a write: disk full, read-only, folder removed, permission, I/O
  kExitInterrupted = 130,
};

// Most CPU threads --threads may ask for (frames: Runner.h's kMaxRunFrames).
constexpr int kMaxThreads = 1024;

struct RunArguments {
  std::string scene;
  std::string output;      // empty: soak-out/<scene stem>
  std::string device = "auto";
  int frames = -1;
  double time = -1.0;
  std::vector<std::string> overrides;
  std::vector<std::string> plugins;
  bool profile = false;
  bool quiet = false;
  bool checkStages = false;
  int threads = 0;
  int checkpointEvery = 0;  // 0: no checkpoints
  std::string resume;       // output folder of a run to continue
  bool overwrite = false;   // replace the run already in the output folder
  std::vector<std::string> catalystScripts;  // --catalyst SCRIPT.py (repeatable)
  int catalystEvery = 0;    // --catalyst-every N; 0: the scene's (<Catalyst every>), else 1
  std::string live;         // --live HOST:PORT
};

// Parses the arguments after "run". Throws InputError with usage help.
RunArguments parseRunArguments(const std::vector<std::string>& args);

extern const char* kUsage;

}  // namespace soak::cli

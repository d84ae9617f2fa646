// libFuzzer target: `soak run`'s command line (parseRunArguments and
// prepareRun: options, overrides, the scene and meshes they name, limits,
// the output folder, a resumed run's checkpoint) on arbitrary bytes, one
// argument per line. Everything must be refused with InputError or
// DeviceError, or prepared; nothing may crash, leak or hit undefined
// behaviour. prepareRun writes nothing, so no input can write a file.
//
// The seeds name scenes under cli_files/ and the sample run in
// cli_fuzz_run/ (FuzzRun.h), made at start. --plugin is not followed (it
// would load arbitrary files as code). A run that is not resumed gets
// Simulation.maxParticles=20000 last, so that a scene may not take the
// fuzzer's memory.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "Base/Error.h"
#include "FuzzRun.h"
#include "PrepareRun.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  soak::fuzz::writeSampleRun("cli_fuzz_run");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args;
  std::string arg;
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == '\n') {
      args.push_back(arg);
      arg.clear();
    } else {
      arg += char(data[i]);
    }
  }
  if (!arg.empty()) args.push_back(arg);
  bool resume = false;
  for (const std::string& a : args) {
    if (a == "--plugin") return 0;
    resume = resume || a == "--resume";
  }
  if (!resume) args.insert(args.end(), {"--set", "Simulation.maxParticles=20000"});
  try {
    const soak::cli::RunArguments parsed = soak::cli::parseRunArguments(args);
    (void)soak::cli::prepareRun(parsed);
  } catch (const soak::InputError&) {
  } catch (const soak::DeviceError&) {
  }
  return 0;
}

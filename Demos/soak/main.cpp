// soak: the command-line program. See `soak help`.
#include <malloc.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "Arguments.h"
#include "Base/Error.h"
#include "RunCommand.h"
#include "SweepCommand.h"

int main(int argc, char** argv) {
  using namespace soak::cli;
  // The frame writer threads (Output.writerThreads) build each frame's
  // files in memory. glibc gives every thread a malloc arena of its own and
  // keeps what is freed in it, so with eight writers a long GPU run's
  // resident memory grew by 12 MiB over its first 10,000 steps; in two
  // arenas it grew by 4 MiB, at the same speed (Doc/reliability.md, "Long
  // runs"). MALLOC_ARENA_MAX in the environment still decides.
  if (!std::getenv("MALLOC_ARENA_MAX")) mallopt(M_ARENA_MAX, 2);
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "help" || args[0] == "--help" || args[0] == "-h") {
    std::fputs(kUsage, args.empty() ? stderr : stdout);
    return args.empty() ? kExitInput : kExitOk;
  }
  const std::string cmd = args[0];
  std::vector<std::string> rest(args.begin() + 1, args.end());
  try {
    if (cmd == "run") return runCommand(parseRunArguments(rest));
    if (cmd == "params") return paramsCommand(rest);
    if (cmd == "sweep") return sweepCommand(rest);
    if (cmd == "version" || cmd == "--version") return versionCommand();
    std::fprintf(stderr, "soak: unknown command '%s'\n\n%s", cmd.c_str(), kUsage);
    return kExitInput;
  } catch (const soak::InputError& e) {
    std::fprintf(stderr, "soak: error: %s\n", e.what());
    return kExitInput;
  } catch (const soak::StorageError& e) {
    std::fprintf(stderr, "soak: %s\n", e.what());
    return kExitStorage;
  } catch (const soak::DeviceError& e) {
    std::fprintf(stderr, "soak: device error: %s\n", e.what());
    return kExitDevice;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "soak: internal error: %s\n", e.what());
    return kExitInternal;
  }
}

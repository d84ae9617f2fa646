#include "RunCommand.h"

#include <omp.h>

#include <csignal>
#include <cstdio>
#include <iostream>

#include "Base/Error.h"
#include "Output/FrameWriter.h"
#include "Plugins/PluginLoader.h"
#include "ProgressReport.h"
#include "Scene/Scene.h"
#include "Simulation/Instability.h"
#include "Simulation/LoadedScene.h"
#include "Simulation/Runner.h"
#include "Simulation/Simulation.h"

namespace soak::cli {

namespace {
volatile std::sig_atomic_t g_interrupted = 0;
void onSigint(int) { g_interrupted = 1; }

std::string sceneStem(const std::string& path) {
  std::size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  std::size_t dot = name.find_last_of('.');
  return dot == std::string::npos ? name : name.substr(0, dot);
}

void printProfile(const Simulation& sim) {
  double total = 0.0, wetting = 0.0;
  for (const StageTiming& t : sim.pipeline.timings()) {
    total += t.meanMs();
    if (t.name.rfind("wet.", 0) == 0) wetting += t.meanMs();
  }
  std::printf("\nper-stage mean time (ms per step, device %s, %d particles at the end):\n",
              deviceName(sim.device()), sim.particles.count());
  std::printf("  %-22s %10s %7s\n", "stage", "ms", "share");
  for (const StageTiming& t : sim.pipeline.timings())
    std::printf("  %-22s %10.4f %6.1f%%\n", t.name.c_str(), t.meanMs(), total > 0 ? 100.0 * t.meanMs() / total : 0.0);
  std::printf("  %-22s %10.4f\n", "wetting (wet.*)", wetting);
  std::printf("  %-22s %10.4f\n", "total", total);
}
}  // namespace

int runCommand(const RunArguments& args) {
  if (args.threads > 0) omp_set_num_threads(args.threads);
  // Everything that can fail because of the input happens before the output
  // folder is touched: parse, validate, build the simulation.
  const Device device = resolveDevice(args.device);
  std::unique_ptr<LoadedScene> loaded = loadScene({args.scene, "", args.overrides, args.plugins}, device);
  Simulation& sim = *loaded->sim;
  const Scene& scene = loaded->scene;

  RunOptions options;
  options.frames = args.frames;
  options.time = args.time;
  options.profile = args.profile;

  const std::string out = args.output.empty() ? "soak-out/" + sceneStem(args.scene) : args.output;
  FrameWriter writer(out, scene.textAsRun());
  Runner writingRunner(sim, &writer);

  if (!args.quiet) {
    std::fprintf(stderr, "soak: %s on %s%s, %d particles, dt=%g s, %d frames -> %s\n", args.scene.c_str(),
                 deviceName(device), device == Device::Cuda ? (" (" + cudaDeviceDescription() + ")").c_str() : "",
                 sim.particles.count(), double(sim.settings.timeStep), writingRunner.plannedFrames(options), out.c_str());
  }
  std::signal(SIGINT, onSigint);
  ProgressReport progress(args.quiet);
  sim.checkStages = args.checkStages;
  RunProgress result;
  try {
    result = writingRunner.run(options, [&](const RunProgress& p) {
      progress.update(p);
      if (g_interrupted) writingRunner.requestStop();
    });
  } catch (const InstabilityError& e) {
    progress.finish();
    std::fprintf(stderr, "soak: %s\n      frames 0-%d (t <= %.4f s) are kept in %s%s\n", e.what(),
                 writer.framesWritten() - 1, (writer.framesWritten() - 1) / sim.settings.frameRate, out.c_str(),
                 sim.checkStages ? "" : "; run again with --check-stages to name the stage where it starts");
    return kExitUnstable;
  }
  progress.finish();
  std::signal(SIGINT, SIG_DFL);

  if (!args.quiet) {
    std::fprintf(stderr,
                 "soak: %s: %d frames, %lld steps, %.1f s wall, %.1f steps/s; output in %s\n"
                 "      open in ParaView: paraview %s/water.pvd\n",
                 g_interrupted ? "interrupted" : "done", writer.framesWritten(), result.steps, result.wallSeconds,
                 result.stepsPerSecond, out.c_str(), out.c_str());
  }
  if (args.profile) printProfile(sim);
  return g_interrupted ? kExitInterrupted : kExitOk;
}

int paramsCommand(const std::vector<std::string>& args) {
  ModuleRegistry registry;
  registerCoreElements(registry);
  PluginLoader loader(registry);
  std::vector<std::string> plugins;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--plugin" && i + 1 < args.size()) plugins.push_back(args[++i]);
    else throw InputError("soak params: unknown argument '" + args[i] + "'");
  }
  loadStandardPlugins(loader, plugins);
  std::cout << registryMarkdown(registry);
  return kExitOk;
}

int versionCommand() {
  std::printf("soak %s\n", SOAK_VERSION);
  std::printf("backends: cpu (OpenMP, %d threads)", omp_get_max_threads());
  if (cudaBackendBuilt()) {
    std::string why;
    bool ok = cudaDeviceAvailable(&why);
    std::printf(", cuda (built; %s)\n", ok ? ("GPU: " + cudaDeviceDescription()).c_str() : why.c_str());
  } else {
    std::printf("\nthis is a CPU-only build (configured without the CUDA toolkit)\n");
  }
  return kExitOk;
}

}  // namespace soak::cli

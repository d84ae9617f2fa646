#include "RunCommand.h"

#include <omp.h>
#include <unistd.h>

#include <algorithm>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "Base/Error.h"
#include "Base/ReadInput.h"
#include "Checkpoint/Checkpoint.h"
#include "Output/CatalystLoader.h"
#include "Output/FrameWriter.h"
#include "Output/OutputFolder.h"
#include "Output/RunFolder.h"
#include "Plugins/PluginLoader.h"
#include "PrepareRun.h"
#include "ProgressReport.h"
#include "Scene/Scene.h"
#include "Simulation/Instability.h"
#include "Simulation/LoadedScene.h"
#include "Simulation/Runner.h"
#include "Simulation/Simulation.h"

namespace soak::cli {

namespace {
volatile std::sig_atomic_t g_interrupted = 0;

bool pathExists(const std::string& path) { return ::access(path.c_str(), F_OK) == 0; }
// SIGINT or SIGTERM: finish the frame under way, write it (and a checkpoint
// when asked for), then stop. A second signal ends the program at once.
void onInterrupt(int signal) {
  g_interrupted = 1;
  std::signal(signal, SIG_DFL);
}

// The collections a run writes, for the closing message.
std::string pvdList(const Simulation& sim, const std::string& out) {
  std::string list = out + "/water.pvd";
  for (const ClothObject& c : sim.cloth.objects()) list += " " + out + "/cloth_" + c.name + ".pvd";
  return list;
}

// Stages named "group.stage" are also summed per group of two or more
// (wet.*: every stage of the WetCloth plugin).
void printProfile(const Simulation& sim) {
  struct Group {
    std::string name;
    double ms = 0.0;
    int stages = 0;
  };
  double total = 0.0;
  std::vector<Group> groups;  // in order of their first stage
  for (const StageTiming& t : sim.pipeline.timings()) {
    total += t.meanMs();
    const std::size_t dot = t.name.find('.');
    if (dot == std::string::npos) continue;
    const std::string group = t.name.substr(0, dot);
    auto g = std::find_if(groups.begin(), groups.end(), [&](const Group& e) { return e.name == group; });
    if (g == groups.end()) g = groups.insert(groups.end(), Group{group});
    g->ms += t.meanMs();
    ++g->stages;
  }
  std::printf("\nper-stage mean time (ms per step, device %s, %d particles at the end):\n",
              deviceName(sim.device()), sim.particles.count());
  std::printf("  %-22s %10s %7s\n", "stage", "ms", "share");
  for (const StageTiming& t : sim.pipeline.timings())
    std::printf("  %-22s %10.4f %6.1f%%\n", t.name.c_str(), t.meanMs(), total > 0 ? 100.0 * t.meanMs() / total : 0.0);
  for (const Group& g : groups)
    if (g.stages > 1) std::printf("  %-22s %10.4f\n", (g.name + ".* together").c_str(), g.ms);
  std::printf("  %-22s %10.4f\n", "total", total);
}

// The scene's <Catalyst> with the command line's scripts added and its
// --catalyst-every and --live in place of the scene's.
CatalystSettings catalystFor(const RunArguments& args, CatalystSettings s) {
  for (const std::string& script : args.catalystScripts) s.scripts.push_back(script);
  if (args.catalystEvery > 0) s.every = args.catalystEvery;
  if (!args.live.empty()) s.live = args.live;
  return s;
}

}  // namespace

int runCommand(const RunArguments& args) {
  // Threads: --threads, else OMP_NUM_THREADS, else the CPUs this process may
  // use (affinity, SLURM_CPUS_PER_TASK, the cgroup's cpu.max; ProcessLimits.h).
  std::string threadSource = "--threads";
  if (args.threads > 0) omp_set_num_threads(args.threads);
  else if (const char* env = std::getenv("OMP_NUM_THREADS"); env && *env) threadSource = "OMP_NUM_THREADS";
  else omp_set_num_threads(usableCpuCount(&threadSource));
  // Everything that can fail because of the input happens before the output
  // folder is touched (PrepareRun.h).
  PreparedRun run = prepareRun(args);
  const Device device = run.device;
  const std::string& out = run.out;
  std::optional<Checkpoint>& checkpoint = run.checkpoint;
  Simulation& sim = *run.loaded->sim;
  const Scene& scene = run.loaded->scene;
  RunOptions& options = run.options;
  const int planned = run.plannedFrames;

  // Catalyst (<Catalyst>, --catalyst, --live): loaded and its scripts
  // checked before anything is written; it outlives the writer.
  std::unique_ptr<FrameSink> catalyst;
  const CatalystSettings catalystSettings = catalystFor(args, sim.settings.catalyst);
  if (catalystSettings.wanted()) catalyst = loadCatalyst(catalystSettings, out);

  // The folder is the run's from here on (RunFolder.h): created, locked
  // until the process ends, and an earlier run removed with --overwrite.
  const RunFolderLock folderLock = claimRunFolder(out, run.claim);
  FrameWriter writer(out, scene.textAsRun(), checkpoint ? FrameWriter::Start::Resume : FrameWriter::Start::Fresh,
                     sim.settings.output);
  writer.attachSink(catalyst.get());
  Runner writingRunner(sim, &writer);
  if (checkpoint) {
    checkpoint->restore(writer, sim);
    if (!args.quiet)
      std::fprintf(stderr, "soak: resuming %s at frame %d (t = %.4f s, step %lld), written on %s\n", out.c_str(),
                   options.startFrame, sim.time(), sim.stepIndex(), checkpoint->header().device.c_str());
  }

  if (!args.quiet) {
    std::fprintf(stderr, "soak: %s on %s%s, %d particles, dt=%g s, %d frames -> %s\n", scene.path().c_str(),
                 deviceName(device), device == Device::Cuda ? (" (" + cudaDeviceDescription() + ")").c_str() : "",
                 sim.particles.count(), double(sim.settings.timeStep), planned, out.c_str());
    if (device == Device::Cpu)
      std::fprintf(stderr, "soak: %d CPU threads (from %s)\n", omp_get_max_threads(), threadSource.c_str());
    const SimulationSettings& set = sim.settings;
    if (!sim.cloth.empty() && set.clothSubstepTravel > 0.f)
      std::fprintf(stderr, "soak: cloth solve: %d to %d dependent phases per step (sub-steps from the cloth's speed)\n",
                   sim.cloth.constraintPhasesPerStep(set.clothIterations, set.clothSubsteps),
                   sim.cloth.constraintPhasesPerStep(set.clothIterations, std::max(set.clothSubsteps, set.clothMaxSubsteps)));
    else if (!sim.cloth.empty())
      std::fprintf(stderr, "soak: cloth solve: %d dependent phases per step\n",
                   sim.cloth.constraintPhasesPerStep(set.clothIterations, set.clothSubsteps));
  }
  std::signal(SIGINT, onInterrupt);
  std::signal(SIGTERM, onInterrupt);
  ProgressReport progress(args.quiet);
  sim.checkStages = args.checkStages;
  RunProgress result;
  bool toldDiskBound = false, toldCatalystBound = false;
  try {
    result = writingRunner.run(options, [&](const RunProgress& p) {
      progress.update(p);
      if (writer.waitedForSink() && !toldCatalystBound && !args.quiet) {
        toldCatalystBound = toldDiskBound = true;
        progress.finish();
        std::fprintf(stderr,
                     "soak: Catalyst's pipelines are slower than the simulation: steps now wait for them "
                     "(--catalyst-every N or <Catalyst every=\"N\"/> runs them on every N-th frame)\n");
      }
      if (writer.waitedForDisk() && !toldDiskBound && !args.quiet) {
        toldDiskBound = true;
        progress.finish();
        std::fprintf(stderr,
                     "soak: frames are written more slowly than they are simulated: steps now wait for the disk "
                     "(a lower Simulation.frameRate, or Output.compression=lz4 or none, writes less)\n");
      }
      if (g_interrupted) writingRunner.requestStop();
    });
  } catch (const StorageError& e) {
    // The frames listed are whole (each file is written under a temporary
    // name and listed after it is on disk): say what is kept and how to go on.
    progress.finish();
    const int kept = writer.framesWritten();
    const bool folderGone = !pathExists(out);
    std::fprintf(stderr, "soak: %s\n", e.what());
    if (folderGone)
      std::fprintf(stderr, "      the output folder %s is gone, and the run with it\n", out.c_str());
    else if (pathExists(out + "/" + kCheckpointFile))
      std::fprintf(stderr,
                   "      frames 0-%d are whole and listed in %s; once the cause is fixed, continue with:\n"
                   "        soak run --resume %s\n",
                   kept - 1, out.c_str(), out.c_str());
    else
      std::fprintf(stderr,
                   "      frames 0-%d are whole and listed in %s; the run kept no checkpoint to resume from "
                   "(--checkpoint-every N keeps one): once the cause is fixed, run it again with --overwrite\n",
                   kept - 1, out.c_str());
    return kExitStorage;
  } catch (const InstabilityError& e) {
    writer.flush();  // the frames before the instability are whole and kept
    progress.finish();
    std::fprintf(stderr, "soak: %s\n      frames 0-%d (t <= %.4f s) are kept in %s%s\n", e.what(),
                 writer.framesWritten() - 1, (writer.framesWritten() - 1) / sim.settings.frameRate, out.c_str(),
                 sim.checkStages ? "" : "; run again with --check-stages to name the stage where it starts");
    return kExitUnstable;
  } catch (const DeviceError& e) {
    // Out of device memory or a failed kernel mid-run: the frames before it
    // are whole and kept, and a checkpoint (if any) resumes the run.
    writer.flush();
    progress.finish();
    const int kept = writer.framesWritten();
    std::fprintf(stderr, "soak: device error: %s\n      frames 0-%d are whole and listed in %s\n", e.what(), kept - 1,
                 out.c_str());
    if (pathExists(out + "/" + kCheckpointFile))
      std::fprintf(stderr, "      once the device has room, continue with: soak run --resume %s\n", out.c_str());
    return kExitDevice;
  }
  progress.finish();
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);

  if (!args.quiet) {
    std::fprintf(stderr,
                 "soak: %s: %d frames, %lld steps, %.1f s wall, %.1f steps/s; output in %s\n"
                 "      open in ParaView: paraview %s\n",
                 g_interrupted ? "interrupted" : "done", writer.framesWritten(), result.steps, result.wallSeconds,
                 result.stepsPerSecond, out.c_str(), pvdList(sim, out).c_str());
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

#include "PrepareRun.h"

#include <cstdlib>

#include "Base/Error.h"
#include "Base/ReadInput.h"
#include "Output/OutputFolder.h"

namespace soak::cli {

namespace {
std::string sceneStem(const std::string& path) {
  std::size_t slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  std::size_t dot = name.find_last_of('.');
  return dot == std::string::npos ? name : name.substr(0, dot);
}

std::string absolutePath(const std::string& path) {
  char* real = ::realpath(path.c_str(), nullptr);
  if (!real) return path;  // loadScene reports a missing file with its own message
  std::string result(real);
  std::free(real);
  return result;
}
}  // namespace

PreparedRun prepareRun(const RunArguments& args) {
  PreparedRun run;
  run.device = resolveDevice(args.device);
  SceneSource source{args.scene, "", args.overrides, args.plugins};
  run.out = args.output.empty() ? "soak-out/" + sceneStem(args.scene) : args.output;
  run.claim = !args.resume.empty() ? FolderClaim::Resume : args.overwrite ? FolderClaim::Overwrite : FolderClaim::Fresh;
  if (!args.resume.empty()) run.out = args.resume;
  if (!args.resume.empty()) {
    run.checkpoint = Checkpoint::read(run.out + "/" + kCheckpointFile);
    const CheckpointHeader& h = run.checkpoint->header();
    if (readInputFile(run.out + "/scene.xml", kMaxSceneBytes, "scene file") != h.sceneText)
      throw InputError("scene.xml differs from the scene the checkpoint was written for; a resumed run continues "
                       "the same scene (start a new run to change it)",
                       run.out + "/scene.xml");
    source = {h.scenePath, h.sceneText, {}, args.plugins};
  }
  run.loaded = loadScene(source, run.device);
  Simulation& sim = *run.loaded->sim;
  const Scene& scene = run.loaded->scene;

  RunOptions& options = run.options;
  options.frames = args.frames;
  options.time = args.time;
  options.profile = args.profile;
  options.checkpointEvery = args.checkpointEvery;
  options.checkpointPath = run.out + "/" + kCheckpointFile;
  options.checkpointHeader.scenePath = run.checkpoint ? run.checkpoint->header().scenePath : absolutePath(args.scene);
  options.checkpointHeader.sceneText = run.checkpoint ? run.checkpoint->header().sceneText : scene.textAsRun();
  options.checkpointHeader.device = deviceName(run.device);
  if (run.checkpoint) {
    const CheckpointHeader& h = run.checkpoint->header();
    options.startFrame = h.frame;
    if (options.frames < 0 && options.time < 0) options.frames = h.plannedFrames;
    if (options.checkpointEvery == 0) options.checkpointEvery = h.checkpointEvery;
  }
  options.checkpointHeader.checkpointEvery = options.checkpointEvery;
  checkOutputFolder(run.out, scene.inputFiles());
  // A folder that holds another run, or that a running run holds, is
  // refused before anything is written (RunFolder.h).
  checkRunFolderClaim(run.out, run.claim);
  run.plannedFrames = Runner(sim, nullptr).plannedFrames(options);
  sim.checkPlannedParticles(run.plannedFrames / sim.settings.frameRate);
  if (run.checkpoint && run.plannedFrames <= options.startFrame)
    throw InputError("the run already reached frame " + std::to_string(options.startFrame) +
                         "; give --frames N (N > " + std::to_string(options.startFrame) + ") or --time to extend it",
                     run.out + "/" + kCheckpointFile);
  return run;
}

}  // namespace soak::cli

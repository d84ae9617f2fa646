#pragma once
// What the command-line and checkpoint fuzzers share: a small scene that
// has every kind of state a checkpoint holds (water, a jet, cloth, wetting),
// and a finished run of it with its frames and checkpoint, made once per
// fuzzer process, so that a resume can get past the folder checks.
#include <string>

#include "Checkpoint/Checkpoint.h"
#include "Output/FrameWriter.h"
#include "Simulation/LoadedScene.h"
#include "Simulation/Runner.h"

namespace soak::fuzz {

inline const char* kSampleScene = R"(<Scene>
  <Simulation duration="0.1" maxParticles="20000" maxCellParticles="64"/>
  <WaterBlock min="-0.05 0.1 -0.05" max="0.05 0.16 0.05"/>
  <Nozzle position="0 0.3 0" radius="0.02" speed="2"/>
  <Cloth cellsU="6" cellsV="6" width="0.3" height="0.3" origin="-0.15 0 -0.15" axisU="1 0 0" axisV="0 0 1"
         pinCorners="u0v0 u1v1"/>
  <WetCloth/>
  <Plane point="0 -0.5 0"/>
</Scene>
)";

// Writes a three-frame run of kSampleScene, with a checkpoint after each
// frame, into `dir` (made fresh), and returns it built and stepped.
inline std::unique_ptr<LoadedScene> writeSampleRun(const std::string& dir) {
  std::system(("rm -rf '" + dir + "'").c_str());
  auto loaded = loadScene({dir + "/sample.xml", kSampleScene, {}, {}}, Device::Cpu);
  FrameWriter writer(dir, loaded->scene.textAsRun());
  RunOptions options;
  options.frames = 3;
  options.checkpointEvery = 1;
  options.checkpointPath = dir + "/" + kCheckpointFile;
  options.checkpointHeader.scenePath = dir + "/sample.xml";
  options.checkpointHeader.sceneText = loaded->scene.textAsRun();
  options.checkpointHeader.device = "cpu";
  options.checkpointHeader.checkpointEvery = 1;
  Runner(*loaded->sim, &writer).run(options);
  return loaded;
}

}  // namespace soak::fuzz

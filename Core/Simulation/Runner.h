#pragma once
#include <functional>
#include <string>

#include "Backend/Buffer.h"
#include "Checkpoint/Checkpoint.h"

namespace soak {

class Simulation;
class FrameWriter;

// Most output frames one run may plan (--frames, --time x frameRate).
constexpr int kMaxRunFrames = 10000000;

struct RunOptions {
  int frames = -1;     // output frames after frame 0; -1: from duration
  double time = -1.0;  // simulated seconds; -1: from the scene
  bool profile = false;
  // Resuming: the frame the checkpoint was written at (frames up to it are
  // on disk; the run continues with the next). 0: a fresh run.
  int startFrame = 0;
  // Write a checkpoint every N frames (0: never), and also after the last
  // frame and when stopped early, to `checkpointPath`. `checkpointHeader`
  // carries the scene; the runner fills in the frames.
  int checkpointEvery = 0;
  std::string checkpointPath;
  CheckpointHeader checkpointHeader;
};

struct RunProgress {
  int frame = 0, frames = 0;  // the frame simulated last, of frames
  int framesWritten = 0;      // frames on disk (frame 0 counts; queued frames do not)
  double simTime = 0.0, endTime = 0.0;
  long long steps = 0;
  double stepsPerSecond = 0.0;
  double etaSeconds = 0.0;
  double wallSeconds = 0.0;
};

// Steps a simulation frame by frame, writing each frame (frame 0 is the
// initial state). Frames are at multiples of 1/frameRate, independent of
// the time step: a frame is written at the first step at or past its time.
class Runner {
 public:
  Runner(Simulation& sim, FrameWriter* writer);
  // Returns the final progress. `onFrame` is called after every frame.
  // Before a frame is written the particles are checked (Instability.h): an
  // unstable state throws InstabilityError and is not written, so the
  // frames on disk are the sound ones.
  RunProgress run(const RunOptions& options, const std::function<void(const RunProgress&)>& onFrame = {});
  // Stop after the current frame (e.g. from a signal handler flag).
  void requestStop() { stop_ = true; }
  // Number of frames the options and scene ask for (after frame 0);
  // InputError beyond kMaxRunFrames.
  int plannedFrames(const RunOptions& options) const;

 private:
  Simulation& sim_;
  FrameWriter* writer_;
  Buffer<float> scratch_;
  volatile bool stop_ = false;
};

}  // namespace soak

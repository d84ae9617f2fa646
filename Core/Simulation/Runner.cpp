#include "Simulation/Runner.h"

#include "Base/Error.h"

#include <chrono>
#include <cmath>

#include "Output/FrameWriter.h"
#include "Simulation/Instability.h"
#include "Simulation/Simulation.h"

namespace soak {

Runner::Runner(Simulation& sim, FrameWriter* writer) : sim_(sim), writer_(writer), scratch_(sim.device()) {}

int Runner::plannedFrames(const RunOptions& o) const {
  if (o.frames >= 0) return o.frames;
  double t = o.time >= 0.0 ? o.time : sim_.settings.duration;
  const double frames = std::floor(t * sim_.settings.frameRate + 1e-9);
  if (!(frames <= double(kMaxRunFrames)))
    throw InputError("the run would write " + std::to_string(frames) + " frames (" + std::to_string(t) +
                     " s at " + std::to_string(sim_.settings.frameRate) + " frames per second); at most " +
                     std::to_string(kMaxRunFrames) + " frames per run: shorten the run or lower Simulation.frameRate");
  return static_cast<int>(frames);
}

RunProgress Runner::run(const RunOptions& o, const std::function<void(const RunProgress&)>& onFrame) {
  using Clock = std::chrono::steady_clock;
  RunProgress p;
  p.frames = plannedFrames(o);
  p.endTime = p.frames / sim_.settings.frameRate;
  const auto start = Clock::now();
  p.frame = o.startFrame;
  p.simTime = sim_.time();
  if (o.startFrame == 0 && writer_) writer_->writeFrame(sim_, 0, 0.0);
  p.framesWritten = writer_ ? writer_->framesWritten() : o.startFrame + 1;
  if (onFrame) onFrame(p);
  const long long firstStep = sim_.stepIndex();
  for (int f = o.startFrame + 1; f <= p.frames && !stop_; ++f) {
    const double target = f / sim_.settings.frameRate;
    const auto t0 = Clock::now();
    int steps = 0;
    while (sim_.time() < target - 1e-6 * sim_.settings.timeStep) {
      sim_.step(o.profile);
      ++steps;
    }
    synchronize(sim_.device());
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    const Instability bad = findInstability(sim_, scratch_);
    if (bad.found) throw InstabilityError(bad, describeInstability(bad, sim_.settings.maxSpeed));
    if (writer_) writer_->writeFrame(sim_, f, steps ? ms / steps : 0.0);
    p.frame = f;
    p.framesWritten = writer_ ? writer_->framesWritten() : f + 1;
    p.simTime = sim_.time();
    p.steps = sim_.stepIndex() - firstStep;
    p.wallSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    p.stepsPerSecond = p.wallSeconds > 0 ? double(p.steps) / p.wallSeconds : 0.0;
    const int done = p.frame - o.startFrame;
    p.etaSeconds = done > 0 ? p.wallSeconds / done * (p.frames - p.frame) : 0.0;
    if (onFrame) onFrame(p);
    if (writer_ && o.checkpointEvery > 0 && (f % o.checkpointEvery == 0 || f == p.frames || stop_)) {
      writer_->flush();  // the checkpoint lists the frames on disk
      p.framesWritten = writer_->framesWritten();
      CheckpointHeader h = o.checkpointHeader;
      h.frame = f;
      h.plannedFrames = p.frames;
      writeCheckpoint(o.checkpointPath, h, *writer_, sim_);
    }
  }
  if (writer_) {
    const int before = p.framesWritten;
    writer_->flush();
    p.framesWritten = writer_->framesWritten();
    if (onFrame && p.framesWritten != before) onFrame(p);  // the progress reaches the frames written
  }
  return p;
}

}  // namespace soak

#pragma once
// Something beside the frame files that takes each frame on the host (the
// Catalyst adaptor, Output/Catalyst/). The frame writer hands it the frames
// in order, after their files are listed, on a writer thread: a sink runs
// beside the simulation, and one that is slower than the simulation makes
// the writer wait in consume(), so the steps wait once the writer's queue
// is full (FrameWriter::waitedForDisk), as with a slow disk.
#include <memory>

#include "Output/FrameData.h"
#include "Output/FrameSource.h"

class vtkPolyData;

namespace soak {

// One frame as a sink gets it: the host arrays, and the water surface mesh
// the writer built for it (null where the scene has no <WaterSurface>).
struct SinkFrame {
  int frame = 0;
  FrameData data;
  std::shared_ptr<vtkPolyData> surface;  // holds a VTK reference
};

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  // Once, before the first frame: what does not change during the run.
  virtual void start(const OutputLayout& layout) = 0;
  // Whether the sink takes frame `frame` (frames it skips are not copied).
  virtual bool wants(int frame) const = 0;
  // Takes a frame; returns once it is queued (waits while the sink's own
  // queue is full). Throws the first error the sink met (a failed script).
  virtual void consume(std::shared_ptr<const SinkFrame> frame) = 0;
  // Returns once every frame taken is processed; throws the first error.
  virtual void finish() = 0;
  // Whether consume() ever had to wait for the sink.
  virtual bool waited() const = 0;
};

}  // namespace soak

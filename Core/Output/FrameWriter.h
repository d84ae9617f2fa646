#pragma once
#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <fstream>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "Base/Vec3.h"
#include "Output/OutputSettings.h"
#include "Output/PvdCollection.h"
#include "Output/VtkFiles.h"
#include "Registry/Module.h"
#include "Output/FrameSink.h"
#include "Output/FrameSource.h"

namespace soak {

class StateWriter;
class StateReader;

// Writes a run's folder:
//   OUT/water.pvd + OUT/water/water_NNNNNN.vtu   water particles
//   OUT/cloth_<name>.pvd + OUT/cloth_<name>/*.vtp  each cloth as a triangle mesh
//   OUT/water_surface.pvd + OUT/water_surface/*.vtp  with <WaterSurface>
//   OUT/water_vdb/water_NNNNNN.vdb               with Output.vdb (VdbFiles.h)
//   OUT/cloth_<name>_ply/*.ply                     with Output.ply (PlyFiles.h)
//   OUT/stats.csv                                 one row per frame
//   OUT/scene.xml                                 the scene as run
//
// Off the stepping thread: writeFrame() only queues copies of the frame's
// arrays to the host (FrameCopy.h; on the GPU the device copies them while
// the next steps run); background writer threads wait for the copies,
// compute the stats row, build and compress the files, and commit the
// frames in order (each .pvd and stats.csv gain a frame only once all its
// files are on disk). A step waits only when OutputSettings::queuedFrames
// frames are queued (the disk cannot keep up), which waitedForDisk() then
// reports. The source (the simulation) must outlive the writer (its stats
// read the source's setup), as it does when declared before it.
class FrameWriter {
 public:
  // Fresh: creates the folder (InputError if it cannot be written), writes
  // scene.xml and starts stats.csv. Resume: the folder of an earlier run;
  // nothing is touched until resume() applies a checked ResumeState.
  enum class Start { Fresh, Resume };
  FrameWriter(const std::string& directory, const std::string& sceneText, Start start = Start::Fresh,
              OutputSettings settings = {});
  // Writes the frames still queued (errors are swallowed here: call flush()
  // to see them) and stops the writer threads.
  ~FrameWriter();
  FrameWriter(const FrameWriter&) = delete;
  FrameWriter& operator=(const FrameWriter&) = delete;
  // Captures frame `frame` of `source` and queues it for writing.
  void writeFrame(FrameSource& source, int frame, double stepMs);
  // Returns once every queued frame is on disk and listed; rethrows the
  // first error a writer thread met (a full disk, say).
  void flush();
  const std::string& directory() const { return dir_; }
  // Frames on disk and listed in the .pvd files (queued ones not counted).
  int framesWritten() const { return frames_.load(); }
  // Whether some step had to wait for a frame to be written.
  bool waitedForDisk() const { return waitedForDisk_.load(); }
  // Seconds the stepping thread spent in writeFrame (queueing the copies,
  // and any wait for a full queue), over all frames.
  double captureSeconds() const { return captureSeconds_; }
  // Hands every frame, after its files are listed, to `sink` too (the
  // Catalyst adaptor). The sink must outlive the writer; attach it before
  // the first frame. A sink slower than the simulation makes the writer
  // wait, and then the steps (waitedForSink).
  void attachSink(FrameSink* sink) { sink_ = sink; }
  // Whether the writer had to wait for the sink.
  bool waitedForSink() const { return sink_ && sink_->waited(); }
  // Tests: each writer thread sleeps this long before writing a frame (a
  // slow disk on purpose).
  void setWriteDelayForTesting(double seconds) { testDelaySeconds_ = seconds; }

  // Checkpoints: the .pvd lists, the stats columns and how much of
  // stats.csv belongs to the saved frames.
  void saveState(StateWriter& out) const;
  // What a checkpoint says the folder held at its frame.
  struct ResumeState {
    int frames = 0;
    std::vector<PvdCollection::Entry> water;
    std::vector<std::pair<std::string, std::vector<PvdCollection::Entry>>> cloth;  // collection file, entries
    bool surface = false;
    std::vector<PvdCollection::Entry> surfaceEntries;
    std::vector<std::string> statsColumns;
    std::uint64_t statsBytes = 0;
  };
  // Reads the writer's part of a checkpoint and checks it against the
  // folder (stats.csv at least as long as then, every listed frame file
  // present) without changing anything: InputError if it does not fit.
  ResumeState readResumeState(StateReader& in) const;
  // Applies a checked state: rewrites the .pvd files and cuts stats.csv
  // back, so frames written after the checkpoint are dropped from both and
  // then written again. Called only once every other check has passed.
  void resume(const ResumeState& state);

 private:
  // What does not change during a run, taken from the first frame.
  struct ClothLayout {
    std::string collection;  // "cloth_<name>"
    int colourChannel = -1;  // index of Output.plyColour among the channels
    int phase = 0, firstVertex = 0, vertexCount = 0;
    std::vector<std::array<int, 3>> triangles;
  };
  // A frame as captured on the stepping thread: its copies queued.
  struct Capture {
    long long sequence = 0;
    int frame = 0;
    double stepMs = 0.0;
    FrameCopy copy;
  };
  // A frame on the host, with its stats.csv row (on a writer thread).
  struct Frame {
    int frame = 0;
    FrameData data;
    StatsRow stats;
  };
  // A frame's files written; what its commit adds to the .pvd files.
  struct Written {
    std::string water, surface;
    std::vector<std::string> cloth;
    std::shared_ptr<vtkPolyData> surfaceMesh;  // for the sink (holds a VTK reference)
  };
  void captureLayout(const OutputLayout& layout);
  Frame receive(Capture& c) const;
  Written writeFiles(const Frame& f) const;
  void commit(Frame& f, const Written& files);
  void writerLoop();
  void writeStatsRow(const StatsRow& row);

  std::string dir_;
  OutputSettings settings_;
  PvdCollection water_;
  std::vector<std::unique_ptr<PvdCollection>> cloth_;
  std::unique_ptr<PvdCollection> surface_;
  std::ofstream stats_;
  std::uint64_t statsBytes_ = 0;  // length of stats.csv after the last row
  std::vector<std::string> statsColumns_;
  std::atomic<int> frames_{0};

  bool haveLayout_ = false;
  std::vector<ClothLayout> clothLayout_;
  std::vector<std::string> channelNames_;
  bool surfaceOn_ = false;
  // The density splat that the surface mesh and the VDB level set share:
  // <WaterSurface>'s cell and iso, or the VDB's defaults without it.
  float splatCellSize_ = 0.f, splatIso_ = 0.5f;
  float restDensity_ = 1000.f;
  // OpenVDB's points: the water spacing and a full particle's mass.
  float waterSpacing_ = 0.02f, particleMass_ = 0.0082f;

  // Set by the first writeFrame: the source whose frames these are
  // (frameStats reads its setup) and the queue of its copies to the host.
  const FrameSource* source_ = nullptr;
  std::unique_ptr<DownloadQueue> downloads_;
  int writerThreads_ = 0;  // writerThreadsFor(settings_, the source's device)

  // The queue and its writer threads.
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::unique_ptr<Capture>> queue_;
  long long captured_ = 0;   // frames captured (sequence numbers 0, 1, ...)
  long long committed_ = 0;  // frames committed, in sequence order
  bool stopping_ = false;
  std::exception_ptr error_;
  std::vector<std::thread> threads_;
  std::atomic<bool> waitedForDisk_{false};
  double testDelaySeconds_ = 0.0;
  double captureSeconds_ = 0.0;
  FrameSink* sink_ = nullptr;
};

// Creates a directory and its parents; throws InputError if impossible.
void makeDirectories(const std::string& path);

}  // namespace soak

#pragma once
#include <cstdint>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "Base/Vec3.h"
#include "Output/PvdCollection.h"
#include "Registry/Module.h"

namespace soak {

class Simulation;
class StateWriter;
class StateReader;

// Writes a run's folder:
//   OUT/water.pvd + OUT/water/water_NNNNNN.vtu   water particles
//   OUT/cloth_<name>.pvd + OUT/cloth_<name>/*.vtp  each cloth as a triangle mesh
//   OUT/water_surface.pvd + OUT/water_surface/*.vtp  with <WaterSurface>
//   OUT/stats.csv                                 one row per frame
//   OUT/scene.xml                                 the scene as run
class FrameWriter {
 public:
  // Fresh: creates the folder (InputError if it cannot be written), writes
  // scene.xml and starts stats.csv. Resume: the folder of an earlier run;
  // nothing is touched until resume() applies a checked ResumeState.
  enum class Start { Fresh, Resume };
  FrameWriter(const std::string& directory, const std::string& sceneText, Start start = Start::Fresh);
  void writeFrame(Simulation& sim, int frame, double stepMs);
  const std::string& directory() const { return dir_; }
  int framesWritten() const { return frames_; }

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
  void writeStatsRow(const StatsRow& row);
  void writeCloth(Simulation& sim, int frame);
  void writeWaterSurface(Simulation& sim, int frame, const std::vector<Vec3>& points, const std::vector<float>& mass,
                         const std::vector<float>& radius);
  std::string dir_;
  PvdCollection water_;
  std::vector<std::unique_ptr<PvdCollection>> cloth_;
  std::unique_ptr<PvdCollection> surface_;
  std::ofstream stats_;
  std::uint64_t statsBytes_ = 0;  // length of stats.csv after the last row
  std::vector<std::string> statsColumns_;
  int frames_ = 0;
};

// Creates a directory and its parents; throws InputError if impossible.
void makeDirectories(const std::string& path);

}  // namespace soak
